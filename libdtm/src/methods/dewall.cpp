// SPDX-License-Identifier: MIT
// [dewall] DeWall, the Delaunay Wall (Cignoni, Montani, Perego, Scopigno 1992/1998, [CIG92];
// thesis 000 §3.9): divide and conquer without a merge phase.
//
// Idea: split the points by a line alpha (the median, vertical and horizontal by turns) into
// P1 and P2; first build the wall, the Delaunay triangles with vertices on both sides, then
// triangulate the two halves recursively, independently of each other: here in parallel with
// TBB (the halves share nothing but the read-only points and grid; each returns its
// triangles, concatenated wall first, then P1's, then P2's, so the result does not depend on
// the number of threads). The wall grows from faces crossing alpha through an active face
// list (AFL, detail/front.hpp: directed edges whose left side is open; a face with both ends
// in P1 goes to P1's list, in P2 to P2's); MakeSimplex is the Delaunay third point among the
// current subset, searched in one uniform grid over all points (detail/grid_search.hpp,
// subset membership = an index range of the k-d order the points are renumbered in).
// First simplex (erratum of the source, see docs/algorithms/methods.md): the thesis' "p1 near
// the cut, p2 its nearest point across the cut" need not be a Delaunay edge; the closest pair
// across the cut always is (its diametral circle is empty), so p1-p2 is the nearest point
// across of p1, improved over every point of the slab |x - alpha| < |p1 p2|.
// A subset whose list has no face crossing its cut (possible only for skewed sets) is
// finished as one advancing front without splitting, which is always correct.
// Complexity: O(n log n) (000): each level builds its walls with O(1) grid cells per face.
#include "dewall.hpp"

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <mutex>
#include <unordered_map>

#include "methods/detail/grid_search.hpp"
#include "methods/detail/method_support.hpp"
#include "methods/detail/point_grid.hpp"

namespace dtm::methods {
namespace {

using detail::CountingPredicates;
using detail::TriangleCorners;

struct Face {
    VertexIndex a, b;  ///< directed: the left side is open
};

/// Renumbers the points into k-d order: each segment of the order is split at its middle by
/// the median of x (even depths) or y (odd depths), ties by the other coordinate, then index.
void kd_order(const std::vector<Point3>& p, VertexIndex* first, VertexIndex* last, int depth) {
    if (last - first < 2) return;
    VertexIndex* mid = first + (last - first) / 2;
    const bool by_x = depth % 2 == 0;
    std::nth_element(first, mid, last, [&](VertexIndex u, VertexIndex w) {
        const double ua = by_x ? p[u].x : p[u].y, wa = by_x ? p[w].x : p[w].y;
        const double ub = by_x ? p[u].y : p[u].x, wb = by_x ? p[w].y : p[w].x;
        return ua < wa || (ua == wa && (ub < wb || (ub == wb && u < w)));
    });
    kd_order(p, first, mid, depth + 1);
    kd_order(p, mid, last, depth + 1);
}

/// Per thread: predicate counts and a grid search (its cell stamps).
struct Worker {
    Worker(const detail::PointGrid& grid, const std::vector<Point3>& p) : search(grid, p, pred) {}
    CountingPredicates pred;
    detail::GridThirdPoint search;
};

class DeWall {
public:
    DeWall(const std::vector<Point3>& pts, unsigned threads)
        : p_(pts),
          grid_(pts, 0.0),
          arena_(threads == 0 ? tbb::task_arena::automatic : static_cast<int>(threads)) {}

    std::vector<TriangleCorners> run() {
        std::vector<TriangleCorners> out;
        arena_.execute([&] { out = solve(0, static_cast<VertexIndex>(p_.size()), 0, {}); });
        return out;
    }

    void add_counts(CountingPredicates& total) {
        for (const auto& w : workers_) total.add(w->pred);
    }
    std::size_t bytes() const {
        std::size_t b = grid_.bytes();
        for (const auto& w : workers_) b += w->search.bytes();
        return b;
    }

private:
    Worker& worker() {
        const int id = std::max(tbb::this_task_arena::current_thread_index(), 0);
        std::lock_guard<std::mutex> lock(workers_mutex_);
        while (workers_.size() <= static_cast<std::size_t>(id)) {
            workers_.push_back(std::make_unique<Worker>(grid_, p_));
        }
        return *workers_[static_cast<std::size_t>(id)];
    }

    /// The closest pair across the cut of [lo, hi) at mid, then its first triangle.
    TriangleCorners first_simplex(
        VertexIndex lo, VertexIndex mid, VertexIndex hi, bool by_x, Worker& w) {
        // P1's points are at or before the cut, P2's at or after it in the split coordinate:
        // a pair across closer than d has both ends within d of P1's largest coordinate.
        auto coord = [&](VertexIndex v) { return by_x ? p_[v].x : p_[v].y; };
        double cut = coord(lo);
        for (VertexIndex v = lo; v < mid; ++v) cut = std::max(cut, coord(v));
        auto off = [&](VertexIndex v) { return std::abs(coord(v) - cut); };
        VertexIndex a = lo;
        for (VertexIndex v = lo; v < mid; ++v) {
            if (off(v) < off(a)) a = v;
        }
        const auto in2 = [&](VertexIndex v) { return v >= mid && v < hi; };
        VertexIndex b = detail::nearest_in_grid(grid_, p_, w.pred, a, in2);
        double d = std::hypot(p_[a].x - p_[b].x, p_[a].y - p_[b].y) * (1.0 + 1e-9);
        for (VertexIndex v = lo; v < mid; ++v) {
            if (v == a || off(v) > d * (1.0 + 1e-9)) continue;
            const VertexIndex u = detail::nearest_in_grid(grid_, p_, w.pred, v, in2, d);
            if (u != no_vertex && w.pred.compare_distances(p_[v], p_[u], p_[a], p_[b]) < 0) {
                a = v;
                b = u;
                d = std::hypot(p_[a].x - p_[b].x, p_[a].y - p_[b].y) * (1.0 + 1e-9);
            }
        }
        const auto in = [&](VertexIndex v) { return v >= lo && v < hi; };
        VertexIndex c = w.search.find(a, b, in);
        if (c == no_vertex) {
            std::swap(a, b);
            c = w.search.find(a, b, in);
        }
        return {a, b, c};
    }

    /// DeWall(P = [lo, hi), AFL): the triangles made for this subset and below.
    std::vector<TriangleCorners> solve(VertexIndex lo,
                                       VertexIndex hi,
                                       int depth,
                                       std::vector<Face> afl) {
        Worker& w = worker();
        const VertexIndex mid = lo + (hi - lo) / 2;
        const bool by_x = depth % 2 == 0;
        const auto in = [lo, hi](VertexIndex v) { return v >= lo && v < hi; };
        // side: 0 both in P1, 1 both in P2, 2 crossing.
        const auto side = [mid](const Face& f) {
            const bool a1 = f.a < mid, b1 = f.b < mid;
            return a1 && b1 ? 0 : (!a1 && !b1 ? 1 : 2);
        };
        std::vector<TriangleCorners> out;
        // The open faces of this call, by edge; lists per side with lazy deletion.
        std::unordered_map<std::uint64_t, int> open;
        std::vector<Face> lists[3];
        const auto key = [](VertexIndex a, VertexIndex b) {
            return (static_cast<std::uint64_t>(a) << 32) | b;
        };
        const auto insert = [&](Face f) {
            const int s = side(f);
            open[key(f.a, f.b)] = s;
            lists[s].push_back(f);
        };
        // Update (DeWall): a face of a new triangle closes its open twin or opens.
        const auto update = [&](VertexIndex a, VertexIndex b) {
            const auto it = open.find(key(a, b));
            if (it != open.end()) {
                open.erase(it);
            } else {
                insert({b, a});
            }
        };
        const auto add_triangle = [&](const TriangleCorners& t) {
            out.push_back(t);
            update(t[1], t[2]);
            update(t[2], t[0]);
        };
        if (afl.empty()) {
            const TriangleCorners t = first_simplex(lo, mid, hi, by_x, w);
            out.push_back(t);
            for (int k = 0; k < 3; ++k)
                insert({t[static_cast<std::size_t>((k + 1) % 3)], t[static_cast<std::size_t>(k)]});
        } else {
            for (const Face& f : afl) insert(f);
        }
        detail::free_storage(afl);
        const bool split = !lists[2].empty() && hi - lo > 2;
        if (!split) {
            // No face crosses the cut: finish this subset as one advancing front.
            if (hi - lo > 2) ++unsplit_;
            for (int s = 0; s < 2; ++s) {
                lists[2].insert(lists[2].end(), lists[s].begin(), lists[s].end());
                lists[s].clear();
            }
            for (auto& [k, s] : open) s = 2;
        }
        // The wall: every open crossing face, first in, first out.
        for (std::size_t i = 0; i < lists[2].size(); ++i) {
            const Face f = lists[2][i];
            const auto it = open.find(key(f.a, f.b));
            if (it == open.end() || it->second != 2) continue;  // closed since
            open.erase(it);
            const VertexIndex c = w.search.find(f.a, f.b, in);
            if (c == no_vertex) {
                ++hull_;
                continue;
            }
            const TriangleCorners t{f.a, f.b, c};
            if (!split) {
                out.push_back(t);
                for (const auto& [u, v] : {std::pair{t[1], t[2]}, std::pair{t[2], t[0]}}) {
                    const auto o = open.find(key(u, v));
                    if (o != open.end()) {
                        open.erase(o);
                    } else {
                        open[key(v, u)] = 2;
                        lists[2].push_back({v, u});
                    }
                }
            } else {
                add_triangle(t);
            }
        }
        if (split) ++walls_;
        std::vector<Face> afl1;
        std::vector<Face> afl2;
        for (int s = 0; s < 2 && split; ++s) {
            for (const Face& f : lists[s]) {
                const auto it = open.find(key(f.a, f.b));
                if (it != open.end() && it->second == s) (s == 0 ? afl1 : afl2).push_back(f);
            }
        }
        detail::free_storage(open);
        std::vector<TriangleCorners> left;
        std::vector<TriangleCorners> right;
        tbb::task_group tasks;
        if (!afl1.empty()) {
            tasks.run([&] { left = solve(lo, mid, depth + 1, std::move(afl1)); });
        }
        if (!afl2.empty()) right = solve(mid, hi, depth + 1, std::move(afl2));
        tasks.wait();
        out.reserve(out.size() + left.size() + right.size());  // one exact growth, not two
        out.insert(out.end(), left.begin(), left.end());
        detail::free_storage(left);
        out.insert(out.end(), right.begin(), right.end());
        return out;
    }

    const std::vector<Point3>& p_;
    detail::PointGrid grid_;
    tbb::task_arena arena_;
    std::mutex workers_mutex_;
    std::vector<std::unique_ptr<Worker>> workers_;
    std::atomic<std::uint64_t> hull_{0};
    std::atomic<std::uint64_t> walls_{0};
    std::atomic<std::uint64_t> unsplit_{0};

public:
    std::uint64_t hull_count() const { return hull_.load(); }
    std::uint64_t wall_count() const { return walls_.load(); }
    std::uint64_t unsplit_count() const { return unsplit_.load(); }
};

}  // namespace

MethodResult run_dewall(const MethodInput& input,
                        const MethodOptions& options,
                        const Progress& progress) {
    detail::ParamReader params("dewall", options);
    params.finish();
    CountingPredicates pred;
    detail::PreparedPoints prepared = detail::prepare_points("dewall", input, pred);
    const std::vector<Point3>& in = prepared.vertices;
    // Renumber into k-d order (subsets = index ranges).
    std::vector<VertexIndex> perm(in.size());
    for (VertexIndex i = 0; i < perm.size(); ++i) perm[i] = i;
    kd_order(in, perm.data(), perm.data() + perm.size(), 0);
    std::vector<Point3> pts(in.size());
    for (std::size_t k = 0; k < pts.size(); ++k) pts[k] = in[perm[k]];
    progress.report(0.1, "walls");
    MethodResult result;
    std::size_t peak = 0;
    std::vector<TriangleCorners> triangles;
    {
        DeWall dw(pts, options.threads);
        triangles = dw.run();
        progress.check();
        dw.add_counts(pred);
        result.counters.extra["hull_edges"] = dw.hull_count();
        result.counters.extra["walls"] = dw.wall_count();
        result.counters.extra["unsplit_subsets"] = dw.unsplit_count();
        peak = dw.bytes() + detail::bytes_of(pts) + detail::bytes_of(in) + detail::bytes_of(perm) +
               2 * detail::bytes_of(triangles);
    }
    detail::free_storage(pts);  // the k-d ordered copy
    for (TriangleCorners& t : triangles) {
        for (VertexIndex& v : t) v = perm[v];
    }
    detail::free_storage(perm);
    peak = std::max(peak, detail::bytes_of(in) + detail::bytes_of(triangles) +
                              triangles.size() * sizeof(Triangle));
    result.tin = detail::tin_from_triangles(std::move(prepared.vertices), std::move(triangles));
    detail::finish_counters(result, pred, prepared.duplicates, peak);
    progress.report(1.0, "triangulated");
    return result;
}

}  // namespace dtm::methods
