// SPDX-License-Identifier: MIT
/// @file
/// @brief The distributed run's mesh: triangles addressed by global slots, vertices by global
/// kernel positions (64-bit), as the serial kernel numbers them (ghost_mesh.hpp: half-edge i of
/// slot t is (t << 2) | i, the ghost vertex is the largest id). Each rank holds the slots of
/// its leaves and the coordinates of every vertex its triangles name.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "algo/detail/ghost_mesh.hpp"

namespace dtm::dist {

inline constexpr std::uint64_t global_ghost = ~std::uint64_t{0};

struct GlobalTriangle {
    std::array<std::uint64_t, 3> v{global_ghost, global_ghost, global_ghost};
    std::array<std::uint64_t, 3> n{global_ghost, global_ghost, global_ghost};

    friend bool operator==(const GlobalTriangle&, const GlobalTriangle&) = default;
    /// An unused slot (all corners ghost) holds no triangle.
    [[nodiscard]] bool unused() const noexcept {
        return v[0] == global_ghost && v[1] == global_ghost && v[2] == global_ghost;
    }
    [[nodiscard]] bool is_ghost() const noexcept {
        return v[0] == global_ghost || v[1] == global_ghost || v[2] == global_ghost;
    }
};

struct XY {
    double x = 0.0;
    double y = 0.0;
};

/// One rank's part of the global mesh: slots [first_slot, first_slot + tris.size()) and its own
/// vertices [first_vertex, first_vertex + own_points.size()), stored as the serial kernel stores
/// them (32-bit Triangle, local numbers) so that the rank holds about as many bytes per point as
/// one machine does. A vertex number v < own count is own vertex first_vertex + v; a larger one
/// (not the ghost) is another rank's, foreign_vertices[v - own count]. A twin code below
/// foreign_edge_tag is a local half-edge; from it up (not no_half_edge) it indexes
/// foreign_edges. at() and set() translate to and from global numbers.
struct LocalMesh {
    static constexpr std::uint32_t foreign_edge_tag = 0x80000000u;

    std::uint64_t first_slot = 0;
    std::vector<Triangle> tris;
    std::uint64_t first_vertex = 0;
    std::vector<XY> own_points;
    std::vector<std::uint64_t> foreign_vertices;
    std::vector<XY> foreign_xy;
    std::unordered_map<std::uint64_t, std::uint32_t> foreign_index;
    std::vector<std::uint64_t> foreign_edges;
    /// Per slot, the ConstraintBits of its three edges (edge i runs from v[i] to v[i + 1]);
    /// empty until constraints are inserted (dist/constraints.hpp).
    std::vector<std::array<std::uint8_t, 3>> bits;
    /// Per slot, 1 when the domain (boundary, holes) removed its triangle; empty: none removed
    /// (dist/domain.hpp).
    std::vector<std::uint8_t> removed;

    /// Own slot @p s (local index) holds a triangle of the TIN: real, not removed.
    [[nodiscard]] bool kept(std::uint64_t s) const noexcept {
        return !detail::is_ghost_triangle(tris[s]) && (removed.empty() || removed[s] == 0);
    }

    [[nodiscard]] bool owns(std::uint64_t slot) const noexcept {
        return slot >= first_slot && slot - first_slot < tris.size();
    }
    [[nodiscard]] bool own_vertex(std::uint64_t v) const noexcept {
        return v >= first_vertex && v - first_vertex < own_points.size();
    }

    [[nodiscard]] GlobalTriangle at(std::uint64_t slot) const {
        const Triangle& t = tris[slot - first_slot];
        GlobalTriangle g;
        const auto own = static_cast<std::uint32_t>(own_points.size());
        for (unsigned i = 0; i < 3; ++i) {
            const std::uint32_t v = t.v[i];
            g.v[i] = v == detail::ghost ? global_ghost
                     : v < own          ? first_vertex + v
                                        : foreign_vertices[v - own];
            const std::uint32_t n = t.n[i];
            g.n[i] = n == detail::no_half_edge ? global_ghost
                     : n < foreign_edge_tag    ? n + (first_slot << 2)
                                               : foreign_edges[n - foreign_edge_tag];
        }
        return g;
    }

    /// Stores @p g at @p slot; its vertices' coordinates must be known (learn_point).
    void set(std::uint64_t slot, const GlobalTriangle& g) {
        Triangle& t = tris[slot - first_slot];
        const auto own = static_cast<std::uint32_t>(own_points.size());
        for (unsigned i = 0; i < 3; ++i) {
            const std::uint64_t v = g.v[i];
            t.v[i] = v == global_ghost ? detail::ghost
                     : own_vertex(v)   ? static_cast<std::uint32_t>(v - first_vertex)
                                       : own + foreign_index.at(v);
            const std::uint64_t n = g.n[i];
            if (n == global_ghost) {
                t.n[i] = detail::no_half_edge;
            } else if (owns(n >> 2)) {
                t.n[i] = static_cast<std::uint32_t>(n - (first_slot << 2));
            } else {
                t.n[i] = foreign_edge_tag + static_cast<std::uint32_t>(foreign_edges.size());
                foreign_edges.push_back(n);
            }
        }
    }

    /// The global position of a stored (local) vertex number.
    [[nodiscard]] std::uint64_t global_vertex(std::uint32_t v) const {
        const auto own = static_cast<std::uint32_t>(own_points.size());
        return v < own ? first_vertex + v : foreign_vertices[v - own];
    }

    [[nodiscard]] XY point(std::uint64_t v) const {
        if (own_vertex(v)) return own_points[v - first_vertex];
        return foreign_xy[foreign_index.at(v)];
    }
    /// The real triangles among the slots (the others are hull ghosts or unused).
    [[nodiscard]] std::uint64_t real_triangles() const noexcept {
        std::uint64_t n = 0;
        for (const Triangle& t : tris) n += detail::is_ghost_triangle(t) ? 0 : 1;
        return n;
    }

    /// Every slot in global numbers (tests, checks).
    [[nodiscard]] std::vector<GlobalTriangle> global_triangles() const {
        std::vector<GlobalTriangle> out;
        out.reserve(tris.size());
        for (std::uint64_t s = 0; s < tris.size(); ++s) out.push_back(at(first_slot + s));
        return out;
    }

    /// Keeps @p p as the coordinates of vertex @p v if it is another rank's.
    void learn_point(std::uint64_t v, XY p) {
        if (own_vertex(v) || foreign_index.contains(v)) return;
        foreign_index.emplace(v, static_cast<std::uint32_t>(foreign_vertices.size()));
        foreign_vertices.push_back(v);
        foreign_xy.push_back(p);
    }
};

/// A kernel triangle of a mesh whose positions start at @p first_vertex and slots at
/// @p first_slot, in global numbers.
inline GlobalTriangle to_global(const Triangle& t,
                                std::uint64_t first_vertex,
                                std::uint64_t first_slot) {
    GlobalTriangle g;
    for (unsigned i = 0; i < 3; ++i) {
        g.v[i] = t.v[i] == detail::ghost ? global_ghost : t.v[i] + first_vertex;
        g.n[i] = t.n[i] == detail::no_half_edge ? global_ghost : t.n[i] + (first_slot << 2);
    }
    return g;
}

}  // namespace dtm::dist
