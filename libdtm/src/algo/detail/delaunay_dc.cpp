// SPDX-License-Identifier: MIT
//
// Delaunay triangulation by divide and conquer with alternating cuts.
//
// The point set is split at its median, alternately by x and by y (Dwyer's improvement of the
// Guibas-Stolfi algorithm, as in Shewchuk's Triangle), down to pieces of two or three points.
// Two neighbouring halves are stitched by the Guibas-Stolfi merge: start from the lower common
// tangent of the two hulls and zip upwards, each step adding the triangle chosen by the
// in-circle test and deleting the edges of either half that it makes non-Delaunay. The mesh is
// triangle-based with ghost triangles on the hull (ghost_mesh.hpp, after Shewchuk's Triangle): a
// deletion is a flip with the ghost vertex, a zip step turns a ghost into a real triangle, and
// the finished mesh is already the TIN's triangle array.
// A cut by y is merged in a frame rotated by 90 degrees: the merge reads geometry only through
// orient2d and incircle, which are invariant under that rotation, so only the order used to pick
// the extreme hull vertices changes ((x, y) for x cuts, (y, -x) for y cuts).
//
// The recursion tree depends only on the input (a median split of a canonically sorted array),
// so the triangulation is the same whether a subtree runs sequentially or as a parallel task:
// the top levels of the tree are the "tiles" and their merges are the exact seam stitches.
// Every subtree of m points uses exactly 2 m - 2 of the triangle slots [2 lo, 2 hi) of its range
// (a merge adds two triangles, a flip none), and a merge takes the two slots its left half left
// over, so every triangle gets the same slot for every tile and thread count.
//
// References:
//   L. Guibas, J. Stolfi, "Primitives for the manipulation of general subdivisions and the
//     computation of Voronoi diagrams", ACM Transactions on Graphics 4(2), 1985.
//   R. A. Dwyer, "A faster divide-and-conquer algorithm for constructing Delaunay
//     triangulations", Algorithmica 2, 1987.
//   J. R. Shewchuk, "Triangle: engineering a 2D quality mesh generator and Delaunay
//     triangulator", 1996 (alternating cuts, robust predicates).
#include "algo/detail/delaunay_dc.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <string>

#include "algo/detail/ghost_merge.hpp"
#include "algo/detail/kd_order.hpp"
#include "algo/detail/median_split.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

using Hull = GhostHull<HalfEdge>;

/// The kernel's mesh as ghost_merge.hpp reads it: the triangles and the points in kernel order.
struct KernelAccess {
    using Vertex = VertexId;
    using Edge = HalfEdge;
    static constexpr Vertex ghost_vertex = ghost;
    static constexpr Edge half_edge(std::size_t t, unsigned i) noexcept {
        return detail::half_edge(t, i);
    }

    GhostMesh& mesh;
    const KernelPoint* pts;

    [[nodiscard]] VertexId& org(HalfEdge h) const noexcept { return mesh.org(h); }
    [[nodiscard]] VertexId dest(HalfEdge h) const noexcept { return mesh.dest(h); }
    [[nodiscard]] HalfEdge& twin(HalfEdge h) const noexcept { return mesh.twin(h); }
    void bond(HalfEdge a, HalfEdge b) const noexcept { mesh.bond(a, b); }
    void set_triangle(std::size_t t, VertexId a, VertexId b, VertexId c) const noexcept {
        mesh.set_triangle(t, a, b, c);
    }
    [[nodiscard]] int orient(VertexId a, VertexId b, VertexId c) const noexcept {
        return geom::orient2d(pts[a].x, pts[a].y, pts[b].x, pts[b].y, pts[c].x, pts[c].y);
    }
    [[nodiscard]] bool incircle(VertexId a, VertexId b, VertexId c, VertexId d) const noexcept {
        return geom::incircle(pts[a].x, pts[a].y, pts[b].x, pts[b].y, pts[c].x, pts[c].y, pts[d].x,
                              pts[d].y) > 0;
    }
    [[nodiscard]] bool before(int frame, VertexId a, VertexId b) const noexcept {
        return frame == 0 ? Before<0>{}(pts[a], pts[b]) : Before<1>{}(pts[a], pts[b]);
    }
};

/// A built subtree: its hull and the two triangle slots of its range it did not use.
struct Part {
    Hull hull;
    std::array<std::size_t, 2> spare;
};

class Builder {
public:
    Builder(BigArray<KernelPoint>& points,
            GhostMesh& mesh,
            const DelaunayDcOptions& options,
            const Progress& progress)
        : pts_(points.data()),
          mesh_(mesh),
          options_(options),
          progress_(progress),
          total_(points.size()),
          progress_unit_(options.parallel_cutoff > 0 ? options.parallel_cutoff : 65536) {}

    /// Orders points [lo, hi) as the recursion will cut them (kd_order.hpp): median selection
    /// for the large subtrees, order_subtree (in rank space, in the caches) for the rest. Done as
    /// a pass of its own, before any merge, so the partitioning streams through the points
    /// without the mesh in the caches.
    void split(std::size_t lo, std::size_t hi, int cut, std::size_t parent_n) {
        const std::size_t n = hi - lo;
        if (n <= SubtreeScratch::capacity) {
            order_subtree(pts_ + lo, n, cut, subtree_scratch_.local());
            // Everything below counts here, whether or not it is one progress unit.
            if (n > progress_unit_ || parent_n > progress_unit_) report(n);
            return;
        }
        const std::size_t mid = lo + n / 2;
        if (cut == 0) {
            select_kth(pts_ + lo, n, n / 2, Before<0>{}, scratch_.local());
        } else {
            select_kth(pts_ + lo, n, n / 2, Before<1>{}, scratch_.local());
        }
        if (options_.parallel_cutoff > 0 && n > options_.parallel_cutoff) {
            tbb::parallel_invoke([&] { split(lo, mid, 1 - cut, n); },
                                 [&] { split(mid, hi, 1 - cut, n); });
        } else {
            split(lo, mid, 1 - cut, n);
            split(mid, hi, 1 - cut, n);
        }
        if (n <= progress_unit_ && parent_n > progress_unit_) report(n);
    }

    /// Triangulates points [lo, hi) in the triangle slots [2 lo, 2 hi); the hull handles are in
    /// the order of @p frame.
    Part build(std::size_t lo, std::size_t hi, int cut, int frame, std::size_t parent_n) {
        const std::size_t n = hi - lo;
        const Part part = n <= 3 ? base_case(lo, n, frame) : build_inner(lo, hi, cut, frame);
        if (n <= progress_unit_ && parent_n > progress_unit_) report(n);
        return part;
    }

private:
    /// Progress over both passes (split, then build), about a fifth of the work in the first.
    void report(std::size_t n) {
        const std::size_t done = done_.fetch_add(n) + n;
        const double total = static_cast<double>(total_);
        const double fraction = done <= total_
                                    ? 0.2 * static_cast<double>(done) / total
                                    : 0.2 + 0.8 * static_cast<double>(done - total_) / total;
        progress_.report(fraction, "triangulating");
    }

    Part build_inner(std::size_t lo, std::size_t hi, int cut, int frame) {
        const std::size_t n = hi - lo;
        if (n <= strip_size) cut = 0;  // sorted by x: cut by index, vertically
        const std::size_t mid = lo + n / 2;
        Part left{};
        Part right{};
        if (options_.parallel_cutoff > 0 && n > options_.parallel_cutoff) {
            bool left_done = false;
            bool right_done = false;
            tbb::parallel_invoke(
                [&] {
                    left = build(lo, mid, 1 - cut, cut, n);
                    left_done = true;
                },
                [&] {
                    right = build(mid, hi, 1 - cut, cut, n);
                    right_done = true;
                });
            // When a task elsewhere in the tree threw (cancellation), TBB cancels the shared
            // context and a nested parallel_invoke may return without running its tasks and
            // without an exception: never merge halves that were not built.
            if (!left_done || !right_done) throw Cancelled();
        } else {
            left = build(lo, mid, 1 - cut, cut, n);
            right = build(mid, hi, 1 - cut, cut, n);
        }
        // The merge takes the left half's spare slots; the right half's are passed up, whether
        // or not the halves ran in parallel.
        KernelAccess mesh = access();
        const HalfEdge on_hull = ghost_merge(mesh, left.hull, right.hull, left.spare);
        return {hull_handles(mesh, on_hull, frame), right.spare};
    }

    [[nodiscard]] KernelAccess access() const noexcept { return {mesh_, pts_}; }

    [[nodiscard]] int orient(VertexId a, VertexId b, VertexId c) const noexcept {
        return access().orient(a, b, c);
    }

    /// Ghost triangles on the three edges of the real triangle @p t = (a, b, c), in the slots
    /// @p g0, @p g1, @p g2 (on the edges a-b, b-c, c-a), linked along the hull.
    void close_with_ghosts(std::size_t t,
                           std::size_t g0,
                           std::size_t g1,
                           std::size_t g2) const noexcept {
        const std::array<std::size_t, 3> g{g0, g1, g2};
        const auto& v = mesh_.tris[t].v;
        for (unsigned i = 0; i < 3; ++i) {
            mesh_.set_triangle(g[i], v[(i + 1) % 3], v[i], ghost);
            mesh_.bond(half_edge(t, i), half_edge(g[i], 0));
        }
        // Along the hull (outer face on the left) ghost i is followed by ghost i - 1.
        for (unsigned i = 0; i < 3; ++i)
            mesh_.bond(half_edge(g[i], 1), half_edge(g[(i + 2) % 3], 2));
    }

    /// Two or three points, sorted by x by split(); put in the order of the frame. Uses the
    /// first two (or four) slots of the range [2 lo, 2 lo + 2 n).
    Part base_case(std::size_t lo, std::size_t n, int frame) {
        if (frame == 1) {
            const Before<1> less;
            KernelPoint* p = pts_ + lo;
            if (less(p[1], p[0])) std::swap(p[0], p[1]);
            if (n == 3) {
                if (less(p[2], p[1])) std::swap(p[1], p[2]);
                if (less(p[1], p[0])) std::swap(p[0], p[1]);
            }
        }
        const auto v0 = static_cast<VertexId>(lo);
        const std::size_t t = 2 * lo;
        if (n == 2) {
            mesh_.set_triangle(t, v0, v0 + 1, ghost);
            mesh_.set_triangle(t + 1, v0 + 1, v0, ghost);
            mesh_.bond(half_edge(t, 0), half_edge(t + 1, 0));
            mesh_.bond(half_edge(t, 1), half_edge(t + 1, 2));
            mesh_.bond(half_edge(t, 2), half_edge(t + 1, 1));
            KernelAccess mesh = access();
            return {hull_handles(mesh, half_edge(t, 0), frame), {t + 2, t + 3}};
        }
        const int o = orient(v0, v0 + 1, v0 + 2);
        if (o == 0) {  // a chain v0 - v1 - v2: four ghosts around it
            mesh_.set_triangle(t, v0, v0 + 1, ghost);
            mesh_.set_triangle(t + 1, v0 + 1, v0 + 2, ghost);
            mesh_.set_triangle(t + 2, v0 + 2, v0 + 1, ghost);
            mesh_.set_triangle(t + 3, v0 + 1, v0, ghost);
            mesh_.bond(half_edge(t, 0), half_edge(t + 3, 0));
            mesh_.bond(half_edge(t + 1, 0), half_edge(t + 2, 0));
            for (std::size_t i = 0; i < 4; ++i) {
                mesh_.bond(half_edge(t + i, 1), half_edge(t + (i + 1) % 4, 2));
            }
        } else {
            if (o > 0) {
                mesh_.set_triangle(t, v0, v0 + 1, v0 + 2);
            } else {
                mesh_.set_triangle(t, v0, v0 + 2, v0 + 1);
            }
            close_with_ghosts(t, t + 1, t + 2, t + 3);
        }
        KernelAccess mesh = access();
        return {hull_handles(mesh, half_edge(t + 1, 0), frame), {t + 4, t + 5}};
    }

    KernelPoint* pts_;
    GhostMesh& mesh_;
    const DelaunayDcOptions& options_;
    const Progress& progress_;
    std::size_t total_;
    std::size_t progress_unit_;
    std::atomic<std::size_t> done_{0};
    tbb::enumerable_thread_specific<SelectScratch<KernelPoint>> scratch_;
    tbb::enumerable_thread_specific<SubtreeScratch> subtree_scratch_;
};

}  // namespace

void delaunay_divide_and_conquer(BigArray<KernelPoint>& points,
                                 GhostMesh& mesh,
                                 const DelaunayDcOptions& options,
                                 const Progress& progress) {
    const std::size_t n = points.size();
    if (n > max_kernel_points) {
        throw InputError("too many points for one triangulation: " + std::to_string(n) +
                         " (at most " + std::to_string(max_kernel_points) + ")");
    }
    mesh.tris.clear();
    if (n >= 2) {
        // Every slot starts as "unused" (all corners ghost); the root leaves two of them.
        reserve_huge(mesh.tris, 2 * n);
        prefault_in_parallel(mesh.tris);
        mesh.tris.resize(2 * n);
        Builder builder(points, mesh, options, progress);
        builder.split(0, n, 0, n + 1);
        builder.build(0, n, 0, 0, n + 1);
    }
    mesh.points = std::move(points);
    points = {};
}

void order_kernel_subtree(BigArray<KernelPoint>& points, std::size_t lo, std::size_t hi, int cut) {
    GhostMesh unused;
    const DelaunayDcOptions options;
    const Progress progress;
    Builder builder(points, unused, options, progress);
    if (hi - lo >= 2) builder.split(lo, hi, cut, hi - lo + 1);
}

KernelSubtree build_kernel_subtree(BigArray<KernelPoint>& points,
                                   GhostMesh& mesh,
                                   std::size_t lo,
                                   std::size_t hi,
                                   int cut,
                                   int frame) {
    const DelaunayDcOptions options;
    const Progress progress;
    Builder builder(points, mesh, options, progress);
    const Part part = builder.build(lo, hi, cut, frame, hi - lo + 1);
    return {part.hull, part.spare};
}

}  // namespace dtm::detail
