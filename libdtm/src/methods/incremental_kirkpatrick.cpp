// SPDX-License-Identifier: MIT
// [incremental-kirkpatrick] Incremental Delaunay insertion (thesis 000 §3.8, the winged-edge
// structure of detail/winged_edge.hpp) with Kirkpatrick's hierarchy for point location
// (§3.8.2; Kirkpatrick 1983, detail/kirkpatrick.hpp).
//
// Kirkpatrick's hierarchy is static: it is built over a fixed triangulation. The thesis
// mentions building it bottom-up during the insertion and judges that impractical (flips
// change the lowest level). Here it is rebuilt over the current triangulation (T_pom
// included, which is exactly Kirkpatrick's enclosing triangle) each time the number of
// inserted points doubles, while the points inserted so far are at most half the input, so
// the last hierarchy is built over at most n/2 points. A point is located in the hierarchy
// (O(log n)), which gives a triangle of that snapshot; the walk in the current triangulation
// starts at one of its corners, a vertex that still exists, and crosses the few triangles made
// since the snapshot. Insertion order: BRIO (Amenta, Choi, Rote 2003; detail/spatial_order.hpp):
// random rounds of doubling size, each in Hilbert order; the hierarchy is rebuilt at the start
// of each round but the last (n/2^j points in, j >= 2), so the snapshot is a random sample of
// a half (a quarter in the last round) of the points and its triangles hold O(1) later points
// on average, as with a plain random order, while
// consecutive queries descend nearby paths of the hierarchy. Each rebuild is linear, so all
// of them cost O(n); the queries O(n log n) in total. Until 64 points are in, the walk alone
// is used.
#include "incremental_kirkpatrick.hpp"

#include <utility>

#include "methods/detail/kirkpatrick.hpp"
#include "methods/detail/method_support.hpp"
#include "methods/detail/spatial_order.hpp"
#include "methods/detail/winged_edge.hpp"

namespace dtm::methods {

MethodResult run_incremental_kirkpatrick(const MethodInput& input,
                                         const MethodOptions& options,
                                         const Progress& progress) {
    detail::ParamReader params("incremental-kirkpatrick", options);
    params.finish();
    detail::CountingPredicates pred;
    detail::PreparedPoints prepared =
        detail::prepare_points("incremental-kirkpatrick", input, pred);
    const std::vector<VertexIndex> order = detail::brio_order(prepared.vertices, options.seed);
    // Vertex k = the k-th inserted (detail::to_insertion_order): same coordinates, same
    // decisions, nearby memory for nearby points.
    detail::to_insertion_order(prepared.vertices, order);
    std::vector<Point3>& pts = prepared.vertices;
    const std::size_t n = pts.size();
    // The starts of the BRIO rounds, n >> j (brio_order halves the range each round), all but
    // the last: a hierarchy over half the points would not fit the memory budget; the last
    // round walks from the snapshot of a quarter.
    std::vector<std::size_t> rebuild_at;
    for (std::size_t b = n / 4; b >= 64; b /= 2) rebuild_at.push_back(b);
    MethodResult result;
    std::size_t peak = 0;
    {
        detail::WingedEdgeDelaunay we(pts, pred);
        detail::KirkpatrickHierarchy hierarchy;
        std::uint64_t hierarchy_steps = 0;
        std::uint64_t rebuilds = 0;
        for (std::size_t k = 0; k < n; ++k) {
            if ((k & 4095) == 0) {
                progress.report(static_cast<double>(k) / static_cast<double>(n), "inserting");
            }
            if (!rebuild_at.empty() && k == rebuild_at.back()) {
                rebuild_at.pop_back();
                std::vector<detail::KirkpatrickHierarchy::Corners> snapshot(we.triangles().size());
                for (TriangleIndex t = 0; t < snapshot.size(); ++t) snapshot[t] = we.corners(t);
                hierarchy.build(std::move(snapshot), n + 3, we.super());
                peak = std::max(peak, we.bytes() + hierarchy.bytes() + detail::bytes_of(pts) +
                                          detail::bytes_of(order));
                ++rebuilds;
            }
            const auto p = static_cast<VertexIndex>(k);
            detail::EdgeIndex start = detail::no_edge;
            if (!hierarchy.empty()) {
                const auto corners = hierarchy.locate(p, we.super(), hierarchy_steps);
                start = we.edge_of(corners[0]);
            }
            result.counters.walk_steps += we.insert(p, start);
        }
        result.counters.extra["hierarchy_steps"] = hierarchy_steps;
        result.counters.extra["rebuilds"] = rebuilds;
        result.counters.extra["levels"] = hierarchy.levels();
        result.counters.extra["hierarchy_nodes"] = hierarchy.nodes();
        result.counters.extra["max_children"] = hierarchy.max_children();
        const std::size_t inserting =
            we.bytes() + hierarchy.bytes() + detail::bytes_of(pts) + detail::bytes_of(order);
        detail::free_storage(hierarchy);
        peak = std::max(peak, we.bytes() + we.release_extra_bytes() + detail::bytes_of(pts) +
                                  detail::bytes_of(order));
        result.counters.flips = we.flips();
        result.tin.triangles = we.release_triangles();  // after the edges are freed: less
        peak = std::max(peak, inserting);
    }
    detail::to_input_numbering(result.tin.triangles, pts, order);
    result.tin.vertices = std::move(pts);
    detail::finish_counters(result, pred, prepared.duplicates, peak);
    progress.report(1.0, "triangulated");
    return result;
}

}  // namespace dtm::methods
