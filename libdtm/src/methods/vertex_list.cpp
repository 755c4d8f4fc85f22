// SPDX-License-Identifier: MIT
// The thesis' vertex list and its four queries (dtm/methods/vertex_list.hpp; 000 §3.10.7).
#include "dtm/methods/vertex_list.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace dtm::methods {
namespace {

bool same_triangle(const VertexTriangle& a, const VertexTriangle& b) {
    for (int r = 0; r < 3; ++r) {
        if (a[0] == b[static_cast<std::size_t>(r)] &&
            a[1] == b[static_cast<std::size_t>((r + 1) % 3)] &&
            a[2] == b[static_cast<std::size_t>((r + 2) % 3)]) {
            return true;
        }
    }
    return false;
}

}  // namespace

VertexList make_vertex_list(const std::vector<std::vector<VertexIndex>>& lists,
                            const std::vector<bool>& hull) {
    VertexList out;
    out.offset.push_back(0);
    for (std::size_t v = 0; v < lists.size(); ++v) {
        out.around.insert(out.around.end(), lists[v].begin(), lists[v].end());
        out.offset.push_back(static_cast<std::uint32_t>(out.around.size()));
        out.hull.push_back(v < hull.size() && hull[v] ? 1 : 0);
    }
    return out;
}

VertexList vertex_list_of(const Tin& tin) {
    const std::size_t nv = tin.vertices.size();
    // One triangle per vertex, a boundary one when there is one: the walk then starts at the
    // hull predecessor.
    std::vector<TriangleIndex> start(nv, no_triangle);
    std::vector<int> corner(nv, 0);
    for (TriangleIndex t = 0; t < tin.triangles.size(); ++t) {
        const Triangle& x = tin.triangles[t];
        for (int i = 0; i < 3; ++i) {
            const VertexIndex v = x.v[static_cast<std::size_t>(i)];
            // Triangle (v, a, b) ccw: clockwise around v the list reads b then a; with no
            // neighbour across (b, v), the edge opposite a, b is v's hull predecessor.
            const bool first = x.n[static_cast<std::size_t>((i + 1) % 3)] == no_triangle;
            if (start[v] == no_triangle || first) {
                start[v] = t;
                corner[v] = i;
            }
        }
    }
    std::vector<std::vector<VertexIndex>> lists(nv);
    std::vector<bool> hull(nv, false);
    for (VertexIndex v = 0; v < nv; ++v) {
        TriangleIndex t = start[v];
        if (t == no_triangle) continue;
        int i = corner[v];
        hull[v] = tin.triangles[t].n[static_cast<std::size_t>((i + 1) % 3)] == no_triangle;
        // Clockwise: from (v, a, b) to the triangle across (v, a), i.e. opposite b.
        const TriangleIndex first = t;
        lists[v].push_back(tin.triangles[t].v[static_cast<std::size_t>((i + 2) % 3)]);
        for (;;) {
            const Triangle& x = tin.triangles[t];
            lists[v].push_back(x.v[static_cast<std::size_t>((i + 1) % 3)]);
            const TriangleIndex u = x.n[static_cast<std::size_t>((i + 2) % 3)];
            if (u == no_triangle || u == first) break;
            t = u;
            const auto& w = tin.triangles[t].v;
            i = w[0] == v ? 0 : (w[1] == v ? 1 : 2);
        }
        if (!hull[v]) lists[v].pop_back();  // cyclic: the start came round again
    }
    return make_vertex_list(lists, hull);
}

std::vector<VertexTriangle> triangles_at_vertex(const VertexList& list, VertexIndex v) {
    const auto l = list.neighbours(v);
    std::vector<VertexTriangle> out;
    const std::size_t m = l.size();
    const std::size_t pairs = list.is_hull(v) ? (m > 0 ? m - 1 : 0) : m;
    for (std::size_t i = 0; i < pairs; ++i) out.push_back({v, l[i], l[(i + 1) % m]});
    return out;
}

std::vector<VertexTriangle> triangles_on_edge(const VertexList& list,
                                              VertexIndex a,
                                              VertexIndex b) {
    std::vector<VertexTriangle> out;
    auto from = [&](VertexIndex u, VertexIndex w) {
        const auto l = list.neighbours(u);
        const std::size_t m = l.size();
        for (std::size_t i = 0; i < m; ++i) {
            if (l[i] != w) continue;
            if (i + 1 < m) {
                out.push_back({u, w, l[i + 1]});
            } else if (!list.is_hull(u)) {
                out.push_back({u, w, l[0]});
            }
        }
    };
    from(a, b);
    from(b, a);
    if (out.size() == 2 && same_triangle(out[0], out[1])) out.pop_back();
    return out;
}

std::vector<std::pair<VertexIndex, VertexIndex>> edges_at_vertex(const VertexList& list,
                                                                 VertexIndex v) {
    std::vector<std::pair<VertexIndex, VertexIndex>> out;
    for (const VertexIndex w : list.neighbours(v)) out.emplace_back(v, w);
    return out;
}

std::vector<VertexTriangle> neighbours_of_triangle(const VertexList& list,
                                                   const VertexTriangle& t) {
    std::vector<VertexTriangle> out;
    for (int k = 0; k < 3; ++k) {
        for (const VertexTriangle& u : triangles_on_edge(
                 list, t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)])) {
            if (!same_triangle(u, t)) out.push_back(u);
        }
    }
    return out;
}

std::vector<VertexIndex> hull_cycle(const VertexList& list, VertexIndex from) {
    std::vector<VertexIndex> out;
    VertexIndex v = from;
    do {
        if (!list.is_hull(v) || list.neighbours(v).empty()) {
            throw std::invalid_argument("hull_cycle: not a hull vertex");
        }
        out.push_back(v);
        v = list.neighbours(v).back();
    } while (v != from && out.size() <= list.vertex_count());
    return out;
}

}  // namespace dtm::methods
