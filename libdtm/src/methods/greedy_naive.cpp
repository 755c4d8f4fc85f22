// SPDX-License-Identifier: MIT
// [greedy-naive] The basic greedy triangulation (thesis 000 §3.1a after Preparata and Shamos,
// "Computational Geometry: An Introduction", 1985; slides 004 Algorithm 1).
//
// All n(n-1)/2 candidate edges sorted by length (GreedyOrder: exact lengths, ties by index);
// take the shortest remaining one and add it to the triangulation (erratum 3: "to the stack" in
// the thesis) if it crosses no edge already added, else drop it; stop at 3n - 3 - h edges.
// Fixed edges (the input segments) are added before the loop and stay (R17). A candidate with a
// point inside it can never be a triangulation edge and is dropped (the thesis does not discuss
// degeneracies; an edge through a vertex counts as crossing). Crossing test: against every added
// edge, so O(n^2 log n + n^2 * n) = O(n^3) (R16).
#include "greedy_naive.hpp"

#include <algorithm>

#include "methods/detail/greedy_common.hpp"
#include "methods/detail/planar.hpp"

namespace dtm::methods {

MethodResult run_greedy_naive(const MethodInput& input,
                              const MethodOptions& options,
                              const Progress& progress) {
    detail::GreedySetup setup = detail::greedy_setup(input, options, "greedy-naive");
    const auto& p = setup.input.points;
    auto& pred = setup.pred;
    const auto n = static_cast<VertexIndex>(p.size());
    std::vector<detail::GreedyEdge> candidates;
    candidates.reserve(static_cast<std::size_t>(n) * (n - 1) / 2);
    for (VertexIndex a = 0; a < n; ++a) {
        for (VertexIndex b = a + 1; b < n; ++b) candidates.emplace_back(a, b);
    }
    std::sort(candidates.begin(), candidates.end(), detail::GreedyOrder(p, pred));
    progress.report(0.2, "greedy-naive");

    std::vector<detail::GreedyEdge> edges(setup.input.segments.begin(), setup.input.segments.end());
    std::uint64_t tested = 0;
    for (std::size_t k = 0; k < candidates.size() && edges.size() < setup.target_edges; ++k) {
        if ((k & 1023) == 0) progress.report(0.2 + 0.8 * double(k) / double(candidates.size()));
        const auto [a, b] = candidates[k];
        if (std::binary_search(setup.input.segments.begin(), setup.input.segments.end(),
                               candidates[k])) {
            continue;  // a fixed edge, already in
        }
        ++tested;
        bool ok = true;
        for (VertexIndex c = 0; c < n && ok; ++c) {
            ok = !detail::strictly_inside_segment(pred, p[a], p[b], p[c]);
        }
        for (std::size_t e = 0; e < edges.size() && ok; ++e) {
            ok = !detail::properly_cross(pred, p[a], p[b], p[edges[e].first], p[edges[e].second]);
        }
        if (ok) edges.push_back(candidates[k]);
    }
    MethodResult result = detail::greedy_result(setup, std::move(edges), "");
    result.counters.extra["candidates_tested"] = tested;
    return result;
}

}  // namespace dtm::methods
