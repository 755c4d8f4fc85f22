// SPDX-License-Identifier: MIT
/// @file
/// @brief OGR polygon-face writer (GeoPackage, shapefile): one PolygonZ feature per face.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::io {

/// Writes @p faces to exactly @p path (no temporary; write_polygon_faces adds atomicity);
/// @p ext is "gpkg" or "shp". Fields: id, corners (the vertex count), z_min, z_max.
void write_ogr_faces(std::span<const Point3> vertices,
                     const std::vector<std::vector<VertexIndex>>& faces,
                     const std::filesystem::path& path,
                     const std::string& crs_wkt,
                     std::string_view ext);

}  // namespace dtm::io
