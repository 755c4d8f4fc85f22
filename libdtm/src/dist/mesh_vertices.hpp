// SPDX-License-Identifier: MIT
/// @file
/// @brief What the writers and products of a distributed run need of the kernel's mesh beyond
/// one rank's slots: which rank holds a number, the vertex numbers of foreign positions, the
/// ghost slots of all ranks, and the triangles with their vertices' heights (docs/distributed.md).
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "dist/kernel.hpp"
#include "dtm/core/point.hpp"
#include "dtm/dist/duplicates.hpp"

namespace dtm::dist {

/// The rank of a number when ranks hold contiguous runs [lo, hi) of them in rank order (kernel
/// positions, merged vertex numbers). Collective construction (one allgatherv of two numbers).
class RunOwners {
public:
    RunOwners(Comm& comm, std::uint64_t lo, std::uint64_t hi);
    [[nodiscard]] int of(std::uint64_t number) const;

private:
    struct Run {
        std::uint64_t lo, hi;
        int rank;
    };
    std::vector<Run> runs_;
};

/// Collective: the merged vertex numbers of the foreign positions this rank's triangles name,
/// asked of the positions' owners.
[[nodiscard]] std::unordered_map<std::uint64_t, std::uint64_t> foreign_vertex_numbers(
    Comm& comm, const DistributedMesh& kernel);

/// Collective: the ghost slots of all ranks (the hull's and the unused ones), in slot order.
[[nodiscard]] std::vector<std::uint64_t> all_ghost_slots(Comm& comm, const LocalMesh& mesh);

/// A real triangle of the TIN in the Tin's conventions: corners as in the serial TIN, edge e
/// opposite corner e, bit e of `border` set when no triangle lies across edge e (the hull).
struct SurfaceTriangle {
    std::array<std::uint64_t, 3> id{};  ///< merged vertex numbers (the serial TIN's)
    std::array<Point3, 3> p{};
    std::uint32_t border = 0;
};

/// Collective: this rank's real triangles with their vertices as the merge keeps them (x, y, z
/// asked of the vertices' owners in @p merged), in slot order.
[[nodiscard]] std::vector<SurfaceTriangle> surface_triangles(Comm& comm,
                                                             const MergedShare& merged,
                                                             const DistributedMesh& kernel);

}  // namespace dtm::dist
