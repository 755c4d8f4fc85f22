// SPDX-License-Identifier: MIT
//
// Delaunay triangulation by divide and conquer with alternating cuts.
//
// The point set is split at its median, alternately by x and by y (Dwyer's improvement of the
// Guibas-Stolfi algorithm, as in Shewchuk's Triangle), down to pieces of two or three points.
// Two neighbouring halves are stitched by the Guibas-Stolfi merge: start from the lower common
// tangent of the two hulls and zip upwards, each step adding the cross edge chosen by the
// in-circle test and deleting the edges of either half that the new edge makes non-Delaunay.
// A cut by y is merged in a frame rotated by 90 degrees: the merge reads geometry only through
// orient2d and incircle, which are invariant under that rotation, so only the order used to pick
// the extreme hull vertices changes ((x, y) for x cuts, (y, -x) for y cuts).
//
// The recursion tree depends only on the input (a median split of a canonically sorted array),
// so the triangulation is the same whether a subtree runs sequentially or as a parallel task:
// the top levels of the tree are the "tiles" and their merges are the exact seam stitches.
// Every subtree allocates edges from its own slot range (3 slots per point always suffice: a
// planar straight-line graph on m >= 3 points has at most 3m - 6 edges), whether it runs as a
// parallel task or not, so every edge gets the same slot for every tile and thread count.
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
#include <atomic>

#include "algo/detail/median_split.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

/// ldo: counter-clockwise hull edge out of the first (leftmost) vertex of the frame order;
/// rdo: clockwise hull edge out of the last (rightmost) one.
struct Hull {
    EdgeId left;
    EdgeId right;
};

/// Subtrees of at most this many points are not cut alternately but sorted by x once and cut
/// vertically by index (Guibas and Stolfi's original scheme): at this size the shape of the pieces
/// hardly changes the merges, and selecting medians for every tiny subtree cost more than all the
/// larger cuts together.
constexpr std::size_t strip_size = 16;

/// Strict order of the frame: lexicographic (x, y) for axis 0, (y, -x) for axis 1. Written
/// without branches, for the median selection.
template <int Axis>
struct Before {
    bool operator()(const KernelPoint& a, const KernelPoint& b) const noexcept
    {
        if constexpr (Axis == 0) return (a.x < b.x) | ((a.x == b.x) & (a.y < b.y));
        return (a.y < b.y) | ((a.y == b.y) & (a.x > b.x));
    }
};

/// The order of @p frame (0 or 1), chosen at run time.
inline bool before(int frame, const KernelPoint& a, const KernelPoint& b) noexcept
{
    return frame == 0 ? Before<0>{}(a, b) : Before<1>{}(a, b);
}

class Builder {
public:
    Builder(BigArray<KernelPoint>& points, EdgeMesh& mesh, const DelaunayDcOptions& options,
            const Progress& progress)
        : pts_(points.data()), mesh_(mesh), options_(options), progress_(progress),
          total_(points.size()),
          progress_unit_(options.parallel_cutoff > 0 ? options.parallel_cutoff : 65536)
    {
    }

    /// Orders points [lo, hi) as the recursion will cut them: the median split by the cut's order,
    /// recursively, down to pieces of at most strip_size points, which are sorted by x. Done as a
    /// pass of its own, before any merge, so the partitioning streams through the points without
    /// the mesh in the caches.
    void split(std::size_t lo, std::size_t hi, int cut, std::size_t parent_n)
    {
        const std::size_t n = hi - lo;
        if (n <= strip_size) {
            std::sort(pts_ + lo, pts_ + hi, Before<0>{});
        } else {
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
        }
        if (n <= progress_unit_ && parent_n > progress_unit_) report(n);
    }

    /// Triangulates points [lo, hi) with edges from the slots [3 lo, 3 hi); @p slots receives
    /// what is left of that range.
    Hull build(std::size_t lo, std::size_t hi, int cut, int frame, EdgeSlots& slots,
               std::size_t parent_n)
    {
        const std::size_t n = hi - lo;
        slots = EdgeSlots{static_cast<EdgeId>(3 * lo), static_cast<EdgeId>(3 * hi)};
        const Hull hull = n <= 3 ? base_case(lo, n, frame, slots)
                                 : build_inner(lo, hi, cut, frame, slots);
        if (n <= progress_unit_ && parent_n > progress_unit_) report(n);
        return hull;
    }

private:
    /// Progress over both passes (split, then build), about a fifth of the work in the first.
    void report(std::size_t n)
    {
        const std::size_t done = done_.fetch_add(n) + n;
        const double total = static_cast<double>(total_);
        const double fraction = done <= total_ ? 0.2 * static_cast<double>(done) / total
                                               : 0.2 + 0.8 * static_cast<double>(done - total_) / total;
        progress_.report(fraction, "triangulating");
    }

    Hull build_inner(std::size_t lo, std::size_t hi, int cut, int frame, EdgeSlots& slots)
    {
        const std::size_t n = hi - lo;
        if (n <= strip_size) cut = 0;  // sorted by x: cut by index, vertically
        const std::size_t mid = lo + n / 2;
        Hull left{};
        Hull right{};
        EdgeSlots left_slots;
        if (options_.parallel_cutoff > 0 && n > options_.parallel_cutoff) {
            bool left_done = false;
            bool right_done = false;
            tbb::parallel_invoke(
                [&] {
                    left = build(lo, mid, 1 - cut, cut, left_slots, n);
                    left_done = true;
                },
                [&] {
                    right = build(mid, hi, 1 - cut, cut, slots, n);
                    right_done = true;
                });
            // When a task elsewhere in the tree threw (cancellation), TBB cancels the shared
            // context and a nested parallel_invoke may return without running its tasks and
            // without an exception: never merge halves that were not built.
            if (!left_done || !right_done) throw Cancelled();
        } else {
            left = build(lo, mid, 1 - cut, cut, left_slots, n);
            right = build(mid, hi, 1 - cut, cut, slots, n);
        }
        // The merge allocates from both halves' leftovers, in an order that does not depend on
        // whether the halves ran in parallel.
        mesh_.absorb_slots(slots, left_slots);
        const Hull merged = merge(left, right, slots);
        return frame == cut ? merged : rehull(merged, frame);
    }

    [[nodiscard]] int orient(VertexId a, VertexId b, VertexId c) const noexcept
    {
        return geom::orient2d(pts_[a].x, pts_[a].y, pts_[b].x, pts_[b].y, pts_[c].x, pts_[c].y);
    }
    [[nodiscard]] bool incircle(VertexId a, VertexId b, VertexId c, VertexId d) const noexcept
    {
        return geom::incircle(pts_[a].x, pts_[a].y, pts_[b].x, pts_[b].y, pts_[c].x, pts_[c].y,
                              pts_[d].x, pts_[d].y) > 0;
    }
    [[nodiscard]] bool rightof(VertexId x, EdgeId e) const noexcept
    {
        return orient(x, mesh_.dest(e), mesh_.org[e]) > 0;
    }
    [[nodiscard]] bool leftof(VertexId x, EdgeId e) const noexcept
    {
        return orient(x, mesh_.org[e], mesh_.dest(e)) > 0;
    }

    /// Two or three points, sorted by x by split(); put in the order of the frame.
    Hull base_case(std::size_t lo, std::size_t n, int frame, EdgeSlots& slots)
    {
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
        const EdgeId a = mesh_.make_edge(slots, v0, v0 + 1);
        if (n == 2) return {a, EdgeMesh::sym(a)};
        const EdgeId b = mesh_.make_edge(slots, v0 + 1, v0 + 2);
        mesh_.splice(EdgeMesh::sym(a), b);
        const int o = orient(v0, v0 + 1, v0 + 2);
        if (o > 0) {
            mesh_.connect(slots, b, a);
            return {a, EdgeMesh::sym(b)};
        }
        if (o < 0) {
            const EdgeId c = mesh_.connect(slots, b, a);
            return {EdgeMesh::sym(c), c};
        }
        return {a, EdgeMesh::sym(b)};
    }

    /// Re-expresses the hull handles in another frame by walking the hull once.
    [[nodiscard]] Hull rehull(Hull hull, int frame) const noexcept
    {
        const EdgeId start = hull.left;
        EdgeId lo_edge = start;
        EdgeId hi_edge = mesh_.oprev[start];
        VertexId lo_v = mesh_.org[start];
        VertexId hi_v = lo_v;
        for (EdgeId e = mesh_.onext[start ^ 1u]; e != start; e = mesh_.onext[e ^ 1u]) {
            const VertexId v = mesh_.org[e];
            if (before(frame, pts_[v], pts_[lo_v])) {
                lo_v = v;
                lo_edge = e;
            }
            if (before(frame, pts_[hi_v], pts_[v])) {
                hi_v = v;
                hi_edge = mesh_.oprev[e];
            }
        }
        return {lo_edge, hi_edge};
    }

    /// Candidate e lies above basel. Repeated vertices are answered without the predicate, whose
    /// filter cannot certify an exact zero and would take the slow exact path.
    [[nodiscard]] bool valid(EdgeId e, EdgeId basel) const noexcept
    {
        const VertexId d = mesh_.dest(e);
        return d != mesh_.org[basel] && d != mesh_.dest(basel) && rightof(d, basel);
    }

    Hull merge(Hull left, Hull right, EdgeSlots& slots)
    {
        EdgeMesh& m = mesh_;
        EdgeId ldo = left.left;
        EdgeId ldi = left.right;
        EdgeId rdi = right.left;
        EdgeId rdo = right.right;
        // Lower common tangent.
        for (;;) {
            if (leftof(m.org[rdi], ldi)) {
                ldi = m.lnext(ldi);
            } else if (rightof(m.org[ldi], rdi)) {
                rdi = m.rprev(rdi);
            } else {
                break;
            }
        }
        EdgeId basel = m.connect(slots, EdgeMesh::sym(rdi), ldi);
        if (m.org[ldi] == m.org[ldo]) ldo = EdgeMesh::sym(basel);
        if (m.org[rdi] == m.org[rdo]) rdo = basel;
        // Zip upwards.
        for (;;) {
            // A candidate's validity is tested again only when edges were deleted in front of it.
            EdgeId lcand = m.onext[EdgeMesh::sym(basel)];
            bool lvalid = valid(lcand, basel);
            if (lvalid) {
                bool deleted = false;
                while (m.dest(m.onext[lcand]) != m.org[basel] &&
                       incircle(m.dest(basel), m.org[basel], m.dest(lcand),
                                m.dest(m.onext[lcand]))) {
                    const EdgeId t = m.onext[lcand];
                    m.delete_edge(slots, lcand);
                    lcand = t;
                    deleted = true;
                }
                if (deleted) lvalid = valid(lcand, basel);
            }
            EdgeId rcand = m.oprev[basel];
            bool rvalid = valid(rcand, basel);
            if (rvalid) {
                bool deleted = false;
                while (m.dest(m.oprev[rcand]) != m.dest(basel) &&
                       incircle(m.dest(basel), m.org[basel], m.dest(rcand),
                                m.dest(m.oprev[rcand]))) {
                    const EdgeId t = m.oprev[rcand];
                    m.delete_edge(slots, rcand);
                    rcand = t;
                    deleted = true;
                }
                if (deleted) rvalid = valid(rcand, basel);
            }
            if (!lvalid && !rvalid) break;
            if (!lvalid ||
                (rvalid && incircle(m.dest(lcand), m.org[lcand], m.org[rcand], m.dest(rcand)))) {
                basel = m.connect(slots, rcand, EdgeMesh::sym(basel));
            } else {
                basel = m.connect(slots, EdgeMesh::sym(basel), EdgeMesh::sym(lcand));
            }
        }
        return {ldo, rdo};
    }

    KernelPoint* pts_;
    EdgeMesh& mesh_;
    const DelaunayDcOptions& options_;
    const Progress& progress_;
    std::size_t total_;
    std::size_t progress_unit_;
    std::atomic<std::size_t> done_{0};
    tbb::enumerable_thread_specific<SelectScratch<KernelPoint>> scratch_;
};

}  // namespace

void delaunay_divide_and_conquer(BigArray<KernelPoint>& points, EdgeMesh& mesh, EdgeSlots& slots,
                                 const DelaunayDcOptions& options, const Progress& progress)
{
    const std::size_t n = points.size();
    mesh.resize_slots(3 * n + 16);
    slots = EdgeSlots{0, static_cast<EdgeId>(3 * n)};
    if (n >= 2) {
        Builder builder(points, mesh, options, progress);
        builder.split(0, n, 0, n + 1);
        builder.build(0, n, 0, 0, slots, n + 1);
    }
    slots.end = static_cast<EdgeId>(mesh.slot_count());
    mesh.points = std::move(points);
    points = {};
}

}  // namespace dtm::detail
