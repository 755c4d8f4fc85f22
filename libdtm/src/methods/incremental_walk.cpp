// SPDX-License-Identifier: MIT
// [incremental-walk] Incremental Delaunay triangulation on the winged-edge structure with
// walking point location (thesis 000 §3.8 Procedure Incremental_Delaunay, §3.8.1 the
// winged-edge structure after [SKA92] and the walk "cesta"; Lawson 1977 for the swaps).
//
// Idea: an auxiliary triangle T_pom holds every point (symbolic corners, so removing it at the
// end leaves the convex hull: the thesis does not say how large T_pom must be); insert the
// points one by one: walk to the triangle containing the point, split it, swap the edges that
// fail the empty-circle test; finally drop T_pom's corners with their triangles.
// Data structure: detail/winged_edge.hpp (the thesis' three lists).
// Complexity: the thesis gives O(N^2) (the walk is O(N) in the worst case) and O(N^{1/2}) per
// walk for spatially sorted input. With the default Hilbert order and the walk starting at
// the last edge of the previous walk the walks are O(1) (measured in docs/algorithms/
// methods.md); order=random shows the O(N^{1/2}) walks, order=input takes the points as given.
#include "incremental_walk.hpp"

#include "methods/detail/method_support.hpp"
#include "methods/detail/spatial_order.hpp"
#include "methods/detail/winged_edge.hpp"

namespace dtm::methods {

MethodResult run_incremental_walk(const MethodInput& input,
                                  const MethodOptions& options,
                                  const Progress& progress) {
    detail::ParamReader params("incremental-walk", options);
    const std::string order_name =
        params.choice("order", {"hilbert", "random", "input"}, "hilbert");
    params.finish();
    detail::CountingPredicates pred;
    detail::PreparedPoints prepared = detail::prepare_points("incremental-walk", input, pred);
    const std::vector<Point3>& pts = prepared.vertices;
    std::vector<VertexIndex> order;
    if (order_name == "hilbert") {
        order = detail::hilbert_order(pts);
    } else if (order_name == "random") {
        order = detail::random_order(pts.size(), options.seed);
    } else {
        order = detail::random_order(0, 0);
        order.resize(pts.size());
        for (std::size_t i = 0; i < pts.size(); ++i) order[i] = static_cast<VertexIndex>(i);
    }
    MethodResult result;
    std::size_t peak = 0;
    {
        // The structure works on the points renumbered in insertion order (vertex k = the k-th
        // inserted), so consecutive insertions touch neighbouring memory; same coordinates,
        // same decisions. The input numbering is restored at the end.
        std::vector<Point3>& sorted = prepared.vertices;
        detail::to_insertion_order(sorted, order);
        detail::WingedEdgeDelaunay we(sorted, pred);
        for (std::size_t k = 0; k < sorted.size(); ++k) {
            if ((k & 4095) == 0) {
                progress.report(static_cast<double>(k) / static_cast<double>(sorted.size()),
                                "inserting");
            }
            result.counters.walk_steps += we.insert(static_cast<VertexIndex>(k));
        }
        // Peak: the release of the structure (WingedEdgeDelaunay::release_triangles: the links
        // beside the edges); the output is assembled after the edges are freed, in less.
        peak = we.bytes() + we.release_extra_bytes() + detail::bytes_of(sorted) +
               detail::bytes_of(order);
        result.counters.flips = we.flips();
        result.tin.triangles = we.release_triangles();
        detail::to_input_numbering(result.tin.triangles, sorted, order);
        result.tin.vertices = std::move(sorted);
    }
    detail::finish_counters(result, pred, prepared.duplicates, peak);
    progress.report(1.0, "triangulated");
    return result;
}

}  // namespace dtm::methods
