// SPDX-License-Identifier: MIT
/// @file
/// @brief `dtm voronoi`: Thiessen polygons of survey points, clipped to a boundary (with holes)
/// or to the points' convex hull, written through OGR with each point's id, index and height.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/io/inputs.hpp"

namespace dtm::products {

struct VoronoiCellsOptions {
    unsigned threads = 0;           ///< for the triangulation and the clipping (0: all cores)
    std::string layer = "voronoi";  ///< layer name (GeoPackage, GeoJSON)
};

struct VoronoiCellsReport {
    std::size_t points = 0;       ///< survey points read
    std::size_t duplicates = 0;   ///< points at the xy of an earlier one (one cell: the first's)
    std::size_t cells = 0;        ///< features written
    std::size_t empty_cells = 0;  ///< points whose region misses the clip region
    double region_area = 0.0;
    double cells_area = 0.0;  ///< sum of the cells' areas (equals region_area up to rounding)
    bool boundary = false;    ///< clipped to the given boundary (else to the convex hull)
};

/// Thiessen polygons of @p inputs' points into @p output (format by extension, atomically):
/// one MultiPolygon feature per point with fields id (the reader's point id, or the index when
/// it has none), index (0-based position among the input points), z, area; in the inputs' CRS.
/// @throws UsageError for breaklines among the inputs or an unknown extension; InputError for
///   collinear points without a boundary, or no point; Error when the file cannot be written.
VoronoiCellsReport write_voronoi_cells(const io::LoadedInputs& inputs,
                                       const std::filesystem::path& output,
                                       const VoronoiCellsOptions& options,
                                       const Progress& progress = {});

}  // namespace dtm::products
