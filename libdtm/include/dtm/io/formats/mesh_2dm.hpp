// SPDX-License-Identifier: MIT
/// @file
/// @brief SMS 2DM mesh (the text format QGIS opens as a mesh layer through MDAL): the TIN as
/// `MESH2D`, one `ND id x y z` line per vertex and one `E3T id n1 n2 n3 1` line per triangle,
/// all ids 1-based.
#pragma once

#include <filesystem>

#include "dtm/core/tin.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::io {

/// Writes @p tin as 2DM to exactly @p path (the caller provides atomicity: write_tin() and
/// `dtm build` write to a temporary first). Coordinates are written in the shortest form that
/// reads back to the same double. 2DM cannot carry a CRS; options.crs_wkt is ignored.
/// @throws Error if the file cannot be written.
void write_2dm(const Tin& tin, const std::filesystem::path& path, const TinWriteOptions& options);

/// Reads the ND and E3T lines of a 2DM file (other cards are skipped) into a Tin with its
/// neighbour links (link_neighbours) and no constraints (2DM has none); ids are mapped back to
/// 0-based indices.
/// @throws InputError with the line number for a malformed ND/E3T line, an unknown node id, or a
/// missing MESH2D header; naming the edge when two elements overlap.
[[nodiscard]] Tin read_2dm(const std::filesystem::path& path);

}  // namespace dtm::io
