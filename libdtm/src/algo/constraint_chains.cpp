// SPDX-License-Identifier: MIT
// Constrained edges joined into polylines: an adjacency list per vertex (CSR), then walks from
// every vertex of degree other than two, then the rings that are left.
#include "dtm/algo/constraint_chains.hpp"

#include <algorithm>
#include <cstdint>

namespace dtm {

std::vector<ConstraintChain> constraint_chains(const Tin& tin, ConstraintKind kind) {
    std::vector<std::uint32_t> edges;  // indices into tin.constraints
    for (std::uint32_t i = 0; i < tin.constraints.size(); ++i) {
        if (tin.constraints[i].kind == kind) edges.push_back(i);
    }
    const std::size_t n = tin.vertices.size();
    std::vector<std::uint32_t> first(n + 1, 0);
    for (std::uint32_t e : edges) {
        ++first[tin.constraints[e].a + 1];
        ++first[tin.constraints[e].b + 1];
    }
    for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    std::vector<std::uint32_t> incident(first[n]);
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::uint32_t k = 0; k < edges.size(); ++k) {
        incident[fill[tin.constraints[edges[k]].a]++] = k;
        incident[fill[tin.constraints[edges[k]].b]++] = k;
    }
    std::vector<bool> used(edges.size(), false);
    const auto degree = [&](VertexIndex v) { return first[v + 1] - first[v]; };
    const auto other = [&](std::uint32_t k, VertexIndex v) {
        const ConstrainedEdge& c = tin.constraints[edges[k]];
        return c.a == v ? c.b : c.a;
    };
    const auto unused_edge = [&](VertexIndex v) -> std::int64_t {
        for (std::uint32_t i = first[v]; i < first[v + 1]; ++i) {
            if (!used[incident[i]]) return incident[i];
        }
        return -1;
    };
    const auto walk = [&](VertexIndex start, std::uint32_t k, bool ring) {
        ConstraintChain chain;
        chain.closed = ring;
        chain.vertices.push_back(start);
        VertexIndex at = start;
        for (;;) {
            used[k] = true;
            at = other(k, at);
            if (ring && at == start) break;
            chain.vertices.push_back(at);
            if (!ring && degree(at) != 2) break;
            const std::int64_t next = unused_edge(at);
            if (next < 0) break;
            k = static_cast<std::uint32_t>(next);
        }
        return chain;
    };
    std::vector<ConstraintChain> chains;
    for (VertexIndex v = 0; v < n; ++v) {
        if (degree(v) == 0 || degree(v) == 2) continue;
        for (std::int64_t k = unused_edge(v); k >= 0; k = unused_edge(v)) {
            chains.push_back(walk(v, static_cast<std::uint32_t>(k), false));
        }
    }
    for (std::uint32_t k = 0; k < edges.size(); ++k) {
        if (!used[k]) chains.push_back(walk(tin.constraints[edges[k]].a, k, true));
    }
    return chains;
}

void chain_edges(const std::vector<VertexIndex>& vertices,
                 bool closed,
                 ConstraintKind kind,
                 std::vector<ConstrainedEdge>& out) {
    const std::size_t n = vertices.size();
    const std::size_t count = closed && n > 2 ? n : (n > 0 ? n - 1 : 0);
    for (std::size_t i = 0; i < count; ++i) {
        const VertexIndex a = vertices[i];
        const VertexIndex b = vertices[(i + 1) % n];
        if (a == b) continue;
        out.push_back({std::min(a, b), std::max(a, b), kind});
    }
}

}  // namespace dtm
