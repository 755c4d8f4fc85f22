// SPDX-License-Identifier: MIT
// The cut/fill `maplayer` elements of the QGIS project: the cut_fill polygons categorised by their
// `kind` (fill blue, cut red, half transparent over the DEM) and the zero lines in black (see
// qgis_project_layers.cpp for the format references).
#include <string>

#include "qgis_project_xml.hpp"

namespace dtm::io::qgis {
namespace {

void write_fill_symbol(XmlWriter& xml,
                       std::string_view name,
                       const std::string& color,
                       const std::string& outline) {
    xml.open("symbol", {{"type", "fill"},
                        {"name", std::string(name)},
                        {"alpha", "0.55"},
                        {"clip_to_extent", "1"},
                        {"force_rhr", "0"}});
    xml.open("layer", {{"class", "SimpleFill"}, {"enabled", "1"}, {"locked", "0"}, {"pass", "0"}});
    const std::pair<std::string_view, std::string> props[] = {
        {"color", color},         {"joinstyle", "bevel"},       {"offset", "0,0"},
        {"offset_unit", "MM"},    {"outline_color", outline},   {"outline_style", "solid"},
        {"outline_width", "0.2"}, {"outline_width_unit", "MM"}, {"style", "solid"}};
    write_symbol_properties(xml, props);
    xml.close("layer");
    xml.close("symbol");
}

void write_zero_symbol(XmlWriter& xml) {
    xml.open("symbol", {{"type", "line"},
                        {"name", "0"},
                        {"alpha", "1"},
                        {"clip_to_extent", "1"},
                        {"force_rhr", "0"}});
    xml.open("layer", {{"class", "SimpleLine"}, {"enabled", "1"}, {"locked", "0"}, {"pass", "0"}});
    const std::pair<std::string_view, std::string> props[] = {
        {"line_color", "0,0,0,255"}, {"line_style", "solid"}, {"line_width", "0.35"},
        {"line_width_unit", "MM"},   {"capstyle", "round"},   {"joinstyle", "round"}};
    write_symbol_properties(xml, props);
    xml.close("layer");
    xml.close("symbol");
}

}  // namespace

std::string cut_fill_source(const QgisProject& project, std::string_view layer) {
    return project_path(project.cut_fill) + "|layername=" + std::string(layer);
}

void write_cut_fill_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs) {
    open_maplayer(xml, "vector", "Polygon");
    write_layer_head(xml, project, crs, cut_fill_id, cut_fill_source(project, "cut_fill"),
                     "Cut and fill", "ogr");
    xml.open("renderer-v2", {{"type", "categorizedSymbol"},
                             {"attr", "kind"},
                             {"symbollevels", "0"},
                             {"enableorderby", "0"},
                             {"forceraster", "0"}});
    xml.open("categories");
    xml.leaf("category", {{"render", "true"},
                          {"symbol", "0"},
                          {"value", "fill"},
                          {"label", "Fill (top above base)"}});
    xml.leaf(
        "category",
        {{"render", "true"}, {"symbol", "1"}, {"value", "cut"}, {"label", "Cut (top below base)"}});
    xml.close("categories");
    xml.open("symbols");
    write_fill_symbol(xml, "0", "33,102,172,255", "8,48,107,255");
    write_fill_symbol(xml, "1", "214,47,39,255", "103,0,13,255");
    xml.close("symbols");
    xml.close("renderer-v2");
    xml.text("blendMode", "0");
    xml.text("featureBlendMode", "0");
    xml.text("layerOpacity", "1");
    xml.close("maplayer");
}

void write_zero_lines_layer(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs) {
    open_maplayer(xml, "vector", "Line");
    write_layer_head(xml, project, crs, zero_lines_id, cut_fill_source(project, "zero_lines"),
                     "Zero lines", "ogr");
    xml.open("renderer-v2", {{"type", "singleSymbol"},
                             {"symbollevels", "0"},
                             {"enableorderby", "0"},
                             {"forceraster", "0"}});
    xml.open("symbols");
    write_zero_symbol(xml);
    xml.close("symbols");
    xml.close("renderer-v2");
    xml.text("blendMode", "0");
    xml.text("featureBlendMode", "0");
    xml.text("layerOpacity", "1");
    xml.close("maplayer");
}

}  // namespace dtm::io::qgis
