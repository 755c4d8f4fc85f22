// SPDX-License-Identifier: MIT
// [delaunay-distance] Incremental construction ("přírůstková konstrukce") by Delaunay distance
// with an active edge list (lecture 004, Alg. "Delaunay Triangulation Incremental(S, AEL, DT)";
// thesis 000 §2.4.3, the gift-wrapping class).
//
// Idea: p1 is a random point, p2 its nearest neighbour (an exact distance comparison), so
// p1p2 is a Delaunay edge. Over an oriented Delaunay edge, the point on its left with the
// smallest Delaunay distance (the signed radius of the circle through the edge and the point;
// found with incircle alone: a candidate strictly inside the current circle wins) closes a
// Delaunay triangle; if there is none the edge is a hull edge. The active edge list holds
// the edges whose left side is still open. Slide defects resolved (docs/algorithms/
// methods.md): a triangle's new edge opens only when its twin is not already active (else the
// twin closes), and the triangle joins the result; cocircular ties use detail/third_point.hpp.
// Data structure: the AEL (a hash set with a first-in-first-out queue, detail/front.hpp), the
// triangles. Complexity: O(n) per search, O(n^2) in all (004; quadratic, marked as such).
#include "delaunay_distance.hpp"

#include "methods/detail/front.hpp"
#include "methods/detail/method_support.hpp"
#include "methods/detail/spatial_order.hpp"
#include "methods/detail/third_point.hpp"

namespace dtm::methods {

MethodResult run_delaunay_distance(const MethodInput& input,
                                   const MethodOptions& options,
                                   const Progress& progress) {
    detail::ParamReader params("delaunay-distance", options);
    params.finish();
    detail::CountingPredicates pred;
    detail::PreparedPoints prepared = detail::prepare_points("delaunay-distance", input, pred);
    const std::vector<Point3>& p = prepared.vertices;
    const auto n = static_cast<VertexIndex>(p.size());

    // First edge: a random point and its nearest neighbour.
    const VertexIndex p1 = detail::random_order(n, options.seed)[0];
    VertexIndex p2 = p1 == 0 ? 1 : 0;
    for (VertexIndex q = 0; q < n; ++q) {
        if (q != p1 && pred.compare_distances(p[p1], p[q], p[p1], p[p2]) < 0) p2 = q;
    }
    detail::ThirdPoint third(p, pred);
    auto search = [&](VertexIndex a, VertexIndex b) {
        third.reset(a, b);
        for (VertexIndex q = 0; q < n; ++q) third.offer(q);
        return third.choose();
    };
    std::vector<detail::TriangleCorners> triangles;
    triangles.reserve(2 * p.size());
    detail::ActiveEdges ael;
    VertexIndex a = p1;
    VertexIndex b = p2;
    VertexIndex c = search(a, b);
    if (c == no_vertex) {  // nothing left of p1->p2: reverse it
        std::swap(a, b);
        c = search(a, b);
    }
    triangles.push_back({a, b, c});
    ael.open(b, a);
    ael.add_triangle(a, b, c);
    std::size_t peak_front = 0;
    std::uint64_t hull_edges = 0;
    detail::ActiveEdges::Edge e{};
    while (ael.take(e)) {
        if ((triangles.size() & 1023) == 0) {
            progress.report(static_cast<double>(triangles.size()) / (2.0 * static_cast<double>(n)),
                            "triangles");
        }
        c = search(e.a, e.b);
        if (c == no_vertex) {
            ++hull_edges;
            continue;
        }
        triangles.push_back({e.a, e.b, c});
        ael.add_triangle(e.a, e.b, c);
        peak_front = std::max(peak_front, ael.bytes());
    }
    MethodResult result;
    result.counters.extra["hull_edges"] = hull_edges;
    const std::size_t peak = detail::bytes_of(p) + detail::bytes_of(triangles) + peak_front +
                             triangles.size() * sizeof(Triangle);
    result.tin = detail::tin_from_triangles(std::move(prepared.vertices), triangles);
    detail::finish_counters(result, pred, prepared.duplicates, peak);
    progress.report(1.0, "triangulated");
    return result;
}

}  // namespace dtm::methods
