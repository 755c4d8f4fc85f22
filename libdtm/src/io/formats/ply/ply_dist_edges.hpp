// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: the constrained edges of one rank's triangles as the serial TIN lists them
/// (finish_tin: every constrained edge of a kept triangle once, from the side where a < b or from
/// its only kept triangle, with the kind of that side's bits), shared by the distributed PLY and
/// the tiled TIN writers.
#pragma once

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "algo/detail/tin_build.hpp"
#include "dist/domain.hpp"
#include "dist/global_mesh.hpp"

namespace dtm::io::detail {

struct EdgeNumbers {
    std::uint64_t a = 0;  ///< vertex numbers of the TIN, a < b
    std::uint64_t b = 0;
    std::uint8_t kind = 0;
    friend bool operator<(const EdgeNumbers& x, const EdgeNumbers& y) {
        return x.a < y.a || (x.a == y.a && x.b < y.b);
    }
};

/// Collective (when @p trimmed). This rank's share of the TIN's constrained edges, unsorted;
/// @p number maps a stored vertex to its number in the TIN, @p ghosts are every rank's ghost
/// slots (ascending), @p trimmed says a domain removed triangles.
template <class Number>
std::vector<EdgeNumbers> own_constrained_edges(dist::Comm& comm,
                                               const dist::LocalMesh& mesh,
                                               const std::vector<std::uint64_t>& ghosts,
                                               const Number& number,
                                               bool trimmed) {
    // A removed neighbour leaves the edge on the border, as a hull ghost does.
    const std::unordered_set<std::uint64_t> removed_next_door =
        trimmed ? dist::foreign_removed(comm, mesh) : std::unordered_set<std::uint64_t>{};
    const auto outside = [&](std::uint64_t slot) {
        if (std::binary_search(ghosts.begin(), ghosts.end(), slot)) return true;
        if (!trimmed) return false;
        return mesh.owns(slot) ? mesh.removed[slot - mesh.first_slot] != 0
                               : removed_next_door.contains(slot);
    };
    std::vector<EdgeNumbers> out;
    for (std::uint64_t s = 0; s < mesh.bits.size(); ++s) {
        const Triangle& t = mesh.tris[s];
        if (!mesh.kept(s)) continue;
        for (unsigned i = 0; i < 3; ++i) {
            const std::uint8_t bits = mesh.bits[s][i];
            if (bits == 0) continue;
            const std::uint64_t a = number(t.v[i]);
            const std::uint64_t c = number(t.v[(i + 1) % 3]);
            const std::uint64_t twin = mesh.at(mesh.first_slot + s).n[i] >> 2;
            if (a < c || outside(twin)) {
                out.push_back({std::min(a, c), std::max(a, c),
                               static_cast<std::uint8_t>(dtm::detail::constraint_kind_of(bits))});
            }
        }
    }
    return out;
}

}  // namespace dtm::io::detail
