// SPDX-License-Identifier: MIT
/// @file
/// @brief What the three greedy triangulations share (thesis 000 §3.1, slides 004): the input
/// checks, the one total order of candidate edges, the edge count that ends the loop, and the
/// result with its total edge length against the Delaunay (constrained) triangulation's.
#pragma once

#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "dtm/methods/method.hpp"
#include "methods/detail/counting_predicates.hpp"
#include "methods/detail/point_set.hpp"

namespace dtm::methods::detail {

using GreedyEdge = std::pair<VertexIndex, VertexIndex>;  ///< first < second

/// The order in which every greedy variant considers candidate edges: shorter first (exact
/// comparison of squared lengths), equal lengths by (smaller index, larger index). A strict total
/// order, so the greedy triangulation is unique and the variants can be compared edge for edge.
class GreedyOrder {
public:
    GreedyOrder(std::span<const Point3> points, CountingPredicates& pred)
        : p_(points), pred_(pred) {}
    [[nodiscard]] bool operator()(const GreedyEdge& e, const GreedyEdge& f) const {
        if (e == f) return false;
        const int c = pred_.compare_distances(p_[e.first], p_[e.second], p_[f.first], p_[f.second]);
        return c != 0 ? c < 0 : e < f;
    }

private:
    std::span<const Point3> p_;
    CountingPredicates& pred_;
};

struct GreedySetup {
    PreparedInput input;
    std::size_t target_edges = 0;  ///< 3n - 3 - h: a full triangulation of the hull
    CountingPredicates pred;
};

/// Prepares the input (distinct points, non-crossing segments) and the target edge count.
/// @throws UsageError for any parameter, InputError for fewer than 3 or collinear points.
[[nodiscard]] GreedySetup greedy_setup(const MethodInput& input,
                                       const MethodOptions& options,
                                       std::string_view method);

/// The Tin of the accepted edges with counters and stats ("edges", "total_length",
/// "delaunay_total_length", "length_ratio"). @p extra_json: more members, or empty.
[[nodiscard]] MethodResult greedy_result(GreedySetup& setup,
                                         std::vector<GreedyEdge> edges,
                                         std::string extra_json);

}  // namespace dtm::methods::detail
