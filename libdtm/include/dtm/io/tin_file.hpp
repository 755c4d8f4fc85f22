// SPDX-License-Identifier: MIT
/// @file
/// @brief Writing a Tin to a file chosen by extension, atomically: the table of TIN writers is in
/// src/io/tin_file.cpp (.ply formats/ply.hpp, .2dm, .vtp, .gpkg, .shp). Reading TINs goes
/// through the reader table (reader.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm::io {

struct TinWriteOptions {
    std::string crs_wkt;  ///< written where the format can carry it (PLY: a `comment crs` line)
    bool ascii = false;   ///< PLY: text instead of binary little endian
    /// PLY: each vertex's number in the whole TIN, as a `vertex_id` element after the edges
    /// (a tile of a tiled TIN, formats/tin_tiles.hpp); empty: none.
    std::span<const std::uint64_t> vertex_ids = {};
};

/// Writes @p tin to @p path, choosing the format by extension; atomically (temporary file, then
/// rename), so a failure never leaves a partial file or clobbers an existing one.
/// @throws UsageError for an unknown extension (the message lists the known ones); Error on I/O.
void write_tin(const Tin& tin, const std::filesystem::path& path, const TinWriteOptions& options);

/// Extensions write_tin() knows, lower case without the dot.
[[nodiscard]] std::vector<std::string_view> tin_extensions();

}  // namespace dtm::io
