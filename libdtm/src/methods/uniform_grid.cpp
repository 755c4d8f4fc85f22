// SPDX-License-Identifier: MIT
// [uniform-grid] Delaunay triangulation using a uniform grid, after Fang and Piegl 1993
// ([FANG93]), as the thesis implemented it (000 §3.10, program DTUG.EXE with the vertex-list
// control, §3.10.8).
//
// Idea: bucket the points in a uniform grid (about one per cell); start at the middle cell,
// join its point to its exact nearest neighbour (a Delaunay edge); then peel the triangulation
// outwards: the front is a circular list of half-edges, the active one is the last; its
// Delaunay third point on the right is searched in the grid (detail/grid_search.hpp); a new
// point extends the front, a point adjacent on the front closes a notch (right or left touch,
// the vertex between becomes interior: its clockwise vertex list is complete and streamed, and
// it leaves the grid), any other used point would pinch the front (no touch: the head
// half-edge moves to the tail and is tried first), and no point at all makes the active edge a
// hull edge (deleted, the head moves to the tail). It ends with an empty list; the surviving
// front is the hull (§3.10.5).
// Robustness: every side and circle test is exact, so the thesis' cavities (the wrong side
// test of Fig. 33, R5/R52) cannot occur; the triangle count is checked at the end anyway.
// Cocircular points (claimed but not explained by the thesis, erratum 12) get the consistent
// fan rule of detail/third_point.hpp. Exact duplicates are merged before (TOL = 0; `tol=`
// drops points within TOL of one already in the same cell, as §3.10.1 does).
// Complexity: linear on uniform input (each search scans O(1) cells; interior points leave
// the grid), as the thesis measured on a 486 (Fig. 36).
#include "uniform_grid.hpp"

#include <deque>
#include <stdexcept>

#include "dtm/core/error.hpp"
#include "dtm/methods/vertex_list.hpp"
#include "methods/detail/grid_search.hpp"
#include "methods/detail/method_support.hpp"
#include "methods/detail/point_grid.hpp"

namespace dtm::methods {
namespace {

using detail::CountingPredicates;

/// Per-vertex clockwise lists growing at both ends (the thesis' VERTEX_LIST / header lists),
/// nodes recycled once a list is streamed.
class ListPool {
public:
    explicit ListPool(std::size_t n) : head_(n, none), tail_(n, none) {}
    void push_back(VertexIndex v, VertexIndex w) {
        const std::uint32_t k = node(w, none);
        if (tail_[v] == none) {
            head_[v] = tail_[v] = k;
        } else {
            nodes_[tail_[v]].next = k;
            tail_[v] = k;
        }
    }
    void push_front(VertexIndex v, VertexIndex w) {
        const std::uint32_t k = node(w, head_[v]);
        head_[v] = k;
        if (tail_[v] == none) tail_[v] = k;
    }
    /// The list of v, then its nodes are free again.
    void take(VertexIndex v, std::vector<VertexIndex>& out) {
        out.clear();
        for (std::uint32_t k = head_[v]; k != none;) {
            out.push_back(nodes_[k].w);
            const std::uint32_t next = nodes_[k].next;
            nodes_[k].next = free_;
            free_ = k;
            k = next;
        }
        head_[v] = tail_[v] = none;
    }
    [[nodiscard]] std::size_t bytes() const noexcept {
        return nodes_.capacity() * sizeof(Node) + (head_.capacity() + tail_.capacity()) * 4;
    }

private:
    static constexpr std::uint32_t none = 0xffffffffu;
    struct Node {
        VertexIndex w;
        std::uint32_t next;
    };
    std::uint32_t node(VertexIndex w, std::uint32_t next) {
        if (free_ != none) {
            const std::uint32_t k = free_;
            free_ = nodes_[k].next;
            nodes_[k] = {w, next};
            return k;
        }
        nodes_.push_back({w, next});
        return static_cast<std::uint32_t>(nodes_.size() - 1);
    }
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> head_;
    std::vector<std::uint32_t> tail_;
    std::uint32_t free_ = none;
};

class GridSweep {
public:
    GridSweep(const std::vector<Point3>& pts,
              CountingPredicates& pred,
              double tol,
              const VertexListSink& sink)
        : p_(pts),
          pred_(pred),
          grid_(pts, tol),
          search_(grid_, pts, pred),
          next_(pts.size(), no_vertex),
          prev_(pts.size(), no_vertex),
          used_(pts.size(), 0),
          lists_(pts.size()),
          sink_(sink) {
        triangles_.reserve(2 * pts.size());
    }

    void run(const Progress& progress);

    std::vector<detail::TriangleCorners> triangles_;
    std::uint64_t hull_edges = 0;
    std::uint64_t no_touch = 0;
    std::uint64_t touches = 0;
    std::uint64_t streamed = 0;
    std::size_t peak = 0;
    [[nodiscard]] std::uint64_t cells_scanned() const { return search_.cells_scanned(); }
    [[nodiscard]] std::size_t bytes() const {
        return grid_.bytes() + search_.bytes() + lists_.bytes() + detail::bytes_of(triangles_) +
               9 * p_.size();
    }

private:
    VertexIndex start_point() const;
    void emit(VertexIndex v, bool hull) {
        lists_.take(v, scratch_);
        if (!hull && scratch_.size() > 1) scratch_.pop_back();  // cyclic: first came back
        ++streamed;
        if (sink_) sink_(v, scratch_, hull);
    }
    void interior(VertexIndex v) {
        grid_.remove(v, p_[v]);
        used_[v] = 2;
        emit(v, false);
    }

    const std::vector<Point3>& p_;
    CountingPredicates& pred_;
    detail::PointGrid grid_;
    detail::GridThirdPoint search_;
    std::vector<VertexIndex> next_;  ///< the front polygon (the triangulated part on the left)
    std::vector<VertexIndex> prev_;
    std::vector<std::uint8_t> used_;  ///< 0 unused, 1 on the front, 2 interior
    ListPool lists_;
    VertexListSink sink_;
    std::vector<VertexIndex> scratch_;
};

/// The first point of the middle cell, or of the nearest ring of cells around it (R46).
VertexIndex GridSweep::start_point() const {
    const int mc = grid_.cols() / 2, mr = grid_.rows() / 2;
    const int rings = std::max(grid_.cols(), grid_.rows());
    for (int k = 0; k <= rings; ++k) {
        for (int r = mr - k; r <= mr + k; ++r) {
            for (int c = mc - k; c <= mc + k; ++c) {
                if (r < 0 || c < 0 || r >= grid_.rows() || c >= grid_.cols()) continue;
                if (std::max(std::abs(r - mr), std::abs(c - mc)) != k) continue;
                VertexIndex found = no_vertex;
                grid_.for_each(c, r, [&](VertexIndex v) {
                    if (found == no_vertex) found = v;
                });
                if (found != no_vertex) return found;
            }
        }
    }
    return 0;
}

void GridSweep::run(const Progress& progress) {
    const VertexIndex p1 = start_point();
    const VertexIndex p2 =
        detail::nearest_in_grid(grid_, p_, pred_, p1, [](VertexIndex) { return true; });
    used_[p1] = used_[p2] = 1;
    next_[p1] = prev_[p1] = p2;
    next_[p2] = prev_[p2] = p1;
    lists_.push_back(p1, p2);
    lists_.push_back(p2, p1);
    struct Half {
        VertexIndex s, e;
    };
    std::deque<Half> queue{{p2, p1}, {p1, p2}};
    const auto keep = [](VertexIndex) { return true; };
    std::uint64_t rotations = 0;
    while (!queue.empty()) {
        if ((triangles_.size() & 4095) == 0) {
            progress.report(
                static_cast<double>(triangles_.size()) / (2.0 * static_cast<double>(p_.size())),
                "peeling");
        }
        const Half act = queue.back();
        const VertexIndex ps = act.s, pe = act.e;
        const VertexIndex p = search_.find(pe, ps, keep);  // right of ps -> pe
        if (p == no_vertex) {                              // a hull edge
            queue.pop_back();
            ++hull_edges;
            if (!queue.empty()) {
                queue.push_back(queue.front());
                queue.pop_front();
            }
            continue;
        }
        if (used_[p] && prev_[ps] == p) {  // right touch: ps becomes interior
            if (queue.front().s != p || queue.front().e != ps) {
                throw std::logic_error("uniform-grid: front out of order at a right touch");
            }
            queue.pop_front();
            queue.pop_back();
            queue.push_back({p, pe});
            triangles_.push_back({pe, ps, p});
            lists_.push_back(ps, p);
            lists_.push_front(pe, p);
            lists_.push_back(p, pe);
            next_[p] = pe;
            prev_[pe] = p;
            interior(ps);
            ++touches;
        } else if (used_[p] && next_[pe] == p) {  // left touch: pe becomes interior
            queue.pop_back();
            if (queue.empty() || queue.back().s != pe || queue.back().e != p) {
                throw std::logic_error("uniform-grid: front out of order at a left touch");
            }
            queue.pop_back();
            queue.push_back({ps, p});
            triangles_.push_back({pe, ps, p});
            lists_.push_back(ps, p);
            lists_.push_front(pe, p);
            lists_.push_front(p, ps);
            next_[ps] = p;
            prev_[p] = ps;
            interior(pe);
            ++touches;
        } else if (used_[p]) {  // no touch: the front would be pinched; try the head first
            ++no_touch;
            if (++rotations > 4 * queue.size() + 16) {
                throw std::logic_error("uniform-grid: the front makes no progress");
            }
            queue.push_back(queue.front());
            queue.pop_front();
            continue;
        } else {  // a new point
            used_[p] = 1;
            queue.pop_back();
            queue.push_back({p, pe});
            queue.push_back({ps, p});
            triangles_.push_back({pe, ps, p});
            lists_.push_back(ps, p);
            lists_.push_front(pe, p);
            lists_.push_back(p, ps);
            lists_.push_back(p, pe);
            prev_[p] = ps;
            next_[p] = pe;
            next_[ps] = p;
            prev_[pe] = p;
        }
        rotations = 0;
        if ((triangles_.size() & 1023) == 0) peak = std::max(peak, bytes());
    }
    peak = std::max(peak, bytes());
    // The survivors of the front are the hull (§3.10.5): their lists are open.
    for (VertexIndex v = 0; v < p_.size(); ++v) {
        if (used_[v] == 1) emit(v, true);
    }
}

struct SweepOutput {
    std::vector<detail::TriangleCorners> triangles;
    MethodCounters counters;
};

/// The sweep over @p input, run on a copy in grid-cell order (neighbours in the grid are then
/// neighbours in memory); triangles and lists come back in the input's numbering.
SweepOutput sweep(const std::vector<Point3>& input,
                  CountingPredicates& pred,
                  double tol,
                  const VertexListSink& sink,
                  const Progress& progress) {
    std::vector<VertexIndex> perm = detail::PointGrid(input, tol).cell_order();
    std::vector<Point3> pts(input.size());
    for (std::size_t k = 0; k < pts.size(); ++k) pts[k] = input[perm[k]];
    std::vector<VertexIndex> mapped;
    const VertexListSink relabel = [&](VertexIndex v, std::span<const VertexIndex> cw, bool h) {
        mapped.resize(cw.size());
        for (std::size_t i = 0; i < cw.size(); ++i) mapped[i] = perm[cw[i]];
        sink(perm[v], mapped, h);
    };
    GridSweep g(pts, pred, tol, sink ? relabel : VertexListSink{});
    g.run(progress);
    SweepOutput out;
    out.counters.extra["hull_edges"] = g.hull_edges;
    out.counters.extra["no_touch"] = g.no_touch;
    out.counters.extra["touches"] = g.touches;
    out.counters.extra["cells_scanned"] = g.cells_scanned();
    out.counters.extra["vertex_lists"] = g.streamed;
    out.counters.peak_bytes =
        g.peak + detail::bytes_of(pts) + detail::bytes_of(input) + detail::bytes_of(perm);
    const std::size_t h = g.hull_edges;
    if (g.triangles_.size() + 2 + h != 2 * pts.size()) {
        // R52: a cavity or an overlap would show here (never with exact predicates).
        throw std::logic_error("uniform-grid: topology error (" +
                               std::to_string(g.triangles_.size()) + " triangles)");
    }
    out.triangles = std::move(g.triangles_);
    for (detail::TriangleCorners& t : out.triangles) {
        for (VertexIndex& v : t) v = perm[v];
    }
    return out;
}

}  // namespace

MethodResult run_uniform_grid(const MethodInput& input,
                              const MethodOptions& options,
                              const Progress& progress) {
    detail::ParamReader params("uniform-grid", options);
    const double tol = params.number("tol", 0.0, 0.0, 1e300);
    params.finish();
    CountingPredicates pred;
    detail::PreparedPoints prepared = detail::prepare_points("uniform-grid", input, pred);
    std::size_t dropped = 0;
    if (tol > 0.0) {
        // §3.10.1: a point within TOL of one already stored in its cell is ignored.
        detail::PointGrid cells(prepared.vertices, tol);
        std::vector<std::uint8_t> keep(prepared.vertices.size(), 1);
        std::vector<Point3> kept;
        for (VertexIndex i = 0; i < prepared.vertices.size(); ++i) {
            const Point3& q = prepared.vertices[i];
            bool near = false;
            cells.for_each(cells.col(q.x), cells.row(q.y), [&](VertexIndex j) {
                if (j < i && keep[j] &&
                    std::hypot(prepared.vertices[j].x - q.x, prepared.vertices[j].y - q.y) <= tol) {
                    near = true;
                }
            });
            keep[i] = near ? 0 : 1;
            if (keep[i]) kept.push_back(q);
        }
        dropped = prepared.vertices.size() - kept.size();
        prepared.vertices = std::move(kept);
        (void)detail::prepare_points("uniform-grid", MethodInput{prepared.vertices, {}}, pred);
    }
    SweepOutput out = sweep(prepared.vertices, pred, tol, {}, progress.sub(0.0, 0.95));
    MethodResult result;
    result.counters = std::move(out.counters);
    const std::size_t peak =
        std::max(result.counters.peak_bytes, detail::bytes_of(prepared.vertices) +
                                                 detail::bytes_of(out.triangles) +
                                                 out.triangles.size() * sizeof(Triangle));
    result.tin = detail::tin_from_triangles(std::move(prepared.vertices), out.triangles);
    detail::finish_counters(result, pred, prepared.duplicates + dropped, peak);
    progress.report(1.0, "triangulated");
    return result;
}

VertexList uniform_grid_vertex_list(std::span<const Point3> points, const VertexListSink& sink) {
    CountingPredicates pred;
    detail::PreparedPoints prepared =
        detail::prepare_points("uniform-grid", MethodInput{points, {}}, pred);
    if (prepared.duplicates > 0) {
        throw InputError("uniform_grid_vertex_list: the points must be distinct");
    }
    std::vector<std::vector<VertexIndex>> lists(prepared.vertices.size());
    std::vector<bool> hull(prepared.vertices.size(), false);
    const VertexListSink collect = [&](VertexIndex v, std::span<const VertexIndex> cw, bool h) {
        lists[v].assign(cw.begin(), cw.end());
        hull[v] = h;
        if (sink) sink(v, cw, h);
    };
    (void)sweep(prepared.vertices, pred, 0.0, collect, Progress{});
    return make_vertex_list(lists, hull);
}

}  // namespace dtm::methods
