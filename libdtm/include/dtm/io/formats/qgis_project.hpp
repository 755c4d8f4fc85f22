// SPDX-License-Identifier: MIT
/// @file
/// @brief A QGIS project (.qgs, XML) that opens the products of `dtm build` ready to look at:
/// the DEM in a terrain colour ramp multiplied over its hillshade, contours labelled by
/// elevation with index contours emphasised, the TIN as a mesh layer (2DM through MDAL), and a
/// cut/fill map when the build compared the surface with a base.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm::io {

/// A print layout (QGIS "Layout" item) of one map sheet: the page, a map item at the sheet's
/// extent and scale with grid crosses, and the furniture (title block, legend, scale bar, north
/// arrow) where the dtm map sheet has it, so QGIS users can edit and print the same sheet.
/// Rectangles are x, y, width, height in mm from the page's top-left corner.
struct QgisLayout {
    std::string name = "Map sheet";
    double width_mm = 420.0;
    double height_mm = 297.0;
    Box2 extent;                 ///< the map item's extent (CRS units): the whole page
    double scale = 500.0;        ///< 1 : scale
    double grid_interval = 0.0;  ///< grid crosses every this many CRS units (0: no grid)
    bool sjtsk = false;          ///< grid labels as positive S-JTSK Y, X (Y = -E, X = -N)
    std::string title;
    std::vector<std::pair<std::string, std::string>> fields;  ///< title block rows
    std::array<double, 4> title_box{};
    std::array<double, 4> legend_box{};
    std::array<double, 4> scale_bar_box{};
    std::array<double, 4> north_box{};
};

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
    /// Boolean (or 0/1) field that is true on index contours (ContourWriter writes `index`). Empty:
    /// index contours are recognised from their elevation, a multiple of index_interval.
    std::string index_field;
    double index_interval = 5.0;
    /// Layers of the contour GeoPackage with dtm's placed labels (ContourWriter::add_annotation):
    /// point layers of contour numbers and of spot heights; empty: none. With contour labels the
    /// contour layer is not labelled by QGIS itself.
    std::string contour_label_layer;
    std::string spot_layer;
    double label_height = 1.0;   ///< text height of those labels, CRS units
    std::filesystem::path mesh;  ///< 2DM TIN (mdal provider)
    /// GeoPackage of a volume comparison (`dtm build --base`): layer cut_fill (polygons with a
    /// `kind` of "cut" or "fill", drawn red and blue) and layer zero_lines. Empty: no layers.
    std::filesystem::path cut_fill;
    bool mesh_visible = false;  ///< the wireframe starts hidden: it hides the DEM at small scales
    std::optional<QgisLayout> layout;  ///< a print layout of the map sheet
};

/// The point layers of placed labels (ContourWriter::add_annotation).
enum class LabelLayer { contour_labels, spot_heights };

/// The QML style of such a layer (the GeoPackage's default style, layer_styles): contour numbers
/// rotated by the field `angle` (degrees counter-clockwise) from the field `text`; spot heights
/// as a dot with `label` centred at (`label_x`, `label_y`). Text @p text_height in map units.
[[nodiscard]] std::string label_layer_qml(LabelLayer kind, double text_height);

/// The project as QGIS 3 XML (`<qgis>` with projectCrs, layer-tree-group, mapcanvas,
/// projectlayers/maplayer, layerorder and properties).
/// @throws Error if crs_wkt is set but cannot be interpreted.
[[nodiscard]] std::string qgis_project_xml(const QgisProject& project);

/// Writes qgis_project_xml(project) to exactly @p path (the caller provides atomicity).
/// @throws Error if the file cannot be written.
void write_qgis_project(const QgisProject& project, const std::filesystem::path& path);

}  // namespace dtm::io
