// SPDX-License-Identifier: MIT
// Constrained edges to polylines: per kind, an adjacency list of the edges; lines start at every
// vertex whose degree is not two (walking each unused edge until a vertex of degree other than
// two), then the edges left over form cycles, walked into closed rings.
#include "dtm/algo/constraint_lines.hpp"

#include <algorithm>
#include <cstdint>

namespace dtm {
namespace {

struct Adjacency {
    std::vector<std::uint32_t> first;  ///< per vertex: offset into edges (CSR)
    std::vector<std::uint32_t> edges;  ///< edge ids
};

void chain_kind(const Tin& tin, ConstraintKind kind, std::vector<ConstraintLine>& out) {
    std::vector<std::uint32_t> ids;
    for (std::uint32_t e = 0; e < tin.constraints.size(); ++e) {
        if (tin.constraints[e].kind == kind) ids.push_back(e);
    }
    if (ids.empty()) return;
    const std::size_t n = tin.vertices.size();
    Adjacency adj;
    adj.first.assign(n + 1, 0);
    for (const std::uint32_t e : ids) {
        ++adj.first[tin.constraints[e].a + 1];
        ++adj.first[tin.constraints[e].b + 1];
    }
    for (std::size_t v = 0; v < n; ++v) adj.first[v + 1] += adj.first[v];
    adj.edges.resize(adj.first[n]);
    std::vector<std::uint32_t> fill(adj.first.begin(), adj.first.end() - 1);
    for (const std::uint32_t e : ids) {
        adj.edges[fill[tin.constraints[e].a]++] = e;
        adj.edges[fill[tin.constraints[e].b]++] = e;
    }
    const auto degree = [&](VertexIndex v) { return adj.first[v + 1] - adj.first[v]; };
    std::vector<std::uint8_t> used(tin.constraints.size(), 0);
    const auto walk = [&](VertexIndex start, std::uint32_t edge) {
        ConstraintLine line;
        line.kind = kind;
        line.points.push_back(tin.vertices[start]);
        VertexIndex v = start;
        for (;;) {
            used[edge] = 1;
            const ConstrainedEdge& c = tin.constraints[edge];
            v = c.a == v ? c.b : c.a;
            line.points.push_back(tin.vertices[v]);
            if (v == start || degree(v) != 2) break;
            std::uint32_t next = edge;
            for (std::uint32_t k = adj.first[v]; k < adj.first[v + 1]; ++k) {
                if (used[adj.edges[k]] == 0) next = adj.edges[k];
            }
            if (next == edge) break;
            edge = next;
        }
        line.closed = v == start && line.points.size() > 2;
        out.push_back(std::move(line));
    };
    for (VertexIndex v = 0; v < n; ++v) {
        if (degree(v) == 0 || degree(v) == 2) continue;
        for (std::uint32_t k = adj.first[v]; k < adj.first[v + 1]; ++k) {
            if (used[adj.edges[k]] == 0) walk(v, adj.edges[k]);
        }
    }
    for (VertexIndex v = 0; v < n; ++v) {  // what is left are cycles through degree-2 vertices
        for (std::uint32_t k = adj.first[v]; k < adj.first[v + 1]; ++k) {
            if (used[adj.edges[k]] == 0) walk(v, adj.edges[k]);
        }
    }
}

}  // namespace

std::vector<ConstraintLine> constraint_lines(const Tin& tin) {
    std::vector<ConstraintLine> out;
    for (const ConstraintKind kind : {ConstraintKind::breakline, ConstraintKind::soft_breakline,
                                      ConstraintKind::boundary, ConstraintKind::hole}) {
        chain_kind(tin, kind, out);
    }
    return out;
}

}  // namespace dtm
