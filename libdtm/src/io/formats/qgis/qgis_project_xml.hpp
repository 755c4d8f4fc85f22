// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal to the QGIS project writer: a minimal indenting XML builder and the layer
/// element writers shared by qgis_project.cpp and qgis_project_layers.cpp.
#pragma once

#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "dtm/io/formats/qgis_project.hpp"

namespace dtm::io::qgis {

using Attributes = std::initializer_list<std::pair<std::string_view, std::string>>;

/// Builds indented XML text; escapes attribute values and text.
class XmlWriter {
public:
    void open(std::string_view name, Attributes attributes = {});
    void close(std::string_view name);
    void leaf(std::string_view name, Attributes attributes = {});
    void text(std::string_view name, std::string_view value, Attributes attributes = {});
    /// Appends a QGIS `<Option type="QString" name=... value=.../>` entry.
    void option(std::string_view name, std::string value);
    [[nodiscard]] const std::string& str() const noexcept { return out_; }
    void raw(std::string_view text) { out_ += text; }

private:
    void start_tag(std::string_view name, Attributes attributes);
    std::string out_;
    int depth_ = 0;
};

[[nodiscard]] std::string escape(std::string_view text);
[[nodiscard]] std::string number(double value);

/// The CRS as QGIS describes it: written inside `<srs>`, `<projectCrs>` and `<destinationsrs>`.
struct CrsInfo {
    std::string wkt;  ///< WKT2, preferred by QGIS when reading
    std::string proj;
    std::string authid;  ///< "EPSG:5514" when identifiable
    std::string srid;
    std::string description;
    std::string projection_acronym;
    std::string ellipsoid_acronym;
    bool geographic = false;
};

[[nodiscard]] CrsInfo describe_crs(const std::string& crs_wkt);
void write_spatialrefsys(XmlWriter& xml, const CrsInfo& crs);

/// Stable ids of the layers.
inline constexpr std::string_view dem_id = "dtm_dem_layer";
inline constexpr std::string_view hillshade_id = "dtm_hillshade_layer";
inline constexpr std::string_view contours_id = "dtm_contours_layer";
inline constexpr std::string_view mesh_id = "dtm_tin_mesh_layer";
inline constexpr std::string_view contour_labels_id = "dtm_contour_labels_layer";
inline constexpr std::string_view spot_heights_id = "dtm_spot_heights_layer";
inline constexpr std::string_view cut_fill_id = "dtm_cut_fill_layer";
inline constexpr std::string_view zero_lines_id = "dtm_zero_lines_layer";

/// A layer path as QGIS reads it: a relative path gets a leading "./" (QgsPathResolver resolves
/// only "./" and "../" paths against the project folder; a bare name would be taken relative to
/// the working directory of QGIS).
[[nodiscard]] std::string project_path(const std::filesystem::path& path);

/// The `datasource` of the contour layer ("file|layername=x" for a GeoPackage).
[[nodiscard]] std::string contours_source(const QgisProject& project);

/// Opens a `maplayer` element (closed by the caller) and writes the children every layer starts
/// with: extent, id, datasource, layername, srs, provider, flags.
void open_maplayer(XmlWriter& xml, std::string_view type, std::string_view geometry);
void write_layer_head(XmlWriter& xml,
                      const QgisProject& project,
                      const CrsInfo& crs,
                      std::string_view id,
                      const std::string& source,
                      std::string_view name,
                      std::string_view provider);

/// A symbol layer's properties, written both as the Option map (QGIS >= 3.26) and as the prop
/// list older 3.x read; they say the same.
void write_symbol_properties(XmlWriter& xml,
                             std::span<const std::pair<std::string_view, std::string>> props);

/// The `<Layouts>` element with the project's print layout (qgis_project_layout.cpp).
void write_layouts(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs);

void write_dem_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs);
void write_hillshade_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs);
void write_contours_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs);
void write_mesh_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs);
/// A layer of placed labels in the contour GeoPackage (qgis_label_layers.cpp).
void write_label_layer(XmlWriter& xml,
                       const QgisProject& project,
                       const CrsInfo& crs,
                       LabelLayer kind);
void write_cut_fill_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs);
void write_zero_lines_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs);
/// The `datasource` of a layer of the cut/fill GeoPackage.
[[nodiscard]] std::string cut_fill_source(const QgisProject& project, std::string_view layer);

}  // namespace dtm::io::qgis
