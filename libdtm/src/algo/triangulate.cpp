// SPDX-License-Identifier: MIT
//
// Constrained Delaunay triangulation of terrain input: the pipeline.
//
//   1. merge_input: distinct vertices (duplicates and snapped points merged, every merge kept)
//      and the constraint segments of breaklines, boundaries, holes and soft breaklines;
//   2. the Delaunay kernel: divide and conquer with alternating cuts on triangles with ghosts;
//      its top levels run as parallel tiles and the merges that join them are the exact seam
//      stitches (detail/delaunay_dc.cpp, detail/ghost_mesh.hpp);
//   2a. (before 2) the segments split at their crossings, T-junctions and overlaps, the crossing
//      vertices added with interpolated heights (detail/segment_split.cpp);
//   3. constraints inserted into the same triangles by cavity retriangulation, in parallel by
//      deterministic reservations (detail/constraint_batch.cpp, detail/mesh_edit.cpp,
//      detail/mesh_edit_segment.cpp);
//   4. the TIN: the triangle array itself, in place, in canonical order
//   (detail/tin_build_triangles.cpp);
//      the domain: outside the boundary, holes and long border triangles removed
//      (detail/tin_build_domain.cpp, detail/tin_build_finish.cpp).
// First, 2-D line vertices get heights (resolve_line_heights: from survey points at the same
// position, rings from the surface of the points and hard breaklines). Soft breakline vertices
// take theirs from the surface built without them (a first pass of steps 2-3 without soft
// lines, sampled by SurfaceSampler), then everything is built again with them.
#include "dtm/algo/triangulate.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <string>

#include "algo/detail/big_array.hpp"
#include "algo/detail/constraint_batch.hpp"
#include "algo/detail/delaunay_dc.hpp"
#include "algo/detail/input_merge.hpp"
#include "algo/detail/mesh_edit.hpp"
#include "algo/detail/segment_split.hpp"
#include "algo/detail/tin_build.hpp"
#include "dtm/algo/surface_sampler.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

using detail::MergedInput;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The kernel's triangles over a subset of the merged vertices, with the constraints inserted.
struct Kernel {
    detail::GhostMesh triangles;
    std::vector<double> z;  ///< per kernel vertex (with keep_heights or segments)
    std::vector<detail::Crossing> crossings;
    std::size_t kernel_count = 0;  ///< vertices before those added at crossings
    double seconds_triangulate = 0.0;
    double seconds_constrain = 0.0;
};

std::size_t parallel_cutoff(std::size_t n, const TriangulateOptions& options) {
    const unsigned threads = options.threads > 0
                                 ? options.threads
                                 : static_cast<unsigned>(tbb::this_task_arena::max_concurrency());
    if (options.tiles == 1 || (options.tiles == 0 && (threads <= 1 || n < 200'000))) return 0;
    const std::size_t tiles =
        options.tiles > 0 ? options.tiles : 8 * static_cast<std::size_t>(threads);
    return std::max<std::size_t>(n / tiles, 4);
}

/// The kernel over the merged vertices (with @p with_soft, all of them; else those with known
/// heights) with the segments among them inserted (@p segments_free: they touch at shared
/// endpoints only). With @p keep_heights, or when there are segments, the heights per kernel
/// vertex are kept in Kernel::z.
Kernel build_kernel(const MergedInput& in,
                    bool with_soft,
                    bool keep_heights,
                    bool segments_free,
                    const TriangulateOptions& options,
                    const Progress& progress) {
    Kernel k;
    auto start = std::chrono::steady_clock::now();
    detail::BigArray<detail::KernelPoint> points;
    if (with_soft) {  // every vertex: filled in parallel
        points.resize(in.vertices.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 1 << 14),
                          [&](const auto& r) {
                              for (std::size_t i = r.begin(); i < r.end(); ++i) {
                                  points[i] = {{in.vertices[i].x, in.vertices[i].y},
                                               static_cast<std::uint32_t>(i)};
                              }
                          });
    } else {
        points.reserve(in.vertices.size());
        for (std::size_t i = 0; i < in.vertices.size(); ++i) {
            if (!in.z_known[i]) continue;
            points.push_back({{in.vertices[i].x, in.vertices[i].y}, static_cast<std::uint32_t>(i)});
        }
    }
    std::vector<detail::InputSegment> segments;
    for (const detail::InputSegment& seg : in.segments) {
        if (with_soft || seg.bits != detail::constraint_soft) segments.push_back(seg);
    }
    keep_heights = keep_heights || !segments.empty();
    detail::DelaunayDcOptions dc;
    dc.parallel_cutoff = parallel_cutoff(points.size(), options);
    const std::size_t kernel_count = points.size();
    detail::delaunay_divide_and_conquer(points, k.triangles, dc, progress.sub(0.0, 0.7));
    k.kernel_count = kernel_count;
    k.seconds_triangulate = seconds_since(start);
    if (!keep_heights) return k;

    start = std::chrono::steady_clock::now();
    const detail::BigArray<detail::KernelPoint>& kp = k.triangles.points;
    // Every array of this step is first touched in parallel (fresh pages are costly to fault in).
    const std::unique_ptr<detail::VertexId[]> kernel_of(new detail::VertexId[in.vertices.size()]);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, in.vertices.size(), 1 << 16), [&](const auto& r) {
            std::fill(kernel_of.get() + r.begin(), kernel_of.get() + r.end(), no_vertex);
        });
    detail::assign_fresh(k.z, kernel_count, 0.0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kernel_count, 1 << 14),
                      [&](const auto& r) {
                          for (std::size_t v = r.begin(); v < r.end(); ++v) {
                              const VertexIndex id = kp[v].id;  // distinct: no write conflicts
                              kernel_of[id] = static_cast<detail::VertexId>(v);
                              k.z[v] = in.vertices[id].z;
                          }
                      });
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, segments.size(), 1 << 14),
                      [&](const auto& r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i) {
                              segments[i].a = kernel_of[segments[i].a];
                              segments[i].b = kernel_of[segments[i].b];
                          }
                      });
    if (!segments.empty()) {
        detail::MeshEditor editor(k.triangles, k.z, options.z_tolerance);
        detail::insert_segments(editor, k.triangles, segments, segments_free,
                                progress.sub(0.7, 1.0));
        k.crossings = editor.crossings();
    }
    // Vertices added at crossings are numbered after the merged ones, in order.
    const auto first_added = static_cast<VertexIndex>(in.vertices.size());
    for (std::size_t v = kernel_count; v < kp.size(); ++v) {
        k.triangles.points[v].id = first_added + static_cast<VertexIndex>(v - kernel_count);
    }
    k.seconds_constrain = seconds_since(start);
    return k;
}

/// Heights of soft-breakline-only vertices, interpolated on the surface built without them (the
/// kernel of the other vertices with their constraints, sampled as a Tin by SurfaceSampler).
void interpolate_soft_heights(MergedInput& in,
                              bool segments_free,
                              const TriangulateOptions& options,
                              const Progress& progress) {
    Kernel k = build_kernel(in, false, true, segments_free, options, progress);
    std::vector<Point3> vertices = in.vertices;  // the soft-only ones are on no triangle
    const detail::BigArray<detail::KernelPoint>& kp = k.triangles.points;
    for (std::size_t v = k.kernel_count; v < kp.size(); ++v) {  // added at crossings, in order
        vertices.push_back({kp[v].x, kp[v].y, k.z[v]});
    }
    const detail::TinDraft surface = detail::ghost_mesh_to_tin(k.triangles, std::move(vertices));
    const SurfaceSampler sampler(surface.tin);
    SurfaceSampler::Cursor cursor;
    for (std::size_t i = 0; i < in.vertices.size(); ++i) {
        if (in.z_known[i]) continue;
        in.vertices[i].z = sampler.height_or_nearest({in.vertices[i].x, in.vertices[i].y}, cursor);
    }
    for (std::size_t i = 0; i < in.vertices.size(); ++i) in.z_known[i] = true;
}

void check_not_degenerate(const MergedInput& in) {
    const std::size_t n = in.vertices.size();
    if (n < 3) {
        throw InputError("triangulation needs at least 3 distinct points; the input has " +
                         std::to_string(n));
    }
    for (std::size_t i = 2; i < n; ++i) {
        if (geom::orient2d(in.vertices[0], in.vertices[1], in.vertices[i]) != 0) return;
    }
    throw InputError("all " + std::to_string(n) +
                     " distinct points are collinear: there is no surface to triangulate");
}

TriangulateResult run(TerrainInput&& input,
                      const TriangulateOptions& options,
                      const Progress& outer) {
    TriangulateResult result;
    result.line_heights =
        resolve_line_heights(input, {options.threads, options.tiles}, outer.sub(0.0, 0.1));
    const Progress progress = result.line_heights.from_surface > 0 ? outer.sub(0.1, 1.0) : outer;
    auto start = std::chrono::steady_clock::now();
    MergedInput merged = detail::merge_input(std::move(input), options);
    const bool has_boundary = !input.boundaries.empty();
    const std::vector<Point2> hole_seeds = std::move(input.hole_seeds);
    input = TerrainInput{};
    check_not_degenerate(merged);
    const double seconds_merge = seconds_since(start);
    start = std::chrono::steady_clock::now();
    const std::size_t distinct_count = merged.vertices.size();
    const detail::SegmentSplit split = detail::split_segments(merged, options.z_tolerance);
    const double seconds_split = seconds_since(start);
    bool has_soft = false;
    for (const bool known : merged.z_known) has_soft = has_soft || !known;
    if (has_soft) interpolate_soft_heights(merged, split.all_free, options, progress.sub(0.0, 0.3));
    Kernel k = build_kernel(merged, true, false, split.all_free, options,
                            progress.sub(has_soft ? 0.3 : 0.0, 0.95));

    start = std::chrono::steady_clock::now();
    std::vector<Point3> vertices = std::move(merged.vertices);
    const std::size_t merged_count = vertices.size();
    const detail::BigArray<detail::KernelPoint>& kp = k.triangles.points;
    if (kp.size() > k.kernel_count) {  // vertices added at crossings, in order
        vertices.reserve(merged_count + (kp.size() - k.kernel_count));
        for (std::size_t v = k.kernel_count; v < kp.size(); ++v) {
            vertices.push_back({kp[v].x, kp[v].y, k.z[v]});
        }
    }
    k.z = {};  // heights live in `vertices` now
    detail::TinDraft draft = detail::ghost_mesh_to_tin(k.triangles, std::move(vertices));
    result.stats.removed_triangles =
        detail::apply_domain(draft, has_boundary, hole_seeds, options.max_edge);
    detail::finish_tin(draft);
    result.tin = std::move(draft.tin);
    if (result.tin.triangles.empty()) {
        throw InputError("no triangle is left inside the boundary and outside the holes");
    }
    progress.report(1.0, "triangulated");

    result.stats.points_in = merged.points_in;
    result.stats.duplicates_merged = merged.merges.size();
    result.stats.intersections = 0;
    const std::vector<detail::Crossing>* const lists[] = {&split.crossings, &k.crossings};
    for (const auto* crossings : lists) {  // the pre-pass's, then any the insertion added
        for (const detail::Crossing& c : *crossings) {
            ++result.stats.intersections;
            if (c.conflict) {
                ++result.stats.conflicts;
                result.conflicts.push_back({c.at, c.z_first, c.z_second});
            }
        }
    }
    result.stats.seconds_triangulate = seconds_merge + k.seconds_triangulate;
    result.stats.seconds_constrain = seconds_split + k.seconds_constrain + seconds_since(start);
    result.merges = std::move(merged.merges);
    result.input_to_vertex = std::move(merged.input_to_vertex);
    if (result.input_to_vertex.empty()) {  // nothing merged: the identity, made now that the
        result.input_to_vertex.resize(distinct_count);  // kernel's memory is released
        std::iota(result.input_to_vertex.begin(), result.input_to_vertex.end(), VertexIndex{0});
    }
    if (options.optimize != Criterion::delaunay) {
        result.stats.optimize =
            optimize_tin(result.tin, {.criterion = options.optimize, .threads = options.threads},
                         progress.sub(1.0, 1.0));
    }
    return result;
}

}  // namespace

TriangulateResult triangulate(TerrainInput&& input,
                              const TriangulateOptions& options,
                              const Progress& progress) {
    if (options.threads == 0) return run(std::move(input), options, progress);
    tbb::task_arena arena(static_cast<int>(options.threads));
    return arena.execute([&] { return run(std::move(input), options, progress); });
}

TriangulateResult triangulate(const TerrainInput& input,
                              const TriangulateOptions& options,
                              const Progress& progress) {
    TerrainInput copy = input;
    return triangulate(std::move(copy), options, progress);
}

}  // namespace dtm
