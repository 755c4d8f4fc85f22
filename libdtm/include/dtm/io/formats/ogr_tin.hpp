// SPDX-License-Identifier: MIT
/// @file
/// @brief TIN triangles as PolygonZ features in an OGR vector file (GeoPackage or shapefile).
#pragma once

#include <filesystem>

#include "dtm/core/tin.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::io {

/// Writes one PolygonZ feature per triangle (closed ring of its three vertices, counter-clockwise)
/// to exactly @p path, with the CRS of options.crs_wkt (none if empty). The driver follows the
/// extension: `.gpkg` GeoPackage (layer `tin`), `.shp` ESRI Shapefile (with .prj). Attributes:
/// `id` (0-based triangle index), `z_min`, `z_max`, `slope_deg` (steepest slope of the plane).
/// The caller provides atomicity; an existing file at @p path is replaced.
/// @throws UsageError for another extension; Error if GDAL fails.
void write_ogr_tin(const Tin& tin,
                   const std::filesystem::path& path,
                   const TinWriteOptions& options);

}  // namespace dtm::io
