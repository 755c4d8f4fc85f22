// SPDX-License-Identifier: MIT
// What a TIN read from a file must be before libdtm uses it (found by fuzz/ply_fuzz and
// fuzz/mesh_2dm_fuzz): faces counter-clockwise and not degenerate (exact orient2d), constrained
// edges that are edges of the TIN. Called by the PLY and 2DM readers after link_neighbours(),
// which already refuses edges used twice in one direction.
#pragma once

#include "dtm/core/tin.hpp"

namespace dtm::io::detail {

/// @throws InputError (without a file: the reader adds it) naming the first bad face or edge.
void check_tin_from_file(const Tin& tin);

}  // namespace dtm::io::detail
