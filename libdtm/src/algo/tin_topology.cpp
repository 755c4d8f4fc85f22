// SPDX-License-Identifier: MIT
// Neighbour links and border rings of a TIN given as faces.
//
// Links: directed edge i of triangle t runs v[i+1] -> v[i+2] (opposite v[i]); every directed edge
// is listed (counting sort) under the smaller of its two vertices, so an edge and its twin land in
// the same short row and are matched there, O(n) overall.
// Border rings: each border edge a -> b (triangle on its left) is followed at b by the border edge
// leaving b that comes first clockwise from the direction b -> a (the one that bounds the same
// wedge of the surface), which keeps rings apart where the border touches itself at a vertex.
#include "dtm/algo/tin_topology.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace dtm {

std::string link_neighbours(Tin& tin) {
    const std::size_t n = tin.vertices.size();
    struct Listed {
        VertexIndex other;   ///< the larger vertex of the edge
        std::uint32_t edge;  ///< 3 t + i
        bool forward;        ///< the edge runs from the row's vertex to `other`
    };
    std::vector<std::uint32_t> first(n + 1, 0);
    for (Triangle& t : tin.triangles) {
        t.n = {no_triangle, no_triangle, no_triangle};
        for (std::size_t i = 0; i < 3; ++i) {
            ++first[std::min(t.v[(i + 1) % 3], t.v[(i + 2) % 3]) + 1];
        }
    }
    for (std::size_t v = 0; v < n; ++v) {
        first[v + 1] += first[v];
    }
    std::vector<Listed> rows(first[n]);
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        const auto& v = tin.triangles[t].v;
        for (std::size_t i = 0; i < 3; ++i) {
            const VertexIndex a = v[(i + 1) % 3];
            const VertexIndex b = v[(i + 2) % 3];
            rows[fill[std::min(a, b)]++] = {std::max(a, b), static_cast<std::uint32_t>(3 * t + i),
                                            a < b};
        }
    }
    std::string problem;
    for (std::size_t a = 0; a < n; ++a) {
        for (std::uint32_t k = first[a]; k < first[a + 1]; ++k) {
            for (std::uint32_t j = k + 1; j < first[a + 1]; ++j) {
                if (rows[j].other != rows[k].other) {
                    continue;
                }
                if (rows[j].forward == rows[k].forward) {
                    if (problem.empty()) {
                        problem = "edge " + std::to_string(a) + "-" +
                                  std::to_string(rows[k].other) +
                                  " is used twice in the same direction";
                    }
                    continue;
                }
                tin.triangles[rows[k].edge / 3].n[rows[k].edge % 3] = rows[j].edge / 3;
                tin.triangles[rows[j].edge / 3].n[rows[j].edge % 3] = rows[k].edge / 3;
            }
        }
    }
    return problem;
}

std::vector<std::vector<VertexIndex>> border_rings(const Tin& tin) {
    // Border edges a -> b, listed by a.
    struct Edge {
        VertexIndex a;
        VertexIndex b;
    };
    std::vector<Edge> edges;
    for (const Triangle& t : tin.triangles) {
        for (std::size_t i = 0; i < 3; ++i) {
            if (t.n[i] == no_triangle) {
                edges.push_back({t.v[(i + 1) % 3], t.v[(i + 2) % 3]});
            }
        }
    }
    std::sort(edges.begin(), edges.end(),
              [](const Edge& x, const Edge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    std::vector<bool> used(edges.size(), false);
    const auto leaving = [&](VertexIndex v) {
        const auto lo = std::lower_bound(edges.begin(), edges.end(), v,
                                         [](const Edge& e, VertexIndex x) { return e.a < x; });
        std::size_t i = static_cast<std::size_t>(lo - edges.begin());
        std::size_t j = i;
        while (j < edges.size() && edges[j].a == v) {
            ++j;
        }
        return std::pair{i, j};
    };
    const auto angle = [&](VertexIndex from, VertexIndex to) {
        const Point3& p = tin.vertices[from];
        const Point3& q = tin.vertices[to];
        return std::atan2(q.y - p.y, q.x - p.x);
    };
    std::vector<std::vector<VertexIndex>> rings;
    for (std::size_t start = 0; start < edges.size(); ++start) {
        if (used[start]) {
            continue;
        }
        std::vector<VertexIndex> ring;
        std::size_t e = start;
        while (!used[e]) {
            used[e] = true;
            ring.push_back(edges[e].a);
            const VertexIndex b = edges[e].b;
            const auto [lo, hi] = leaving(b);
            std::size_t best = edges.size();
            if (hi - lo == 1) {
                best = lo;
            } else {
                // First clockwise from b -> a: the smallest clockwise turn.
                const double back = angle(b, edges[e].a);
                double best_turn = 10.0;
                for (std::size_t k = lo; k < hi; ++k) {
                    if (used[k]) {
                        continue;
                    }
                    double turn = back - angle(b, edges[k].b);
                    while (turn <= 0.0) {
                        turn += 2.0 * 3.14159265358979323846;
                    }
                    if (turn < best_turn) {
                        best_turn = turn;
                        best = k;
                    }
                }
            }
            if (best == edges.size()) {
                break;
            }
            e = best;
        }
        if (ring.size() >= 3) {
            rings.push_back(std::move(ring));
        }
    }
    return rings;
}

}  // namespace dtm
