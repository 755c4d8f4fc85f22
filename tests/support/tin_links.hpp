// SPDX-License-Identifier: MIT
/// @file
/// @brief Test helper: neighbour links of a hand-built Tin, rebuilt from its triangles.
#pragma once

#include <cstdint>
#include <map>
#include <utility>

#include "dtm/core/tin.hpp"

namespace dtm::test {

/// Rebuilds the neighbour links of @p tin from its triangles (shared edges in opposite directions).
inline void link_neighbours(dtm::Tin& tin) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, int>> edges;
    for (std::uint32_t t = 0; t < tin.triangles.size(); ++t) {
        dtm::Triangle& tri = tin.triangles[t];
        tri.n = {dtm::no_triangle, dtm::no_triangle, dtm::no_triangle};
        for (int e = 0; e < 3; ++e) {
            const auto a = tri.v[static_cast<std::size_t>((e + 1) % 3)];
            const auto b = tri.v[static_cast<std::size_t>((e + 2) % 3)];
            const auto it = edges.find({b, a});
            if (it != edges.end()) {
                tri.n[static_cast<std::size_t>(e)] = it->second.first;
                tin.triangles[it->second.first].n[static_cast<std::size_t>(it->second.second)] = t;
            } else {
                edges[{a, b}] = {t, e};
            }
        }
    }
}

}  // namespace dtm::test
