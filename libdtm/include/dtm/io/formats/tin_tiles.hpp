// SPDX-License-Identifier: MIT
/// @file
/// @brief A tiled TIN (issue 18, R-P2 of docs/distributed.md): what a distributed run writes
/// when one PLY cannot hold the TIN (2^31 - 1 vertices or faces) or when asked to (`-o NAME.json`).
/// A JSON manifest ("format": "dtm-tin-tiles") lists one dtm PLY per rank next to it; each tile
/// holds its rank's triangles in the order of the whole TIN, with every vertex they name and
/// every vertex of the rank, and a `vertex_id` element giving each vertex's number in the whole
/// TIN. The manifest gives, per tile, the runs of whole-TIN face numbers its faces fill, so the
/// tiles put together are the single-machine TIN: the same vertices, faces and constrained edges
/// in the same order. Layout in docs/formats.md. Sources: src/io/formats/tin_tiles/.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {

struct TinTile {
    std::string file;  ///< the PLY's name, in the manifest's folder
    std::uint64_t vertices = 0;
    std::uint64_t faces = 0;
    std::uint64_t edges = 0;                              ///< constrained edges
    std::vector<std::array<std::uint64_t, 2>> face_runs;  ///< {first face, count}, ascending
    std::array<double, 4> extent{};                       ///< min x, min y, max x, max y
};

struct TinTilesManifest {
    std::string crs_wkt;
    std::uint64_t vertices = 0;
    std::uint64_t faces = 0;
    std::uint64_t edges = 0;
    std::vector<TinTile> tiles;
};

/// The manifest as JSON text.
[[nodiscard]] std::string tin_manifest_json(const TinTilesManifest& manifest);

/// Parses a manifest. @throws InputError naming @p path and what is missing or wrong.
[[nodiscard]] TinTilesManifest parse_tin_manifest(const std::filesystem::path& path,
                                                  std::string_view text);

/// The manifest at @p path, or nothing if it is not a tiled TIN's manifest (absent, unreadable,
/// another JSON file).
[[nodiscard]] std::vector<std::string> tin_manifest_tiles(const std::filesystem::path& path);

/// The tiles of a run: NAME.TOKEN.R-of-P.ply next to manifest NAME.json; @p token tells runs
/// apart, so a new run's tiles never overwrite the tiles the old manifest lists.
[[nodiscard]] std::string tin_tile_name(const std::filesystem::path& manifest,
                                        std::string_view token,
                                        int rank,
                                        int ranks);

/// A new run token (time and process id, 8 hex digits) for tin_tile_name().
[[nodiscard]] std::string new_tile_token();

/// Writes @p manifest at @p path atomically (temporary, then renamed: the one step that switches
/// from an old tiled TIN to the new one, whose tiles must already be in place), then removes the
/// tiles of the manifest it replaced that the new one does not list. @throws Error on failure.
void commit_tin_manifest(const std::filesystem::path& path, const TinTilesManifest& manifest);

/// Writes @p tin as a tiled TIN of one tile (the single-machine `dtm tin -o NAME.json`).
void write_tin_tiles(const Tin& tin,
                     const std::filesystem::path& path,
                     const TinWriteOptions& options);

/// The whole TIN of a tiled TIN, put together in one process (vertices by number, faces by
/// number, constrained edges sorted), neighbour links rebuilt. @throws InputError naming the
/// manifest or the tile and what is wrong (a tile missing, a vertex in no tile, two tiles
/// disagreeing on a vertex, counts that do not add up, more than one process can index).
[[nodiscard]] LoadedTin read_tin_tiles(const std::filesystem::path& manifest);

/// True when @p head is a tiled TIN's manifest (JSON naming "dtm-tin-tiles" near its start).
[[nodiscard]] bool is_tin_manifest(const FileHead& head);

/// The reader table's entry, as read_ply for one PLY.
[[nodiscard]] ReadResult read_tin_tiles_input(const InputFile& file,
                                              const ReadOptions& options,
                                              const Progress& progress = {});

}  // namespace dtm::io
