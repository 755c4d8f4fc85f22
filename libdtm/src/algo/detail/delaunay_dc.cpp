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

#include "algo/detail/kd_order.hpp"
#include "algo/detail/median_split.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

/// Where a subtree's hull is entered by its parent's merge, in the parent's frame: the base of
/// the ghost triangle out of the last vertex (the left half's lower tangent search starts there)
/// and of the one into the first vertex (the right half's).
struct Hull {
    HalfEdge last_out;
    HalfEdge first_in;
};

/// A built subtree: its hull and the two triangle slots of its range it did not use.
struct Part {
    Hull hull;
    std::array<std::size_t, 2> spare;
};

/// The order of @p frame (0 or 1), chosen at run time.
inline bool before(int frame, const KernelPoint& a, const KernelPoint& b) noexcept {
    return frame == 0 ? Before<0>{}(a, b) : Before<1>{}(a, b);
}

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
        const HalfEdge on_hull = merge(left.hull, right.hull, left.spare);
        return {handles(on_hull, frame), right.spare};
    }

    // The mesh's own accessors, short names for the merge.
    [[nodiscard]] VertexId& org(HalfEdge h) const noexcept { return mesh_.org(h); }
    [[nodiscard]] VertexId dest(HalfEdge h) const noexcept { return mesh_.dest(h); }
    [[nodiscard]] HalfEdge& twin(HalfEdge h) const noexcept { return mesh_.twin(h); }
    void bond(HalfEdge a, HalfEdge b) const noexcept { mesh_.bond(a, b); }
    void set_triangle(std::size_t t, VertexId a, VertexId b, VertexId c) const noexcept {
        mesh_.set_triangle(t, a, b, c);
    }
    /// The next ghost along the hull (outer face on the left): (a, b) -> (b, c).
    [[nodiscard]] HalfEdge next_ghost(HalfEdge base) const noexcept {
        return next(twin(next(base)));
    }
    [[nodiscard]] HalfEdge prev_ghost(HalfEdge base) const noexcept {
        return prev(twin(prev(base)));
    }

    [[nodiscard]] int orient(VertexId a, VertexId b, VertexId c) const noexcept {
        return geom::orient2d(pts_[a].x, pts_[a].y, pts_[b].x, pts_[b].y, pts_[c].x, pts_[c].y);
    }
    [[nodiscard]] bool incircle(VertexId a, VertexId b, VertexId c, VertexId d) const noexcept {
        return geom::incircle(pts_[a].x, pts_[a].y, pts_[b].x, pts_[b].y, pts_[c].x, pts_[c].y,
                              pts_[d].x, pts_[d].y) > 0;
    }

    /// The hull handles in @p frame, found by walking the hull once from the ghost base
    /// @p start.
    [[nodiscard]] Hull handles(HalfEdge start, int frame) const noexcept {
        Hull hull{start, start};
        VertexId last = org(start);
        VertexId first = dest(start);
        for (HalfEdge g = next_ghost(start); g != start; g = next_ghost(g)) {
            const VertexId a = org(g);
            const VertexId b = dest(g);
            if (before(frame, pts_[last], pts_[a])) {
                last = a;
                hull.last_out = g;
            }
            if (before(frame, pts_[b], pts_[first])) {
                first = b;
                hull.first_in = g;
            }
        }
        return hull;
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
            set_triangle(g[i], v[(i + 1) % 3], v[i], ghost);
            bond(half_edge(t, i), half_edge(g[i], 0));
        }
        // Along the hull (outer face on the left) ghost i is followed by ghost i - 1.
        for (unsigned i = 0; i < 3; ++i) bond(half_edge(g[i], 1), half_edge(g[(i + 2) % 3], 2));
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
            set_triangle(t, v0, v0 + 1, ghost);
            set_triangle(t + 1, v0 + 1, v0, ghost);
            bond(half_edge(t, 0), half_edge(t + 1, 0));
            bond(half_edge(t, 1), half_edge(t + 1, 2));
            bond(half_edge(t, 2), half_edge(t + 1, 1));
            return {handles(half_edge(t, 0), frame), {t + 2, t + 3}};
        }
        const int o = orient(v0, v0 + 1, v0 + 2);
        if (o == 0) {  // a chain v0 - v1 - v2: four ghosts around it
            set_triangle(t, v0, v0 + 1, ghost);
            set_triangle(t + 1, v0 + 1, v0 + 2, ghost);
            set_triangle(t + 2, v0 + 2, v0 + 1, ghost);
            set_triangle(t + 3, v0 + 1, v0, ghost);
            bond(half_edge(t, 0), half_edge(t + 3, 0));
            bond(half_edge(t + 1, 0), half_edge(t + 2, 0));
            for (std::size_t i = 0; i < 4; ++i) {
                bond(half_edge(t + i, 1), half_edge(t + (i + 1) % 4, 2));
            }
        } else {
            if (o > 0) {
                set_triangle(t, v0, v0 + 1, v0 + 2);
            } else {
                set_triangle(t, v0, v0 + 2, v0 + 1);
            }
            close_with_ghosts(t, t + 1, t + 2, t + 3);
        }
        return {handles(half_edge(t + 1, 0), frame), {t + 4, t + 5}};
    }

    /// Deletes the edge of @p x, a half-edge a -> b of a real triangle (a, b, y) whose twin lies
    /// in a ghost (b, a, ghost) facing the gap, by flipping it with the ghost vertex: the real
    /// triangle becomes the ghost (a, ghost, y) and the ghost becomes (b, y, ghost). Half-edges
    /// x (now a -> ghost) and y -> a keep their places.
    void delete_by_ghost_flip(HalfEdge x) const noexcept {
        const HalfEdge x1 = next(x);   // b -> y
        const HalfEdge g0 = twin(x);   // b -> a
        const HalfEdge g1 = next(g0);  // a -> ghost
        const VertexId y = org(next(x1));
        const HalfEdge across = twin(x1);
        const HalfEdge outer = twin(g1);
        org(x1) = ghost;
        org(g1) = y;
        bond(x, outer);
        bond(g0, across);
        bond(x1, g1);
    }

    /// The Guibas-Stolfi merge on triangles. The left half lies before the right one in the
    /// frame of the cut. Returns the base of a ghost on the merged hull.
    ///
    /// The gap between the halves is covered by their ghosts; the merge adds two triangles: the
    /// ghost below the lower tangent (permanent) and the "upper" ghost (l, r, ghost) above the
    /// current base edge l - r. Each zip step turns the upper ghost into the real triangle
    /// (l, r, c) and the ghost of the half the candidate c came from into the next upper ghost.
    /// An edge of a half that the new edge would make non-Delaunay is deleted by flipping it
    /// with the ghost vertex: its triangle becomes a ghost facing the gap (Shewchuk's scheme).
    /// Every decision (tangent, candidates, deletions, choice) is the same as in the quad-edge
    /// formulation, so the triangulation is the same.
    HalfEdge merge(Hull left, Hull right, std::array<std::size_t, 2> slots) {
        // Lower common tangent: lg is a ghost base l -> x of the left half, rg one y -> r of
        // the right half.
        HalfEdge lg = left.last_out;
        HalfEdge rg = right.first_in;
        for (;;) {
            const VertexId l = org(lg);
            const VertexId r = dest(rg);
            if (orient(r, l, dest(lg)) > 0) {
                lg = next_ghost(lg);
            } else if (orient(l, org(rg), r) > 0) {
                rg = prev_ghost(rg);
            } else {
                break;
            }
        }
        VertexId l = org(lg);
        VertexId r = dest(rg);
        // The ghost below the tangent (r, l, ghost) and the upper ghost (l, r, ghost).
        const std::size_t below = slots[0];
        const std::size_t upper = slots[1];
        const HalfEdge ghost_above_l = twin(prev(lg));  // l -> ghost, in the ghost into l
        const HalfEdge ghost_above_r = twin(next(rg));  // ghost -> r, in the ghost out of r
        set_triangle(below, r, l, ghost);
        set_triangle(upper, l, r, ghost);
        bond(half_edge(below, 0), half_edge(upper, 0));
        bond(half_edge(below, 1), prev(lg));
        bond(half_edge(below, 2), next(rg));
        bond(half_edge(upper, 1), ghost_above_r);
        bond(half_edge(upper, 2), ghost_above_l);
        HalfEdge up = half_edge(upper, 0);  // l -> r in the upper ghost

        for (;;) {
            const HalfEdge up1 = next(up);   // r -> ghost
            const HalfEdge up2 = next(up1);  // ghost -> l
            // Left candidate: l -> c, the edge of the left half next to the gap.
            HalfEdge lcand = twin(prev(twin(up2)));
            VertexId lc = dest(lcand);
            bool lvalid = lc != r && orient(lc, l, r) > 0;
            if (lvalid) {
                bool deleted = false;
                for (;;) {
                    const HalfEdge a1 = next(lcand);  // c -> c2 in the triangle left of lcand
                    const VertexId c2 = org(next(a1));
                    if (c2 == ghost || c2 == r || !incircle(l, r, lc, c2)) break;
                    delete_by_ghost_flip(lcand);
                    lcand = twin(prev(lcand));  // l -> c2
                    lc = c2;
                    deleted = true;
                }
                if (deleted) lvalid = lc != r && orient(lc, l, r) > 0;
            }
            // Right candidate: r -> c, the base of the right half's ghost next to the gap.
            const HalfEdge rcand = next(twin(up1));
            VertexId rc = dest(rcand);
            bool rvalid = rc != l && orient(rc, l, r) > 0;
            if (rvalid) {
                bool deleted = false;
                for (;;) {
                    const HalfEdge b0 = twin(rcand);  // c -> r in the triangle right of rcand
                    const HalfEdge b1 = next(b0);     // r -> d2
                    const VertexId d2 = dest(b1);
                    if (d2 == ghost || d2 == l || !incircle(l, r, rc, d2)) break;
                    delete_by_ghost_flip(b0);  // rcand is now r -> d2
                    rc = d2;
                    deleted = true;
                }
                if (deleted) rvalid = rc != l && orient(rc, l, r) > 0;
            }
            if (!lvalid && !rvalid) break;
            if (!lvalid || (rvalid && incircle(lc, l, r, rc))) {
                // (l, r, rc); the right ghost (r, rc, ghost) becomes the upper ghost (l, rc,
                // ghost).
                const HalfEdge below_rc = twin(rcand);  // rc -> r
                const HalfEdge left_ghost = twin(up2);
                org(up2) = rc;
                org(rcand) = l;
                bond(up1, below_rc);
                bond(up2, rcand);
                bond(next(next(rcand)), left_ghost);
                up = rcand;
                r = rc;
            } else {
                // (l, r, lc); the left ghost (lc, l, ghost) becomes the upper ghost (lc, r, ghost).
                const HalfEdge g0 = twin(lcand);
                const HalfEdge g1 = next(g0);
                const HalfEdge right_ghost = twin(up1);
                org(up2) = lc;
                org(g1) = r;
                bond(up1, g0);
                bond(up2, lcand);
                bond(g1, right_ghost);
                up = g0;
                l = lc;
            }
        }
        return half_edge(below, 0);
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

}  // namespace dtm::detail
