// SPDX-License-Identifier: MIT
// [topological-dc] Voronoi/Delaunay by topology-oriented divide and conquer (Oishi and
// Sugihara 1993, [OIS93]; thesis 000 §3.7, Algorithm 1 with conditions 1-6).
//
// Idea: sort the points, split them at the median into a left and a right half of sizes
// differing by at most one, triangulate each recursively (2 or 3 points directly), merge:
// the lower common tangent is the first base edge; above it, the neighbours of the base's
// ends that fail the circle test are deleted and a cross edge closes the next triangle, until
// the upper tangent is reached. The merge is Guibas and Stolfi's, guarded by the topological
// conditions (detail/topological_merge.hpp): numbers only choose among topologically valid
// actions, so even wrong in-circle answers leave a simple, connected planar graph of
// triangles (tested with corrupted predicates); with exact ones the result is Delaunay.
// Data structure: the primal quad-edge (detail/edge_algebra.hpp). Complexity O(n log n) worst
// case (000); the thesis' O(N) average with Katajainen's quarter cuts is not done here.
#include "topological_dc.hpp"

#include <algorithm>

#include "methods/detail/method_support.hpp"
#include "methods/detail/topological_merge.hpp"

namespace dtm::methods {
namespace {

struct ExactPredicates {
    const std::vector<Point3>& p;
    detail::CountingPredicates& pred;
    int orient(VertexIndex a, VertexIndex b, VertexIndex c) {
        return pred.orient(p[a], p[b], p[c]);
    }
    int incircle(VertexIndex a, VertexIndex b, VertexIndex c, VertexIndex d) {
        return pred.incircle(p[a], p[b], p[c], p[d]);
    }
};

}  // namespace

MethodResult run_topological_dc(const MethodInput& input,
                                const MethodOptions& options,
                                const Progress& progress) {
    detail::ParamReader params("topological-dc", options);
    params.finish();
    detail::CountingPredicates pred;
    detail::PreparedPoints prepared = detail::prepare_points("topological-dc", input, pred);
    const std::vector<Point3>& p = prepared.vertices;
    std::vector<VertexIndex> order(p.size());
    for (VertexIndex i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](VertexIndex a, VertexIndex b) {
        return p[a].x < p[b].x || (p[a].x == p[b].x && p[a].y < p[b].y);
    });
    progress.report(0.1, "dividing");
    ExactPredicates exact{p, pred};
    detail::TopologicalDc<ExactPredicates> dc(std::move(order), exact);
    dc.run();
    progress.check();
    const detail::EdgeAlgebra& q = dc.edges();
    // The counter-clockwise faces of three edges are the triangles (the outer face runs
    // clockwise).
    std::vector<detail::TriangleCorners> triangles;
    triangles.reserve(2 * p.size());
    std::vector<bool> seen(q.half_edges(), false);
    for (detail::HalfEdge e = 0; e < q.half_edges(); ++e) {
        if (seen[e] || !q.alive(e)) continue;
        const detail::HalfEdge f = q.lnext(e);
        const detail::HalfEdge g = q.lnext(f);
        seen[e] = seen[f] = seen[g] = true;
        if (q.lnext(g) != e) {
            for (detail::HalfEdge h = q.lnext(g); h != e; h = q.lnext(h)) seen[h] = true;
            continue;
        }
        const detail::TriangleCorners t{q.org(e), q.org(f), q.org(g)};
        if (pred.orient(p[t[0]], p[t[1]], p[t[2]]) > 0) triangles.push_back(t);
    }
    MethodResult result;
    const detail::MergeCounts& c = dc.counts();
    result.counters.extra["deletions"] = c.deletions;
    result.counters.extra["refused_deletions"] = c.refused_deletions;
    result.counters.extra["conflicts"] = c.conflicts;
    const std::size_t peak = q.bytes() + detail::bytes_of(p) + p.size() * sizeof(VertexIndex) +
                             detail::bytes_of(triangles) + seen.capacity() / 8 +
                             triangles.size() * sizeof(Triangle);
    result.tin = detail::tin_from_triangles(std::move(prepared.vertices), triangles);
    detail::finish_counters(result, pred, prepared.duplicates, peak);
    progress.report(1.0, "triangulated");
    return result;
}

}  // namespace dtm::methods
