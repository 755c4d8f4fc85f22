// SPDX-License-Identifier: MIT
// The `maplayer` elements of the QGIS project: DEM (gdal, singlebandpseudocolor with a terrain
// ramp, multiply blending), hillshade (gdal, singlebandgray), contours (ogr, rule-based renderer
// emphasising index contours, simple labelling on the elevation field), TIN mesh (mdal).
//
// Element and attribute names follow what QGIS 3 writes and reads: QgsMapLayer::writeLayerXml
// (id, datasource, layername, srs, provider), QgsRasterLayer::writeSymbology (pipe/rasterrenderer,
// blendMode, where 6 is QgsPainting::BlendMultiply), QgsColorRampShader (colorrampshader/item),
// QgsRuleBasedRenderer (renderer-v2 type="RuleRenderer", rules/rule, symbols/symbol/layer with
// both the 3.26+ `Option` map and the older `prop` list), QgsPalLayerSettings (labeling
// type="simple", settings/text-style fieldName, placement 3 = curved along the line, a data-defined
// Show property restricting labels to index contours) and QgsMeshRendererSettings.
#include <array>
#include <cstdio>
#include <string>

#include "qgis_project_xml.hpp"

namespace dtm::io::qgis {
namespace {

void write_extent(XmlWriter& xml, const Box2& box) {
    if (box.empty()) {
        return;
    }
    xml.open("extent");
    xml.text("xmin", number(box.xmin));
    xml.text("ymin", number(box.ymin));
    xml.text("xmax", number(box.xmax));
    xml.text("ymax", number(box.ymax));
    xml.close("extent");
}

}  // namespace

void write_layer_head(XmlWriter& xml,
                      const QgisProject& project,
                      const CrsInfo& crs,
                      std::string_view id,
                      const std::string& source,
                      std::string_view name,
                      std::string_view provider) {
    write_extent(xml, project.extent);
    xml.text("id", id);
    xml.text("datasource", source);
    xml.text("layername", name);
    xml.open("srs");
    write_spatialrefsys(xml, crs);
    xml.close("srs");
    if (provider == "ogr") {
        xml.text("provider", provider, {{"encoding", "UTF-8"}});
    } else {
        xml.text("provider", provider);
    }
    xml.open("flags");
    xml.text("Identifiable", "1");
    xml.text("Removable", "1");
    xml.text("Searchable", "1");
    xml.close("flags");
}

void open_maplayer(XmlWriter& xml, std::string_view type, std::string_view geometry) {
    xml.open("maplayer", {{"type", std::string(type)},
                          {"geometry", std::string(geometry)},
                          {"hasScaleBasedVisibilityFlag", "0"},
                          {"minScale", "1e+08"},
                          {"maxScale", "0"},
                          {"styleCategories", "AllStyleCategories"},
                          {"autoRefreshEnabled", "0"},
                          {"autoRefreshTime", "0"},
                          {"refreshOnNotifyEnabled", "0"},
                          {"labelsEnabled", type == "vector" ? "1" : "0"}});
}

namespace {

void write_min_max_origin(XmlWriter& xml) {
    xml.open("minMaxOrigin");
    xml.text("limits", "None");
    xml.text("extent", "WholeRaster");
    xml.text("statAccuracy", "Estimated");
    xml.text("cumulativeCutLower", "0.02");
    xml.text("cumulativeCutUpper", "0.98");
    xml.text("stdDevFactor", "2");
    xml.close("minMaxOrigin");
}

void write_pipe_tail(XmlWriter& xml) {
    xml.leaf("brightnesscontrast", {{"brightness", "0"}, {"contrast", "0"}, {"gamma", "1"}});
    xml.leaf("huesaturation", {{"saturation", "0"},
                               {"grayscaleMode", "0"},
                               {"colorizeOn", "0"},
                               {"colorizeRed", "255"},
                               {"colorizeGreen", "128"},
                               {"colorizeBlue", "128"},
                               {"colorizeStrength", "100"},
                               {"invertColors", "0"}});
    xml.leaf("rasterresampler", {{"maxOversampling", "2"}});
    xml.text("resamplingStage", "resamplingFilter");
}

struct RampStop {
    double at;  ///< position in [0, 1] of the z range
    std::string_view color;
};

/// A hypsometric terrain ramp: lowland green, yellow-tan, brown, near-white summits.
constexpr std::array<RampStop, 6> terrain_ramp{{{0.0, "#3b8d46"},
                                                {0.2, "#8dbb5c"},
                                                {0.45, "#e2d98f"},
                                                {0.7, "#c79a5b"},
                                                {0.88, "#9c6b4a"},
                                                {1.0, "#f4efe9"}}};

void write_color_ramp_shader(XmlWriter& xml, double z_min, double z_max) {
    xml.open("rastershader");
    xml.open("colorrampshader", {{"colorRampType", "INTERPOLATED"},
                                 {"classificationMode", "1"},
                                 {"clip", "0"},
                                 {"minimumValue", number(z_min)},
                                 {"maximumValue", number(z_max)},
                                 {"labelPrecision", "1"}});
    for (const RampStop& stop : terrain_ramp) {
        const double value = z_min + stop.at * (z_max - z_min);
        char label[32];
        std::snprintf(label, sizeof label, "%.1f m", value);
        xml.leaf("item", {{"alpha", "255"},
                          {"value", number(value)},
                          {"label", label},
                          {"color", std::string(stop.color)}});
    }
    xml.close("colorrampshader");
    xml.close("rastershader");
}

}  // namespace

void write_dem_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs) {
    const double z_min = project.z_min;
    const double z_max = project.z_max > project.z_min ? project.z_max : project.z_min + 1.0;
    open_maplayer(xml, "raster", "");
    write_layer_head(xml, project, crs, dem_id, project_path(project.dem), "DEM", "gdal");
    xml.open("noData");
    xml.leaf("noDataList", {{"bandNo", "1"}, {"useSrcNoData", "1"}});
    xml.close("noData");
    xml.open("pipe");
    xml.open("rasterrenderer", {{"type", "singlebandpseudocolor"},
                                {"band", "1"},
                                {"opacity", "1"},
                                {"alphaBand", "-1"},
                                {"classificationMin", number(z_min)},
                                {"classificationMax", number(z_max)},
                                {"nodataColor", ""}});
    xml.leaf("rasterTransparency");
    write_min_max_origin(xml);
    write_color_ramp_shader(xml, z_min, z_max);
    xml.close("rasterrenderer");
    write_pipe_tail(xml);
    xml.close("pipe");
    xml.text("blendMode", "6");  // QgsPainting::BlendMultiply: the ramp tints the hillshade
    xml.close("maplayer");
}

void write_hillshade_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs) {
    open_maplayer(xml, "raster", "");
    write_layer_head(xml, project, crs, hillshade_id, project_path(project.hillshade), "Hillshade",
                     "gdal");
    xml.open("noData");
    xml.leaf("noDataList", {{"bandNo", "1"}, {"useSrcNoData", "1"}});
    xml.close("noData");
    xml.open("pipe");
    xml.open("rasterrenderer", {{"type", "singlebandgray"},
                                {"grayBand", "1"},
                                {"gradient", "BlackToWhite"},
                                {"opacity", "1"},
                                {"alphaBand", "-1"},
                                {"nodataColor", ""}});
    xml.leaf("rasterTransparency");
    write_min_max_origin(xml);
    xml.open("contrastEnhancement");
    xml.text("minValue", "0");
    xml.text("maxValue", "255");
    xml.text("algorithm", "StretchToMinimumMaximum");
    xml.close("contrastEnhancement");
    xml.close("rasterrenderer");
    write_pipe_tail(xml);
    xml.close("pipe");
    xml.text("blendMode", "0");
    xml.close("maplayer");
}

}  // namespace dtm::io::qgis
