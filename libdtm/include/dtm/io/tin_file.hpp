// SPDX-License-Identifier: MIT
/// @file
/// @brief Writing a Tin to a file chosen by extension (.ply here; other formats register in
/// src/io/tin_file.cpp), and reading a dtm PLY TIN back.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm::io {

struct TinWriteOptions {
    std::string crs_wkt;  ///< written where the format can carry it (PLY: a `comment crs` line)
    bool ascii = false;   ///< PLY: text instead of binary little endian
};

/// Writes @p tin to @p path, choosing the format by extension; atomically (temporary file, then
/// rename), so a failure never leaves a partial file or clobbers an existing one.
/// @throws UsageError for an unknown extension (the message lists the known ones); Error on I/O.
void write_tin(const Tin& tin, const std::filesystem::path& path, const TinWriteOptions& options);

/// Extensions write_tin() knows, lower case without the dot.
[[nodiscard]] std::vector<std::string_view> tin_extensions();

/// Writes @p tin as a dtm PLY file to exactly @p path (no temporary; write_tin() adds atomicity).
/// Binary little endian unless options.ascii. See docs/formats.md for the layout.
/// @throws Error if the file cannot be written or the TIN refers to missing vertices.
void write_tin_ply(const Tin& tin, const std::filesystem::path& path,
                   const TinWriteOptions& options);

struct LoadedTin {
    Tin tin;
    std::string crs_wkt;
};

/// Reads a PLY TIN written by dtm (binary or ASCII): vertices, faces and constrained edges.
/// Neighbour links are rebuilt. @throws InputError naming the file and what was wrong.
[[nodiscard]] LoadedTin read_tin_ply(const std::filesystem::path& path);

}  // namespace dtm::io
