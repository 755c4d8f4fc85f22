// SPDX-License-Identifier: MIT
// The contour and mesh `maplayer` elements of the QGIS project (see qgis_project_layers.cpp for
// the format references).
#include <cmath>
#include <string>

#include "qgis_project_xml.hpp"

namespace dtm::io::qgis {
namespace {

/// QGIS expression true on index contours.
std::string index_filter(const QgisProject& project) {
    if (!project.index_field.empty()) {
        return "\"" + project.index_field + "\"";  // true (or 1) on index contours
    }
    const std::string step = number(project.index_interval > 0.0 ? project.index_interval : 1.0);
    const std::string z = "\"" + project.elevation_field + "\"";
    return "abs(" + z + " / " + step + " - round(" + z + " / " + step + ")) < 0.000001";
}

void write_line_symbol(XmlWriter& xml, std::string_view name, std::string color, double width) {
    xml.open("symbol", {{"type", "line"},
                        {"name", std::string(name)},
                        {"alpha", "1"},
                        {"clip_to_extent", "1"},
                        {"force_rhr", "0"}});
    xml.open("layer", {{"class", "SimpleLine"}, {"enabled", "1"}, {"locked", "0"}, {"pass", "0"}});
    const std::pair<std::string_view, std::string> props[] = {
        {"capstyle", "round"},   {"joinstyle", "round"},        {"line_color", color},
        {"line_style", "solid"}, {"line_width", number(width)}, {"line_width_unit", "MM"},
        {"offset", "0"},         {"offset_unit", "MM"},         {"use_custom_dash", "0"}};
    write_symbol_properties(xml, props);
    xml.close("layer");
    xml.close("symbol");
}

void write_contour_renderer(XmlWriter& xml, const QgisProject& project) {
    xml.open("renderer-v2", {{"type", "RuleRenderer"},
                             {"symbollevels", "0"},
                             {"enableorderby", "0"},
                             {"forceraster", "0"}});
    xml.open("rules", {{"key", "{5f0d3c1e-0000-4000-8000-000000000001}"}});
    xml.leaf("rule", {{"key", "{5f0d3c1e-0000-4000-8000-000000000002}"},
                      {"filter", index_filter(project)},
                      {"symbol", "0"},
                      {"label", "Index contours"}});
    xml.leaf("rule", {{"key", "{5f0d3c1e-0000-4000-8000-000000000003}"},
                      {"filter", "ELSE"},
                      {"symbol", "1"},
                      {"label", "Contours"}});
    xml.close("rules");
    xml.open("symbols");
    write_line_symbol(xml, "0", "104,62,30,255", 0.5);
    write_line_symbol(xml, "1", "150,106,70,255", 0.18);
    xml.close("symbols");
    xml.close("renderer-v2");
}

/// Decimals needed to print multiples of @p step exactly (0 for whole metres).
int label_decimals(double step) {
    for (int decimals = 0; decimals < 3; ++decimals) {
        const double scaled = step * std::pow(10.0, decimals);
        if (std::fabs(scaled - std::round(scaled)) < 1e-9) {
            return decimals;
        }
    }
    return 3;
}

/// Data-defined "Show" property: only index contours get a label.
void write_show_property(XmlWriter& xml, const QgisProject& project) {
    xml.open("dd_properties");
    xml.open("Option", {{"type", "Map"}});
    xml.option("name", "");
    xml.open("Option", {{"name", "properties"}, {"type", "Map"}});
    xml.open("Option", {{"name", "Show"}, {"type", "Map"}});
    xml.leaf("Option", {{"name", "active"}, {"type", "bool"}, {"value", "true"}});
    xml.option("expression", index_filter(project));
    xml.leaf("Option", {{"name", "type"}, {"type", "int"}, {"value", "3"}});
    xml.close("Option");
    xml.close("Option");
    xml.option("type", "collection");
    xml.close("Option");
    xml.close("dd_properties");
}

void write_contour_labeling(XmlWriter& xml, const QgisProject& project) {
    xml.open("labeling", {{"type", "simple"}});
    xml.open("settings", {{"calloutType", "simple"}});
    xml.open("text-style", {{"fieldName", project.elevation_field},
                            {"isExpression", "0"},
                            {"fontFamily", "Sans Serif"},
                            {"fontSize", "8"},
                            {"fontSizeUnit", "Point"},
                            {"fontWeight", "50"},
                            {"fontItalic", "0"},
                            {"textColor", "104,62,30,255"},
                            {"textOpacity", "1"},
                            {"multilineHeight", "1"}});
    xml.leaf("text-buffer", {{"bufferDraw", "1"},
                             {"bufferSize", "0.8"},
                             {"bufferSizeUnits", "MM"},
                             {"bufferColor", "255,255,255,255"},
                             {"bufferOpacity", "0.8"},
                             {"bufferNoFill", "1"}});
    xml.close("text-style");
    const double step = project.index_interval > 0.0 ? project.index_interval : 1.0;
    xml.leaf("text-format", {{"formatNumbers", "1"},
                             {"decimals", std::to_string(label_decimals(step))},
                             {"plussign", "0"},
                             {"wrapChar", ""},
                             {"multilineAlign", "0"}});
    xml.leaf("placement", {{"placement", "3"},       // curved, following the line
                           {"placementFlags", "1"},  // on the line
                           {"repeatDistance", "80"},
                           {"repeatDistanceUnits", "MM"},
                           {"maxCurvedCharAngleIn", "25"},
                           {"maxCurvedCharAngleOut", "-25"},
                           {"priority", "5"}});
    xml.leaf("rendering", {{"drawLabels", "1"},
                           {"obstacle", "1"},
                           {"scaleVisibility", "0"},
                           {"mergeLines", "1"},
                           {"upsidedownLabels", "0"}});
    write_show_property(xml, project);
    xml.close("settings");
    xml.close("labeling");
}

}  // namespace

void write_symbol_properties(XmlWriter& xml,
                             std::span<const std::pair<std::string_view, std::string>> props) {
    xml.open("Option", {{"type", "Map"}});
    for (const auto& [key, value] : props) {
        xml.option(key, value);
    }
    xml.close("Option");
    for (const auto& [key, value] : props) {
        xml.leaf("prop", {{"k", std::string(key)}, {"v", value}});
    }
}

void write_contours_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs) {
    open_maplayer(xml, "vector", "Line");
    write_layer_head(xml, project, crs, contours_id, contours_source(project), "Contours", "ogr");
    write_contour_renderer(xml, project);
    // dtm's own placed labels are a layer of their own (qgis_label_layers.cpp)
    if (project.contour_label_layer.empty()) write_contour_labeling(xml, project);
    xml.text("blendMode", "0");
    xml.text("featureBlendMode", "0");
    xml.text("layerOpacity", "1");
    xml.close("maplayer");
}

void write_mesh_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs) {
    open_maplayer(xml, "mesh", "");
    write_layer_head(xml, project, crs, mesh_id, project_path(project.mesh), "TIN (mesh)", "mdal");
    xml.leaf("extra-datasets");
    xml.open("mesh-renderer-settings");
    xml.leaf("active-dataset-group", {{"scalar", "-1"}, {"vector", "-1"}});
    xml.leaf("mesh-settings-native", {{"enabled", "1"},
                                      {"color", "60,60,60,255"},
                                      {"line-width", "0.1"},
                                      {"line-width-unit", "MM"}});
    xml.leaf("mesh-settings-triangular", {{"enabled", "0"},
                                          {"color", "0,0,0,255"},
                                          {"line-width", "0.26"},
                                          {"line-width-unit", "MM"}});
    xml.leaf("mesh-settings-edge", {{"enabled", "0"},
                                    {"color", "0,0,0,255"},
                                    {"line-width", "0.26"},
                                    {"line-width-unit", "MM"}});
    xml.close("mesh-renderer-settings");
    xml.text("blendMode", "0");
    xml.text("layerOpacity", "1");
    xml.close("maplayer");
}

}  // namespace dtm::io::qgis
