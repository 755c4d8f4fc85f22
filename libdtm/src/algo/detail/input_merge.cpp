// SPDX-License-Identifier: MIT
//
// Input merging: every input point (survey points first, then the vertices of hard breaklines,
// soft breaklines, boundaries and holes, in that order) becomes one distinct TIN vertex.
// Exact duplicates in x, y are found with a hash table (exact_duplicates.cpp); with a snap
// distance D > 0, points closer than D to an earlier kept point are merged into it (a uniform grid
// of cell D, scanned in input order, so the result is deterministic). The kept position is the
// first point's; its z follows the DuplicateRule over the points that carry a height (soft
// breakline vertices carry none).
#include "algo/detail/input_merge.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <unordered_map>

#include "algo/detail/exact_duplicates.hpp"
#include "algo/detail/ghost_mesh.hpp"
#include "dtm/core/error.hpp"

namespace dtm::detail {
namespace {

std::string where(const Polyline& line, const char* what, std::size_t number) {
    return line.source.empty() ? std::string(what) + " " + std::to_string(number + 1) : line.source;
}

void add_polylines(const std::vector<Polyline>& lines,
                   std::uint8_t bits,
                   bool ring,
                   const char* what,
                   CombinedInput& c) {
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const Polyline& line = lines[k];
        std::size_t count = line.points.size();
        const bool repeats_first = count > 1 && line.points.front().x == line.points.back().x &&
                                   line.points.front().y == line.points.back().y;
        if (repeats_first) --count;
        const bool closed = line.closed || repeats_first;
        if (ring && (!closed || count < 3)) {
            throw InputError(where(line, what, k) + ": " + what +
                             " must be a closed ring of at least 3 vertices");
        }
        const auto first = static_cast<VertexIndex>(c.points.size());
        for (std::size_t i = 0; i < line.points.size(); ++i) {
            const Point3& p = line.points[i];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) ||
                (bits != constraint_soft && !std::isfinite(p.z))) {
                throw InputError(where(line, what, k) + ": vertex " + std::to_string(i + 1) +
                                 " has a coordinate that is not a finite number");
            }
            c.points.push_back(p);
            c.z_known.push_back(bits != constraint_soft);
        }
        for (std::size_t i = 0; i + 1 < count; ++i) {
            c.segments.push_back({first + static_cast<VertexIndex>(i),
                                  first + static_cast<VertexIndex>(i + 1), bits});
        }
        if (closed && count > 2) {
            c.segments.push_back({first + static_cast<VertexIndex>(count - 1), first, bits});
        }
    }
}

/// rep[i]: the combined index of the point i is merged into (rep[i] == i when kept).
using Representatives = BigArray<VertexIndex>;

Representatives find_representatives(const std::vector<Point3>& pts, double snap) {
    const std::size_t n = pts.size();
    if (snap <= 0.0) return first_occurrences(pts);
    Representatives rep(n);
    struct CellHash {
        std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& c) const noexcept {
            return std::hash<std::int64_t>()(c.first * 0x9e3779b97f4a7c15LL ^ c.second);
        }
    };
    std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::vector<VertexIndex>, CellHash>
        grid;
    const double snap2 = snap * snap;
    for (std::size_t i = 0; i < n; ++i) {
        const auto cx = static_cast<std::int64_t>(std::floor(pts[i].x / snap));
        const auto cy = static_cast<std::int64_t>(std::floor(pts[i].y / snap));
        auto found = static_cast<VertexIndex>(i);
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
            for (std::int64_t dy = -1; dy <= 1; ++dy) {
                const auto it = grid.find({cx + dx, cy + dy});
                if (it == grid.end()) continue;
                for (const VertexIndex r : it->second) {
                    const double ex = pts[r].x - pts[i].x;
                    const double ey = pts[r].y - pts[i].y;
                    if (ex * ex + ey * ey < snap2 && r < found) found = r;
                }
            }
        }
        rep[i] = found;
        if (found == i) grid[{cx, cy}].push_back(found);
    }
    return rep;
}

/// Fills out.vertices, z_known, input_to_vertex and merges when some points merge.
void merge_duplicates(const CombinedInput& c,
                      const Representatives& rep,
                      std::size_t kept_count,
                      DuplicateRule rule,
                      MergedInput& out) {
    std::vector<VertexIndex> vertex_of(c.points.size(), no_vertex);
    std::vector<std::uint32_t> z_count;
    out.vertices.reserve(kept_count);  // exact: no growth slack in the largest array
    out.z_known.reserve(kept_count);
    z_count.reserve(kept_count);
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        if (rep[i] == i) {
            vertex_of[i] = static_cast<VertexIndex>(out.vertices.size());
            out.vertices.push_back(c.points[i]);
            out.z_known.push_back(c.z_known[i]);
            z_count.push_back(c.z_known[i] ? 1 : 0);
            continue;
        }
        const VertexIndex v = vertex_of[rep[i]];
        vertex_of[i] = v;
        if (c.z_known[i]) {
            Point3& kept = out.vertices[v];
            ++z_count[v];
            kept.z = out.z_known[v] ? duplicate_rule_z(rule, kept.z, c.points[i].z, z_count[v])
                                    : c.points[i].z;
            out.z_known[v] = true;
        }
    }
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        if (rep[i] != i) {
            out.merges.push_back({rep[i], i, out.vertices[vertex_of[i]], c.points[i]});
        }
    }
    out.input_to_vertex = std::move(vertex_of);
}

}  // namespace

void add_lines(const TerrainInput& input, CombinedInput& c) {
    add_polylines(input.breaklines, constraint_breakline, false, "breakline", c);
    add_polylines(input.boundaries, constraint_boundary, true, "boundary", c);
    add_polylines(input.holes, constraint_hole, true, "hole", c);
    add_polylines(input.soft_breaklines, constraint_soft, false, "soft breakline", c);
}

MergedInput merge_input(const TerrainInput& input, const TriangulateOptions& options) {
    TerrainInput copy = input;
    return merge_input(std::move(copy), options);
}

MergedInput merge_input(TerrainInput&& input, const TriangulateOptions& options) {
    CombinedInput c;
    // The first point with a coordinate that is not finite, found by all threads.
    const std::size_t bad = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, input.points.size(), 1 << 16), input.points.size(),
        [&](const auto& r, std::size_t found) {
            for (std::size_t i = r.begin(); i < r.end() && i < found; ++i) {
                const Point3& p = input.points[i];
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return i;
            }
            return found;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
    if (bad < input.points.size()) {
        throw InputError("point " + std::to_string(bad + 1) +
                         " has a coordinate that is not a finite number");
    }
    c.points = std::move(input.points);
    input.points = {};
    // Room for every polyline vertex at once: one copy of the points at most, and no growth
    // slack that the no-merge path below would have to copy away again.
    std::size_t line_vertices = 0;
    for (const auto* lines :
         {&input.breaklines, &input.boundaries, &input.holes, &input.soft_breaklines}) {
        for (const Polyline& line : *lines) line_vertices += line.points.size();
    }
    c.points.reserve(c.points.size() + line_vertices);
    c.z_known.reserve(c.points.size() + line_vertices);
    c.z_known.assign(c.points.size(), true);
    add_lines(input, c);

    MergedInput out;
    out.points_in = c.points.size();
    if (c.points.size() >= no_vertex) {
        throw InputError("more than " + std::to_string(no_vertex - 1) + " input points");
    }
    const Representatives rep = find_representatives(c.points, options.snap_distance);
    const std::size_t kept_count = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, rep.size(), 1 << 16), std::size_t{0},
        [&](const auto& r, std::size_t kept) {
            for (std::size_t i = r.begin(); i < r.end(); ++i) kept += rep[i] == i ? 1 : 0;
            return kept;
        },
        std::plus<>());
    if (kept_count == c.points.size()) {
        // Nothing to merge (the usual case): the points become the vertices as they are, unless
        // the reader's growth left much unused capacity in the largest array of the run.
        if (c.points.capacity() > c.points.size() + c.points.size() / 16) {
            out.vertices.reserve(c.points.size());
            out.vertices.assign(c.points.begin(), c.points.end());
            c.points = {};
        } else {
            out.vertices = std::move(c.points);
        }
        out.z_known = std::move(c.z_known);  // input_to_vertex stays empty: the identity
    } else {
        merge_duplicates(c, rep, kept_count, options.duplicates, out);
    }
    for (const InputSegment& s : c.segments) {
        const VertexIndex a = out.vertex_of_input(s.a);
        const VertexIndex b = out.vertex_of_input(s.b);
        if (a != b) out.segments.push_back({a, b, s.bits});
    }
    return out;
}

}  // namespace dtm::detail
