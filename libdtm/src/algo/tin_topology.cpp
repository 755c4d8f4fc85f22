// SPDX-License-Identifier: MIT
// Border rings of a TIN (neighbour links: dtm::link_neighbours in core/tin.hpp): each border
// edge a -> b (triangle on its left) is followed at b by the border edge leaving b that comes
// first clockwise from the direction b -> a (the one that bounds the same wedge of the surface),
// which keeps rings apart where the border touches itself at a vertex.
#include "dtm/algo/tin_topology.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace dtm {

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
