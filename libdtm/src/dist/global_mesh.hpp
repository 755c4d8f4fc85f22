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

/// One rank's part of the global mesh: slots [first_slot, first_slot + tris.size()), its own
/// vertices [first_vertex, first_vertex + own_points.size()) and the coordinates of the other
/// ranks' vertices its triangles name.
struct LocalMesh {
    std::uint64_t first_slot = 0;
    std::vector<GlobalTriangle> tris;
    std::uint64_t first_vertex = 0;
    std::vector<XY> own_points;
    std::unordered_map<std::uint64_t, XY> foreign_points;

    [[nodiscard]] bool owns(std::uint64_t slot) const noexcept {
        return slot >= first_slot && slot - first_slot < tris.size();
    }
    [[nodiscard]] GlobalTriangle& at(std::uint64_t slot) { return tris[slot - first_slot]; }
    [[nodiscard]] const GlobalTriangle& at(std::uint64_t slot) const {
        return tris[slot - first_slot];
    }
    [[nodiscard]] XY point(std::uint64_t v) const {
        if (v >= first_vertex && v - first_vertex < own_points.size()) {
            return own_points[v - first_vertex];
        }
        return foreign_points.at(v);
    }
    /// Keeps @p p as the coordinates of vertex @p v if it is another rank's.
    void learn_point(std::uint64_t v, XY p) {
        if (v < first_vertex || v - first_vertex >= own_points.size()) foreign_points.emplace(v, p);
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
