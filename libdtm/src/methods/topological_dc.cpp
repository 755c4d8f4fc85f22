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
    const std::vector<Point2>& p;
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
    // Work on a copy sorted lexicographically (the division's order), so that each half's
    // points are contiguous in memory; triangles are mapped back at the end.
    std::vector<VertexIndex> perm(prepared.vertices.size());
    for (VertexIndex i = 0; i < perm.size(); ++i) perm[i] = i;
    {
        const std::vector<Point3>& in = prepared.vertices;
        std::sort(perm.begin(), perm.end(), [&](VertexIndex a, VertexIndex b) {
            return in[a].x < in[b].x || (in[a].x == in[b].x && in[a].y < in[b].y);
        });
    }
    std::vector<Point2> p(perm.size());
    for (std::size_t k = 0; k < p.size(); ++k) p[k] = prepared.vertices[perm[k]].xy();
    std::vector<VertexIndex> order(p.size());
    for (VertexIndex i = 0; i < order.size(); ++i) order[i] = i;
    progress.report(0.1, "dividing");
    ExactPredicates exact{p, pred};
    detail::TopologicalDc<ExactPredicates> dc(std::move(order), exact);
    dc.run();
    progress.check();
    const std::size_t working = dc.edges().bytes() + detail::bytes_of(p) +
                                detail::bytes_of(prepared.vertices) + 2 * detail::bytes_of(perm);
    detail::free_storage(p);
    const std::vector<Point3>& v = prepared.vertices;
    // The counter-clockwise faces of three edges are the triangles (the outer face runs
    // clockwise), each taken at its smallest half-edge; there are E - n + 1 of them (Euler).
    // The links are made from the corners once the quad-edges are freed.
    std::vector<Triangle> triangles;
    std::size_t collecting = 0;
    {
        const detail::EdgeAlgebra& q = dc.edges();
        triangles.reserve(std::max(q.edges() + 1, v.size()) - v.size());
        for (detail::HalfEdge e = 0; e < q.half_edges(); ++e) {
            if (!q.alive(e)) continue;
            const detail::HalfEdge f = q.lnext(e);
            const detail::HalfEdge g = q.lnext(f);
            if (q.lnext(g) != e || f < e || g < e ||
                pred.orient(v[perm[q.org(e)]], v[perm[q.org(f)]], v[perm[q.org(g)]]) <= 0) {
                continue;
            }
            Triangle x;
            x.v = {perm[q.org(e)], perm[q.org(f)], perm[q.org(g)]};
            triangles.push_back(x);
        }
        collecting =
            q.bytes() + detail::bytes_of(v) + detail::bytes_of(perm) + detail::bytes_of(triangles);
    }
    const detail::MergeCounts c = dc.counts();
    dc.release();  // the quad-edges
    detail::free_storage(perm);
    detail::link_in_place(triangles, v.size());
    MethodResult result;
    result.counters.extra["deletions"] = c.deletions;
    result.counters.extra["refused_deletions"] = c.refused_deletions;
    result.counters.extra["conflicts"] = c.conflicts;
    const std::size_t peak = std::max(working, collecting);
    result.tin.vertices = std::move(prepared.vertices);
    result.tin.triangles = std::move(triangles);
    detail::finish_counters(result, pred, prepared.duplicates, peak);
    progress.report(1.0, "triangulated");
    return result;
}

}  // namespace dtm::methods
