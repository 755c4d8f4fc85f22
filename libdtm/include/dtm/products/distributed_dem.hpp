// SPDX-License-Identifier: MIT
/// @file
/// @brief `mpirun -np P dtm grid POINTS -o dem.vrt --cell C`: the DEM of a survey point list
/// built on all ranks (R-P3 of docs/distributed.md), one GeoTIFF per rank beside a GDAL VRT
/// that mosaics them; every cell is computed by exactly one rank and equals the single-machine
/// DEM's bit for bit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "dtm/core/grid.hpp"
#include "dtm/products/distributed_tin.hpp"

namespace dtm::products {

struct DistributedDemOptions {
    DistributedSource source;
    double cell = 0.0;           ///< cell size in CRS units (> 0)
    std::optional<Box2> extent;  ///< outer edges (default: the TIN's box snapped to the cell)
    float nodata = -9999.0F;
    std::filesystem::path output;  ///< the .vrt
    /// gdaldem's derivatives of the DEM, each a .vrt over one GeoTIFF per rank beside it (the
    /// serial derivative's cells); empty: not written.
    std::filesystem::path hillshade, slope, aspect;
};

struct DistributedDemResult : DistributedCounts {
    GridSpec spec;
    std::uint64_t filled = 0;                          ///< cells with data, all tiles
    std::vector<std::filesystem::path> tiles;          ///< in row order
    std::vector<std::filesystem::path> derived_tiles;  ///< the derivatives' tiles
};

/// The tile of rank @p rank of @p ranks beside @p vrt: "<stem>-<rank>-of-<ranks>.tif".
[[nodiscard]] std::filesystem::path dem_tile_path(const std::filesystem::path& vrt,
                                                  int rank,
                                                  int ranks);

/// The outputs before any input is read (fail fast): the DEM and its derivatives given as
/// .vrt, each writable, and so rank 0's tile beside each derivative of @p ranks.
/// @throws OptionError naming the derivative's option; UsageError for an unwritable output.
void check_distributed_dem_outputs(const DistributedDemOptions& options, int ranks);

/// Collective: the distributed TIN (as distributed_tin builds it), its linear surface sampled at
/// the cell centres of the grid `dtm grid` chooses for the same options. Rank r computes and
/// writes the rows [r R / P, (r + 1) R / P) of the R rows, from the triangles whose y-extent
/// reaches them (sent by their owners); rank 0 writes the VRT once every tile is in place. The
/// derivatives asked for follow in the same row blocks. Each file is written atomically. @throws
/// InputError, UsageError or Error on every rank.
DistributedDemResult distributed_dem(dist::Comm& comm,
                                     const DistributedDemOptions& options,
                                     const Progress& progress);

}  // namespace dtm::products
