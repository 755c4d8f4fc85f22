// SPDX-License-Identifier: MIT
/// @file
/// @brief Loading every input of a job (points, breaklines, boundaries, holes, TINs) into one
/// TerrainInput in one planar CRS, with a summary of what each reader found. The readers sit
/// behind the reader table (reader.hpp, src/io/reader.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {

/// How the inputs are put into one CRS.
struct CrsOptions {
    /// CRS of inputs that carry none (EPSG:xxxx, WKT, PROJ); empty: they carry none.
    std::string default_crs;
    /// Reproject everything into this CRS (it must be projected). Empty: the first input's CRS;
    /// a geographic one is replaced by the UTM zone of the data.
    std::string target_crs;
};

struct LoadOptions {
    std::vector<InputFile> files;
    ReadOptions read;
    CrsOptions crs;
    /// Without `target_crs`: the output is this UTM zone, chosen from data read elsewhere (a
    /// distributed run's points), geographic inputs projected to it as when chosen here.
    std::optional<UtmZone> utm_zone;
};

/// terrain.points[first, last) are the cells of the raster input summaries[summary].
struct DemCells {
    std::size_t first = 0;
    std::size_t last = 0;
    std::size_t summary = 0;
};

struct LoadedInputs {
    /// Every input merged, in one CRS. Line vertices given without a height keep NaN z
    /// (triangulate() gives them one: algo/line_heights.hpp).
    TerrainInput terrain;
    PointLabels labels;      ///< point ids and codes (text point lists)
    std::string crs_wkt;     ///< CRS of terrain (after any projection); empty if unknown
    std::optional<Tin> tin;  ///< the first TIN a reader returned, in the same CRS
    std::vector<InputSummary> summaries;
    std::size_t skipped_lines = 0;
    /// The raster DEM cells among terrain.points, one range per raster input, in order
    /// (products::surface clips and thins them: DemReduceOptions).
    std::vector<DemCells> dem_cells;
};

/// @throws InputError (file, line, column, what was expected); OptionError for a CRS that GDAL
/// does not know or a geographic target CRS; Cancelled.
[[nodiscard]] LoadedInputs load_inputs(const LoadOptions& options, const Progress& progress = {});

}  // namespace dtm::io
