// SPDX-License-Identifier: MIT
/// @file
/// @brief `mpirun -np P dtm contour POINTS -o contours.vrt --interval I`: the contour lines of
/// a survey point list's TIN traced on all ranks (R-P4 of docs/distributed.md): each rank
/// traces a range of levels into its own GeoPackage, every line whole in one file, and an OGR
/// VRT joins them into the single-machine layer, line for line and bit for bit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "dtm/algo/contour.hpp"
#include "dtm/products/distributed_tin.hpp"

namespace dtm::products {

struct DistributedContourOptions {
    DistributedSource source;
    /// Levels, index contours and smoothing as for `dtm contour`; the surface must be linear.
    ContourOptions contour;
    std::filesystem::path output;  ///< the .vrt
    std::string layer = "contours";
};

struct DistributedContourResult : DistributedCounts {
    std::uint64_t levels = 0;                   ///< levels that cut the TIN
    std::uint64_t lines = 0;                    ///< all pieces
    std::vector<std::filesystem::path> pieces;  ///< in level order
};

/// The GeoPackage of rank @p rank of @p ranks beside @p vrt: "<stem>-<rank>-of-<ranks>.gpkg".
[[nodiscard]] std::filesystem::path contour_piece_path(const std::filesystem::path& vrt,
                                                       int rank,
                                                       int ranks);

/// Collective: the distributed TIN (as distributed_tin builds it) and its contours. The levels
/// that cut it (contour_levels of the exact height range) are split into P ranges of about equal
/// numbers of crossed triangles; every triangle goes to the ranks owning a level that crosses it,
/// so each rank holds every triangle its levels cross, in the serial order, and traces them as `dtm
/// contour` does. Rank 0 writes the VRT once every piece is in place; every file is written
/// atomically.
/// @throws InputError, UsageError or Error on every rank.
DistributedContourResult distributed_contours(dist::Comm& comm,
                                              const DistributedContourOptions& options,
                                              const Progress& progress);

}  // namespace dtm::products
