// SPDX-License-Identifier: MIT
/// @file
/// @brief A QGIS project (.qgs, XML) that opens the products of `dtm build` ready to look at:
/// the DEM in a terrain colour ramp multiplied over its hillshade, contours labelled by
/// elevation with index contours emphasised, the TIN as a mesh layer (2DM through MDAL), and a
/// cut/fill map when the build compared the surface with a base.
#pragma once

#include <filesystem>
#include <string>

#include "dtm/core/point.hpp"

namespace dtm::io {

/// What the project shows. Relative paths are relative to the project file's folder and are
/// written with a leading "./", the form QGIS resolves against the project folder.
struct QgisProject {
    std::string title = "dtm";
    std::string crs_wkt;  ///< CRS of every layer and of the project; empty: left unknown
    Box2 extent;          ///< initial map extent (the data extent; a margin is added)
    double z_min = 0.0;   ///< range of the DEM colour ramp
    double z_max = 1.0;

    std::filesystem::path dem;        ///< GeoTIFF DEM (gdal provider); empty: no layer
    std::filesystem::path hillshade;  ///< GeoTIFF hillshade (gdal) drawn beneath the DEM
    std::filesystem::path contours;   ///< GeoPackage or shapefile (ogr provider)
    std::string contour_layer;        ///< layer inside a GeoPackage; empty for a shapefile
    std::string elevation_field = "elevation";
    /// Boolean (or 0/1) field that is true on index contours (ContourWriter writes `index`). Empty: index contours are recognised from
    /// their elevation, a multiple of index_interval.
    std::string index_field;
    double index_interval = 5.0;
    std::filesystem::path mesh;  ///< 2DM TIN (mdal provider)
    /// GeoPackage of a volume comparison (`dtm build --base`): layer cut_fill (polygons with a
    /// `kind` of "cut" or "fill", drawn red and blue) and layer zero_lines. Empty: no layers.
    std::filesystem::path cut_fill;
    bool mesh_visible = false;   ///< the wireframe starts hidden: it hides the DEM at small scales
};

/// The project as QGIS 3 XML (`<qgis>` with projectCrs, layer-tree-group, mapcanvas,
/// projectlayers/maplayer, layerorder and properties).
/// @throws Error if crs_wkt is set but cannot be interpreted.
[[nodiscard]] std::string qgis_project_xml(const QgisProject& project);

/// Writes qgis_project_xml(project) to exactly @p path (the caller provides atomicity).
/// @throws Error if the file cannot be written.
void write_qgis_project(const QgisProject& project, const std::filesystem::path& path);

}  // namespace dtm::io
