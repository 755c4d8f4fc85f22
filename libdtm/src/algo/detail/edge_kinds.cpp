// SPDX-License-Identifier: MIT
// Triangle edge kinds from the TIN's constraint list: the constraints are bucketed by their
// smaller vertex (a CSR array), so each triangle edge looks through the few constraints of its
// smaller vertex.
#include "algo/detail/edge_kinds.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>

namespace dtm::detail {

TriangleEdgeKinds triangle_edge_kinds(const Tin& tin) {
    TriangleEdgeKinds kinds(tin.triangles.size(), {plain_edge, plain_edge, plain_edge});
    if (tin.constraints.empty()) {
        return kinds;
    }
    const std::size_t n = tin.vertices.size();
    std::vector<std::uint32_t> offsets(n + 1, 0);
    for (const ConstrainedEdge& c : tin.constraints) {
        ++offsets[std::min(c.a, c.b) + 1];
    }
    for (std::size_t v = 0; v < n; ++v) {
        offsets[v + 1] += offsets[v];
    }
    std::vector<std::pair<VertexIndex, std::uint8_t>> others(tin.constraints.size());
    std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for (const ConstrainedEdge& c : tin.constraints) {
        others[fill[std::min(c.a, c.b)]++] = {std::max(c.a, c.b), edge_kind_of(c.kind)};
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tin.triangles.size(), 1 << 14),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t t = range.begin(); t != range.end(); ++t) {
                              const Triangle& tri = tin.triangles[t];
                              for (std::size_t e = 0; e < 3; ++e) {
                                  const VertexIndex a = tri.v[(e + 1) % 3];
                                  const VertexIndex b = tri.v[(e + 2) % 3];
                                  const VertexIndex lo = std::min(a, b), hi = std::max(a, b);
                                  for (std::uint32_t k = offsets[lo]; k < offsets[lo + 1]; ++k) {
                                      if (others[k].first == hi) {
                                          // listed twice: a hard breakline wins (it creases)
                                          std::uint8_t& kind = kinds[t][e];
                                          kind = is_hard(kind) || is_hard(others[k].second)
                                                     ? edge_kind_of(ConstraintKind::breakline)
                                                     : std::max(kind, others[k].second);
                                      }
                                  }
                              }
                          }
                      });
    return kinds;
}

}  // namespace dtm::detail
