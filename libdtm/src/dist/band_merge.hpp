// SPDX-License-Identifier: MIT
/// @file
/// @brief One Guibas-Stolfi merge run on a band (band_mesh.hpp): the changed slots and the
/// merged hull, or BandTooNarrow with the slot it lacked.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "dist/band_mesh.hpp"

namespace dtm::dist {

using GlobalHull = detail::GhostHull<std::uint64_t>;

struct BandMergeOutcome {
    GlobalHull hull;  ///< the merged subtree's hull handles, in the order of its frame
    /// Every slot whose content the merge changed (the spare slots among them), ascending.
    std::vector<std::pair<std::uint64_t, GlobalTriangle>> changed;
};

/// ghost_merge on a copy of @p band: A (left) before B (right) in the cut's frame, A's spare
/// slots, the handles of the result in @p frame (the parent's cut).
/// @throws BandTooNarrow when the merge or the hull walk touches a slot outside the band.
BandMergeOutcome merge_on_band(const BandMesh& band,
                               GlobalHull left,
                               GlobalHull right,
                               std::array<std::uint64_t, 2> spare,
                               int frame);

/// The slots next to the band (twins of its half-edges) that it does not hold, ascending.
std::vector<std::uint64_t> band_ring(const BandMesh& band);

}  // namespace dtm::dist
