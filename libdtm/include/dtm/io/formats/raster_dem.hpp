// SPDX-License-Identifier: MIT
/// @file
/// @brief Raster DEMs as terrain input (GeoTIFF, ESRI ASCII grid, anything GDAL reads;
/// docs/formats.md "Raster DEMs"): every cell with a value becomes a survey point at the cell
/// centre, NoData cells are skipped, the raster's CRS is kept. Source:
/// src/io/formats/raster_dem.cpp.
#pragma once

#include "dtm/core/progress.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {

/// The reader table's entry (band 1). @throws InputError naming the file if GDAL cannot open it
/// as a raster, it has no band, or its geotransform is missing.
[[nodiscard]] ReadResult read_raster_dem(const InputFile& file,
                                         const ReadOptions& options,
                                         const Progress& progress = {});

/// True for an ESRI ASCII grid (a `.asc` whose first word is ncols, nrows, xllcorner, ...),
/// which shares its extension with point text.
[[nodiscard]] bool is_ascii_grid(const FileHead& head);

}  // namespace dtm::io
