// SPDX-License-Identifier: MIT
/// @file
/// @brief A triangle array with neighbour links (Tin's Triangle layout) and the edge flip,
/// shared by the flip-based methods (lawson-flip, randomized-dag).
#pragma once

#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm::methods::detail {

[[nodiscard]] constexpr int next3(int i) noexcept { return i == 2 ? 0 : i + 1; }
[[nodiscard]] constexpr int prev3(int i) noexcept { return i == 0 ? 2 : i - 1; }

/// Triangles as in Tin: corners counter-clockwise, n[i] across the edge opposite v[i].
struct TriMesh {
    std::vector<Triangle> tri;

    [[nodiscard]] Triangle& operator[](TriangleIndex t) { return tri[t]; }
    [[nodiscard]] const Triangle& operator[](TriangleIndex t) const { return tri[t]; }

    /// The corner of @p u opposite the edge it shares with @p t.
    [[nodiscard]] int link_back(TriangleIndex u, TriangleIndex t) const noexcept {
        const Triangle& x = tri[u];
        return x.n[0] == t ? 0 : (x.n[1] == t ? 1 : 2);
    }

    /// In @p u (if any), the link to @p from now goes to @p to.
    void relink(TriangleIndex u, TriangleIndex from, TriangleIndex to) noexcept {
        if (u == no_triangle) return;
        Triangle& x = tri[u];
        for (TriangleIndex& n : x.n) {
            if (n == from) {
                n = to;
                return;
            }
        }
    }

    /// Flips the edge opposite corner @p i of @p t (t = (a, b, c), a = v[i], neighbour u =
    /// (c, b, d) across b-c). Afterwards t = (a, b, d) and u = (a, d, c): the new edge a-d is
    /// t's edge 1 and u's edge 2; the four outer edges are t's 0 (b-d) and 2 (a-b), u's 0 (d-c)
    /// and 1 (c-a). Returns u.
    TriangleIndex flip(TriangleIndex t, int i) noexcept {
        Triangle& x = tri[t];
        const TriangleIndex u = x.n[static_cast<std::size_t>(i)];
        Triangle& y = tri[u];
        const int j = link_back(u, t);
        const VertexIndex a = x.v[static_cast<std::size_t>(i)];
        const VertexIndex b = x.v[static_cast<std::size_t>(next3(i))];
        const VertexIndex c = x.v[static_cast<std::size_t>(prev3(i))];
        const VertexIndex d = y.v[static_cast<std::size_t>(j)];
        const TriangleIndex nb_ca = x.n[static_cast<std::size_t>(next3(i))];
        const TriangleIndex nb_ab = x.n[static_cast<std::size_t>(prev3(i))];
        const TriangleIndex nb_bd = y.n[static_cast<std::size_t>(next3(j))];
        const TriangleIndex nb_dc = y.n[static_cast<std::size_t>(prev3(j))];
        x.v = {a, b, d};
        x.n = {nb_bd, u, nb_ab};
        y.v = {a, d, c};
        y.n = {nb_dc, nb_ca, t};
        relink(nb_bd, u, t);
        relink(nb_ca, t, u);
        return u;
    }
};

}  // namespace dtm::methods::detail
