// SPDX-License-Identifier: MIT
// What a TIN read from a file must be before libdtm uses it (found by fuzz/ply_fuzz and
// fuzz/mesh_2dm_fuzz): faces counter-clockwise and not degenerate (exact orient2d), constrained
// edges that are edges of the TIN. Called by the PLY and 2DM readers after link_neighbours(),
// which already refuses edges used twice in one direction.
#pragma once

#include <filesystem>

#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io::detail {

/// @throws InputError (without a file: the reader adds it) naming the first bad face or edge.
void check_tin_from_file(const Tin& tin);

/// A reader table entry for a file that is a TIN (the PLY, the tiled TIN): refuses line and ring
/// roles, reads it with @p load and gives the TIN with its vertices as points and its CRS.
/// @p format names it in the summary.
[[nodiscard]] ReadResult read_tin_input(const InputFile& file,
                                        const Progress& progress,
                                        const char* format,
                                        LoadedTin (*load)(const std::filesystem::path&));

}  // namespace dtm::io::detail
