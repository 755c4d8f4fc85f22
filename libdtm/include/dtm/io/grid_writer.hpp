// SPDX-License-Identifier: MIT
/// @file
/// @brief Writing a DEM through GDAL, streamed band by band (a GridSink), atomically; and the
/// derived rasters (hillshade, slope, aspect) through GDAL's own DEM processing.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/algo/rasterize.hpp"
#include "dtm/core/grid.hpp"

namespace dtm::io {

struct GridWriteOptions {
    std::string crs_wkt;      ///< written as the raster's CRS when non-empty
    float nodata = -9999.0F;  ///< declared NoData value of the band
    /// Cloud Optimized GeoTIFF (GDAL's COG driver) instead of a plain tiled GeoTIFF; only for
    /// .tif/.tiff targets.
    bool cog = false;
};

/// A GridSink writing a Float32 raster to @p target. The format follows the extension: .tif and
/// .tiff give a tiled, DEFLATE-compressed GeoTIFF; any other extension picks the GDAL raster
/// driver that declares it (.asc: Arc/Info ASCII grid, .img, .nc, ...). Rows are written as they
/// arrive (drivers that can only copy a whole dataset get a temporary GeoTIFF first), to a
/// temporary file that commit() renames onto the target.
class GridWriter final : public GridSink {
public:
    /// @throws UsageError for an extension no GDAL raster driver writes; Error if GDAL fails.
    GridWriter(const std::filesystem::path& target,
               const GridSpec& spec,
               const GridWriteOptions& options);
    GridWriter(const GridWriter&) = delete;
    GridWriter& operator=(const GridWriter&) = delete;
    ~GridWriter() override;

    void write_rows(std::size_t first_row,
                    std::size_t row_count,
                    std::span<const float> values) override;
    /// Flushes, converts if needed, and renames onto the target. @throws Error
    void commit();

private:
    struct State;
    std::unique_ptr<State> state_;
};

/// Writes a whole in-memory grid (convenience for small rasters and samples).
void write_grid(const Grid& grid,
                const std::filesystem::path& target,
                const GridWriteOptions& options);

/// One GeoTIFF of a tiled DEM: rows [first_row, first_row + rows) of the whole raster, all its
/// columns.
struct DemTile {
    std::filesystem::path file;
    std::size_t first_row = 0;
    std::size_t rows = 0;
};

/// Writes @p target, a GDAL VRT of the raster @p spec (CRS and NoData from @p options) mosaicking
/// @p tiles at their rows (integer pixel offsets: no resampling), atomically. Tile paths are
/// written relative to the VRT when they lie beside it. @throws Error if GDAL fails or a tile
/// cannot be opened.
void write_dem_vrt(const std::filesystem::path& target,
                   const GridSpec& spec,
                   const std::vector<DemTile>& tiles,
                   const GridWriteOptions& options);

/// The surface derivatives GDAL computes from a DEM (gdaldem).
enum class DemDerivative { hillshade, slope, aspect };

/// gdaldem's name of @p kind ("hillshade", "slope", "aspect"), also the option naming its file.
[[nodiscard]] const char* dem_derivative_name(DemDerivative kind) noexcept;

/// Runs GDALDEMProcessing on the DEM file @p dem and writes @p target atomically (format by
/// extension as for GridWriter). Slope is in degrees, aspect in degrees from north; edges are
/// computed. @throws UsageError for an unknown extension; Error if GDAL fails.
void write_dem_derivative(const std::filesystem::path& dem,
                          const std::filesystem::path& target,
                          DemDerivative kind);

/// The derivative of the rows [first_row, first_row + rows) of the DEM @p dem (any GDAL raster,
/// e.g. a VRT over tiles) as the GeoTIFF @p target, atomically: the cells write_dem_derivative
/// gives those rows of the whole raster, bit for bit (the window read has one row more on each
/// side that exists). @throws Error if GDAL fails or the rows are not within the raster.
void write_dem_derivative_rows(const std::filesystem::path& dem,
                               const std::filesystem::path& target,
                               DemDerivative kind,
                               std::size_t first_row,
                               std::size_t rows);

/// As write_dem_vrt for tiles of a derivative: the band's type and NoData are the first tile's.
void write_derivative_vrt(const std::filesystem::path& target,
                          const GridSpec& spec,
                          const std::vector<DemTile>& tiles,
                          const std::string& crs_wkt);

/// Lower-case extensions (without dot) that some installed GDAL raster driver can write.
[[nodiscard]] std::vector<std::string> grid_extensions();

}  // namespace dtm::io
