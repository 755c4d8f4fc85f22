// SPDX-License-Identifier: MIT
/// @file
/// @brief `dtm grid`'s job on one machine: a TIN's surface sampled at cell centres into a DEM
/// raster, and GDAL's hillshade, slope or aspect of it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dtm/algo/interpolation.hpp"
#include "dtm/core/grid.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/grid_writer.hpp"

namespace dtm::products {

struct DemOptions {
    double cell = 0.0;           ///< cell size in CRS units (> 0)
    std::optional<Box2> extent;  ///< outer edges (default: the TIN's box snapped to the cell)
    float nodata = -9999.0F;     ///< value of cells off the TIN, outside the boundary, in holes
    bool cog = false;            ///< Cloud Optimized GeoTIFF (.tif targets only)
    Interpolation interpolation = Interpolation::linear;
    unsigned threads = 0;  ///< 0: all
    /// The cubic surface creases along hard breaklines (off for a TIN of contour lines, whose
    /// lines are not edges of the ground).
    bool crease_at_breaklines = true;
    std::filesystem::path hillshade, slope, aspect;  ///< derived rasters; empty: not written
};

struct DemResult {
    GridSpec spec;
    std::uint64_t filled = 0;  ///< cells that received a value
};

/// Any DEM dtm writes, on one machine or many, has at most 2^36 cells (256 GiB of Float32).
/// @throws OptionError (`cell`) beyond that.
void check_dem_size(const GridSpec& spec);

/// A derived raster asked for: its file and its kind (io::dem_derivative_name names the option).
struct DemDerivativeFile {
    std::filesystem::path file;
    io::DemDerivative kind;
};

/// The derived rasters asked for: the non-empty of @p hillshade, @p slope, @p aspect, in order.
[[nodiscard]] std::vector<DemDerivativeFile> dem_derivatives(const std::filesystem::path& hillshade,
                                                             const std::filesystem::path& slope,
                                                             const std::filesystem::path& aspect);

/// The grid of a DEM: the cells of @p extent, or @p tin_box snapped outwards to the cell size.
/// @throws OptionError (`cell`) beyond 2^36 cells.
[[nodiscard]] GridSpec dem_grid_spec(const Box2& tin_box,
                                     double cell,
                                     const std::optional<Box2>& extent);

/// The outputs and option combinations, before any input is read (fail fast).
/// @throws UsageError / OptionError naming the option.
void check_dem_outputs(const std::filesystem::path& output, const DemOptions& options);

/// Samples @p tin's surface (options.interpolation) at the cell centres of dem_grid_spec() into
/// @p output (the extension picks the GDAL driver; written atomically) with @p crs_wkt, then
/// the derived rasters asked for. @throws InputError for a TIN without triangles, OptionError,
/// Error when a write fails, Cancelled.
DemResult write_dem(const Tin& tin,
                    const std::string& crs_wkt,
                    const DemOptions& options,
                    const std::filesystem::path& output,
                    const Progress& progress = {});

/// The same for a TIN the caller gives up: for linear interpolation its vertices are renumbered
/// in place for the rasteriser's sweep instead of in a copy of the whole TIN (less memory and
/// time; the cells are the same).
DemResult write_dem(Tin&& tin,
                    const std::string& crs_wkt,
                    const DemOptions& options,
                    const std::filesystem::path& output,
                    const Progress& progress = {});

}  // namespace dtm::products
