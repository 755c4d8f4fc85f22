// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: the TIN of a distributed run, the steps every distributed product starts
/// with (read by byte ranges, CRS, exact duplicates, the tree and the kernel over ranks, the
/// serial degeneracy checks).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "dist/kernel.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/dist/duplicates.hpp"
#include "dtm/products/distributed_tin.hpp"

namespace dtm::products::detail {

struct DistributedSurface {
    dist::MergedShare merged;
    dist::DistributedMesh kernel;
    std::string crs_wkt;
    std::uint64_t points = 0;         ///< input points and line vertices
    std::uint64_t line_vertices = 0;  ///< of breaklines, boundaries and holes
    std::uint64_t skipped_lines = 0;
    std::uint64_t triangles = 0;          ///< of the TIN (after the domain) over all ranks
    std::uint64_t segments = 0;           ///< breakline segments after the split
    std::uint64_t crossings = 0;          ///< vertices added where breaklines cross
    std::uint64_t removed_triangles = 0;  ///< outside the boundary or inside holes
};

/// Collective. @throws InputError (the serial reader's and triangulation's messages) or Error on
/// every rank.
DistributedSurface distributed_surface(dist::Comm& comm,
                                       const DistributedSource& source,
                                       const Progress& progress);

/// What write_tin_file() wrote.
struct TinFileWritten {
    std::filesystem::path written;   ///< the PLY or the tiled TIN's manifest
    std::vector<std::string> tiles;  ///< a tiled TIN's tiles, next to its manifest
    std::uint64_t constrained_edges = 0;
};

/// Collective: the TIN of @p surface as one PLY at @p output (MPI-IO), or as a tiled TIN when
/// @p output is a .json or the TIN has more than @p ply_limit vertices or triangles (then at
/// @p output with the extension .json).
TinFileWritten write_tin_file(dist::Comm& comm,
                              const DistributedSurface& surface,
                              const std::filesystem::path& output,
                              std::uint64_t ply_limit);

/// The counts of @p surface (bytes_sent is left to the end of the product).
[[nodiscard]] DistributedCounts counts_of(const dist::Comm& comm,
                                          const DistributedSurface& surface);

/// Collective: the exact union of every rank's box @p mine (empty when every one is).
[[nodiscard]] Box2 box_over_ranks(dist::Comm& comm, const Box2& mine);

/// Collective: runs @p step where @p here is true; an Error on any rank is then thrown on every
/// rank with the message and the kind (InputError, UsageError, Cancelled or Error: the exit
/// code) of the lowest rank that failed.
void on_ranks(dist::Comm& comm, bool here, const std::function<void()>& step);

/// Progress on the ranks that show it; a stop request is agreed on by the steps' reductions.
void report_progress(const Progress& progress, double fraction, const char* what);

/// Bytes all ranks sent in every phase so far.
[[nodiscard]] std::uint64_t bytes_sent(dist::Comm& comm);

}  // namespace dtm::products::detail
