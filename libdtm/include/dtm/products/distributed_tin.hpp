// SPDX-License-Identifier: MIT
/// @file
/// @brief `mpirun -np P dtm tin POINTS -o tin.ply`: the TIN of a survey point list built on all
/// ranks, the single-machine PLY byte for byte (issue 18; docs/distributed.md says what is
/// covered: one text point list, exact duplicates, no breaklines yet).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/dist/comm.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::products {

/// The input of a distributed run: one survey point list and how to read and merge it.
struct DistributedSource {
    io::InputFile input;      ///< a text point list (csv, txt, xyz)
    io::ReadOptions read;     ///< columns, skip_bad_lines
    std::string default_crs;  ///< the CRS of the points (the file carries none)
    /// The output CRS (projected): each rank transforms its points one by one as the serial
    /// load does (io::PositionTransform); empty: the points' own CRS.
    std::string target_crs;
    DuplicateRule duplicates = DuplicateRule::first;
    /// Breakline, soft breakline, boundary and hole files (roles breaklines, soft_breaklines,
    /// boundary, holes), read whole by every rank.
    std::vector<io::InputFile> lines;
    double z_tolerance = TriangulateOptions{}.z_tolerance;  ///< at breakline crossings
    double max_edge = 0.0;  ///< border triangles with longer unconstrained edges peeled; 0: none
};

struct DistributedTinOptions {
    DistributedSource source;
    /// A .ply, or a .json for a tiled TIN (io/formats/tin_tiles.hpp) whatever its size.
    std::filesystem::path output;
    /// Vertices or faces beyond which a .ply output is written as a tiled TIN instead, at the
    /// same path with the extension .json (a PLY indexes 2^31 - 1; tests lower it).
    std::uint64_t ply_limit = 2147483647;
};

/// What every distributed product reports of the run and its surface.
struct DistributedCounts {
    int ranks = 1;
    std::uint64_t points = 0;     ///< input points and breakline vertices
    std::uint64_t vertices = 0;   ///< after exact duplicates merged, with those at crossings
    std::uint64_t crossings = 0;  ///< vertices added where breaklines cross
    std::uint64_t triangles = 0;  ///< of the TIN (inside the boundary, outside the holes)
    std::uint64_t removed_triangles = 0;  ///< by the boundary and holes
    std::uint64_t skipped_lines = 0;
    std::uint64_t bytes_sent = 0;  ///< by all ranks, every phase
};

struct DistributedTinResult : DistributedCounts {
    std::uint64_t band_triangles = 0;
    std::uint32_t widenings = 0;
    std::uint64_t constrained_edges = 0;
    std::filesystem::path written;   ///< the PLY or the tiled TIN's manifest
    std::vector<std::string> tiles;  ///< a tiled TIN's tiles, next to its manifest
};

/// Collective: reads the points by byte ranges, merges exact duplicates, spreads the kernel's
/// tree over the ranks, triangulates and writes the PLY (MPI-IO), as `dtm tin` does on one
/// machine for the same input and options, or the tiled TIN (asked for, or beyond ply_limit).
/// @throws InputError (the serial reader's and triangulation's messages) or Error on every rank.
DistributedTinResult distributed_tin(dist::Comm& comm,
                                     const DistributedTinOptions& options,
                                     const Progress& progress);

}  // namespace dtm::products
