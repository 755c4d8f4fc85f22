// SPDX-License-Identifier: MIT
/// @file
/// @brief Writing a planar subdivision into polygons (a pseudo-triangulation's faces) by
/// extension: .ply (PLY with polygon faces), .gpkg / .shp (one PolygonZ feature per face).
/// Layouts in docs/formats.md.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::io {

struct FacesWriteOptions {
    std::string crs_wkt;  ///< PLY: a `comment crs` line; OGR: the layer's CRS
    bool ascii = false;   ///< PLY: text instead of binary little endian
};

/// Writes the polygons @p faces (counter-clockwise vertex indices into @p vertices), atomically.
/// @throws UsageError for an unknown extension (the message lists the known ones); Error on I/O.
void write_polygon_faces(std::span<const Point3> vertices,
                         const std::vector<std::vector<VertexIndex>>& faces,
                         const std::filesystem::path& path,
                         const FacesWriteOptions& options);

/// Extensions write_polygon_faces() knows, lower case without the dot.
[[nodiscard]] std::vector<std::string_view> polygon_face_extensions();

/// Writes every Tin of @p tins into the folder @p dir as t001.ply, t002.ply, ... (at least three
/// digits, more when there are more files), replacing the folder's earlier t*.ply files.
void write_tin_series(std::span<const Tin> tins,
                      const std::filesystem::path& dir,
                      const std::string& crs_wkt);

}  // namespace dtm::io
