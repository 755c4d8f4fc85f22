// SPDX-License-Identifier: MIT
/// @file
/// @brief dtm's own lossless TIN file: PLY with vertices, faces, constrained edges and the CRS
/// (layout in docs/formats.md). Sources: src/io/formats/ply/ (ply_writer.cpp, ply_reader.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/reader.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::io {

/// Writes @p tin as a dtm PLY file to exactly @p path (no temporary; write_tin() adds atomicity).
/// Binary little endian unless options.ascii.
/// @throws Error if the file cannot be written or the TIN refers to missing vertices.
void write_tin_ply(const Tin& tin,
                   const std::filesystem::path& path,
                   const TinWriteOptions& options);

/// The header write_tin_ply() writes for a TIN of these element counts (also the distributed
/// writer's, src/io/formats/ply/ply_dist_writer.hpp).
[[nodiscard]] std::string ply_header(std::size_t vertices,
                                     std::size_t faces,
                                     std::size_t edges,
                                     const TinWriteOptions& options);

struct LoadedTin {
    Tin tin;
    std::string crs_wkt;
    /// A tile's vertex_id element: each vertex's number in the whole TIN; empty in a plain TIN.
    std::vector<std::uint64_t> vertex_ids;
};

/// Reads a PLY TIN written by dtm (binary or ASCII): vertices, faces and constrained edges.
/// Neighbour links are rebuilt. @throws InputError naming the file and what was wrong.
[[nodiscard]] LoadedTin read_tin_ply(const std::filesystem::path& path);

/// The reader table's entry: the TIN (ReadResult::tin), its vertices as points, its CRS.
/// @throws InputError as read_tin_ply(), or if the file is not given as survey input (a TIN
/// cannot be a breakline or a boundary).
[[nodiscard]] ReadResult read_ply(const InputFile& file,
                                  const ReadOptions& options,
                                  const Progress& progress = {});

}  // namespace dtm::io
