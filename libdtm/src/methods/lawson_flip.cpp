// SPDX-License-Identifier: MIT
// [lawson-flip] Local improvement (thesis 000 §2.4.1 and §2.3; lecture 004 "lokální
// prohazování", Alg. 2 "Delaunay Triangulation Local"; lecture 003 LEGALTRIANGULATION).
//
// Idea: build any triangulation quickly, then flip every illegal edge (the opposite vertex
// strictly inside the circumcircle; an illegal edge's quadrilateral is always convex) until
// none is left. Each flip raises the sorted angle vector, so the process stops, and a
// triangulation without illegal edges is Delaunay (003: legal <=> Delaunay); with the max-min
// angle criterion this is Lawson's algorithm, which converges from any start (R15).
// Initial triangulation: a sweep in lexicographic (x, y) order. Each point is outside the hull
// of the points before it and sees at least one hull edge at the previous point; it is joined
// to every hull edge it sees strictly (a fan), so collinear hull runs stay intact.
// Flip order: `stack` keeps a stack of edges to check (the four outer edges of every flip go
// on it); `pass` is the lecture's literal loop: sweep over all edges, flip the illegal ones,
// repeat until a pass flips nothing. Cocircular quadrilaterals (incircle 0) are legal both
// ways and never flipped, so degenerate input cannot loop.
// Data structure: a triangle array with neighbour links (detail/tri_mesh.hpp), the output's
// own layout. Complexity: O(n log n) sweep plus O(n^2) flips in the worst case (004); the
// sweep's long thin fans need many flips (measured in docs/algorithms/methods.md).
#include "lawson_flip.hpp"

#include <algorithm>
#include <vector>

#include "methods/detail/method_support.hpp"
#include "methods/detail/tri_mesh.hpp"

namespace dtm::methods {
namespace {

using detail::CountingPredicates;
using detail::TriMesh;

struct HullEdge {
    VertexIndex next = no_vertex;
    VertexIndex prev = no_vertex;
    TriangleIndex inner = no_triangle;  ///< the triangle on the inner side of (v, next)
    int side = 0;                       ///< and the corner of it opposite that edge
};

class Sweep {
public:
    Sweep(const std::vector<Point3>& pts, CountingPredicates& pred, TriMesh& mesh)
        : p_(pts), pred_(pred), mesh_(mesh), hull_(pts.size()) {}

    void run(const Progress& progress) {
        std::vector<VertexIndex> order(p_.size());
        for (VertexIndex i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](VertexIndex a, VertexIndex b) {
            return p_[a].x < p_[b].x || (p_[a].x == p_[b].x && p_[a].y < p_[b].y);
        });
        std::size_t k = 2;
        while (pred_.orient(p_[order[0]], p_[order[1]], p_[order[k]]) == 0) ++k;
        start(order, k);
        for (std::size_t i = k + 1; i < order.size(); ++i) {
            if ((i & 4095) == 0)
                progress.report(static_cast<double>(i) / static_cast<double>(order.size()),
                                "sweep");
            add(order[i]);
        }
    }

private:
    TriangleIndex make(VertexIndex a, VertexIndex b, VertexIndex c) {
        Triangle t;
        t.v = {a, b, c};
        mesh_.tri.push_back(t);
        return static_cast<TriangleIndex>(mesh_.tri.size() - 1);
    }
    void link(TriangleIndex t, int i, TriangleIndex u, int j) {
        mesh_[t].n[static_cast<std::size_t>(i)] = u;
        if (u != no_triangle) mesh_[u].n[static_cast<std::size_t>(j)] = t;
    }

    /// The fan of the first k collinear points (sorted along their line) to the first point off
    /// their line; the hull is the chain and that point.
    void start(const std::vector<VertexIndex>& order, std::size_t k) {
        const VertexIndex apex = order[k];
        const bool left = pred_.orient(p_[order[0]], p_[order[1]], p_[apex]) > 0;
        std::vector<VertexIndex> chain(order.begin(), order.begin() + static_cast<long>(k));
        if (!left) std::reverse(chain.begin(), chain.end());
        // chain[0] -> ... -> chain[k-1] -> apex is counter-clockwise.
        TriangleIndex prev = no_triangle;
        for (std::size_t j = 0; j + 1 < chain.size(); ++j) {
            const TriangleIndex t = make(chain[j], chain[j + 1], apex);
            link(t, 1, prev, 0);  // edge (apex, chain[j]) shared with the previous triangle
            hull_[chain[j]] = {chain[j + 1], j == 0 ? apex : chain[j - 1], t, 2};
            prev = t;
        }
        hull_[chain.back()] = {apex, chain[chain.size() - 2], prev, 0};
        hull_[apex] = {chain[0], chain.back(), 0, 1};  // (apex, chain[0]): triangle 0, edge 1
        last_ = apex;
    }

    void add(VertexIndex p) {
        // Forward from the last point (the lexicographic maximum, a hull vertex): edges it sees.
        VertexIndex hi = last_;
        TriangleIndex first_fwd = no_triangle;
        TriangleIndex prev_fwd = no_triangle;
        while (pred_.orient(p_[hi], p_[hull_[hi].next], p_[p]) < 0) {
            const VertexIndex f = hull_[hi].next;
            const TriangleIndex t = make(hi, p, f);
            link(t, 1, hull_[hi].inner, hull_[hi].side);
            link(t, 2, prev_fwd, 0);  // (hi, p) shared with the previous forward triangle
            if (first_fwd == no_triangle) first_fwd = t;
            prev_fwd = t;
            hi = f;
        }
        VertexIndex lo = last_;
        TriangleIndex first_bwd = no_triangle;
        TriangleIndex prev_bwd = no_triangle;
        while (pred_.orient(p_[hull_[lo].prev], p_[lo], p_[p]) < 0) {
            const VertexIndex g = hull_[lo].prev;
            const TriangleIndex t = make(g, p, lo);
            link(t, 1, hull_[g].inner, hull_[g].side);
            link(t, 0, prev_bwd, 2);  // (p, lo) shared with the previous backward triangle
            if (first_bwd == no_triangle) first_bwd = t;
            prev_bwd = t;
            lo = g;
        }
        // The first triangles on both sides share the edge (last, p).
        if (first_fwd != no_triangle && first_bwd != no_triangle) link(first_fwd, 2, first_bwd, 0);
        hull_[lo].next = p;
        hull_[hi].prev = p;
        hull_[p].prev = lo;
        hull_[p].next = hi;
        if (prev_bwd != no_triangle) {
            hull_[lo].inner = prev_bwd;
            hull_[lo].side = 2;
        } else {
            hull_[lo].inner = first_fwd;
            hull_[lo].side = 2;
        }
        if (prev_fwd != no_triangle) {
            hull_[p].inner = prev_fwd;
            hull_[p].side = 0;
        } else {
            hull_[p].inner = first_bwd;
            hull_[p].side = 0;
        }
        last_ = p;
    }

    const std::vector<Point3>& p_;
    CountingPredicates& pred_;
    TriMesh& mesh_;
    std::vector<HullEdge> hull_;
    VertexIndex last_ = no_vertex;
};

/// The edge opposite corner i of t is illegal: the apex across it lies strictly inside t's
/// circumcircle.
bool illegal(const TriMesh& m,
             const std::vector<Point3>& p,
             CountingPredicates& pred,
             TriangleIndex t,
             int i) {
    const Triangle& x = m[t];
    const TriangleIndex u = x.n[static_cast<std::size_t>(i)];
    if (u == no_triangle) return false;
    const VertexIndex d = m[u].v[static_cast<std::size_t>(m.link_back(u, t))];
    return pred.incircle(p[x.v[0]], p[x.v[1]], p[x.v[2]], p[d]) > 0;
}

std::uint64_t flip_by_stack(TriMesh& m,
                            const std::vector<Point3>& p,
                            CountingPredicates& pred,
                            const Progress& progress) {
    struct Edge {
        TriangleIndex t;
        int i;
    };
    std::vector<Edge> stack;
    stack.reserve(m.tri.size() * 3);
    for (TriangleIndex t = 0; t < m.tri.size(); ++t) {
        for (int i = 0; i < 3; ++i) {
            if (m[t].n[static_cast<std::size_t>(i)] > t) stack.push_back({t, i});
        }
    }
    std::uint64_t flips = 0;
    while (!stack.empty()) {
        const Edge e = stack.back();
        stack.pop_back();
        if (!illegal(m, p, pred, e.t, e.i)) continue;
        const TriangleIndex u = m.flip(e.t, e.i);
        if ((++flips & 65535) == 0) progress.check();
        stack.push_back({e.t, 0});
        stack.push_back({e.t, 2});
        stack.push_back({u, 0});
        stack.push_back({u, 1});
    }
    return flips;
}

std::uint64_t flip_by_passes(TriMesh& m,
                             const std::vector<Point3>& p,
                             CountingPredicates& pred,
                             const Progress& progress,
                             std::uint64_t& passes) {
    std::uint64_t flips = 0;
    bool legal = false;
    while (!legal) {
        legal = true;
        ++passes;
        progress.check();
        for (TriangleIndex t = 0; t < m.tri.size(); ++t) {
            for (int i = 0; i < 3; ++i) {
                if (illegal(m, p, pred, t, i)) {
                    (void)m.flip(t, i);
                    ++flips;
                    legal = false;
                }
            }
        }
    }
    return flips;
}

}  // namespace

MethodResult run_lawson_flip(const MethodInput& input,
                             const MethodOptions& options,
                             const Progress& progress) {
    detail::ParamReader params("lawson-flip", options);
    (void)params.choice("initial", {"sweep"}, "sweep");
    const bool passes = params.choice("order", {"stack", "pass"}, "stack") == "pass";
    params.finish();
    CountingPredicates pred;
    detail::PreparedPoints prepared = detail::prepare_points("lawson-flip", input, pred);
    const std::vector<Point3>& pts = prepared.vertices;

    TriMesh mesh;
    mesh.tri.reserve(2 * pts.size());
    Sweep(pts, pred, mesh).run(progress.sub(0.0, 0.2));
    MethodResult result;
    result.counters.extra["initial_orient_calls"] = pred.orient_calls();
    std::uint64_t pass_count = 0;
    result.counters.flips = passes ? flip_by_passes(mesh, pts, pred, progress, pass_count)
                                   : flip_by_stack(mesh, pts, pred, progress);
    if (passes) result.counters.extra["passes"] = pass_count;
    // Peak: points, triangles, hull records, the flip stack (3 entries per triangle).
    const std::size_t peak = detail::bytes_of(pts) + detail::bytes_of(mesh.tri) +
                             pts.size() * (sizeof(HullEdge) + 2 * sizeof(VertexIndex)) +
                             (passes ? 0 : mesh.tri.size() * 3 * 8);
    result.tin.vertices = std::move(prepared.vertices);
    result.tin.triangles = std::move(mesh.tri);
    detail::finish_counters(result, pred, prepared.duplicates, peak);
    progress.report(1.0, "flipped");
    return result;
}

}  // namespace dtm::methods
