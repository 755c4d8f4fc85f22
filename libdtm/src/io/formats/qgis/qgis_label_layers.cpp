// SPDX-License-Identifier: MIT
// The point layers of dtm's own label placement (algo/contour_annotation.hpp) as QGIS shows
// them: contour numbers as labels over an invisible point, rotated by the data-defined
// LabelRotation (QGIS turns clockwise: -angle), and spot heights as a dot with the height at the
// placed position (PositionX/PositionY, centred: Hali/Vali). Text sizes are in map units, so the
// placement (free of overlaps in ground units) holds at every zoom (and never below 1.5 mm). The
// same XML is the QML style stored in the GeoPackage's layer_styles table (QGIS loads it as the
// layer's default style) and the layers of the build's project. Reference: QGIS 3 QML/qgs format
// (QgsPalLayerSettings, QgsPalLayerSettings::Property names).
#include <string>

#include "qgis_project_xml.hpp"

namespace dtm::io::qgis {
namespace {

void write_marker(XmlWriter& xml, double size_mm, const std::string& color) {
    xml.open("renderer-v2", {{"type", "singleSymbol"},
                             {"symbollevels", "0"},
                             {"enableorderby", "0"},
                             {"forceraster", "0"}});
    xml.open("symbols");
    xml.open("symbol", {{"type", "marker"},
                        {"name", "0"},
                        {"alpha", size_mm > 0.0 ? "1" : "0"},
                        {"clip_to_extent", "1"},
                        {"force_rhr", "0"}});
    xml.open("layer",
             {{"class", "SimpleMarker"}, {"enabled", "1"}, {"locked", "0"}, {"pass", "0"}});
    const std::pair<std::string_view, std::string> props[] = {
        {"name", "circle"},        {"color", color},    {"outline_style", "no"},
        {"size", number(size_mm)}, {"size_unit", "MM"}, {"outline_width", "0"},
        {"outline_color", color}};
    xml.open("Option", {{"type", "Map"}});
    for (const auto& [key, value] : props) xml.option(key, value);
    xml.close("Option");
    for (const auto& [key, value] : props) {
        xml.leaf("prop", {{"k", std::string(key)}, {"v", value}});
    }
    xml.close("layer");
    xml.close("symbol");
    xml.close("symbols");
    xml.close("renderer-v2");
}

void write_expression(XmlWriter& xml, std::string_view name, const std::string& expression) {
    xml.open("Option", {{"name", std::string(name)}, {"type", "Map"}});
    xml.leaf("Option", {{"name", "active"}, {"type", "bool"}, {"value", "true"}});
    xml.option("expression", expression);
    xml.leaf("Option", {{"name", "type"}, {"type", "int"}, {"value", "3"}});
    xml.close("Option");
}

void write_labeling(XmlWriter& xml, LabelLayer kind, double text_height) {
    const bool contour = kind == LabelLayer::contour_labels;
    xml.open("labeling", {{"type", "simple"}});
    xml.open("settings", {{"calloutType", "simple"}});
    xml.open("text-style", {{"fieldName", contour ? "text" : "label"},
                            {"isExpression", "0"},
                            {"fontFamily", "Sans Serif"},
                            {"fontSize", number(text_height)},
                            {"fontSizeUnit", "MapUnit"},
                            // at least 1.5 mm when zoomed out (QgsMapUnitScale: min/max scale,
                            // min size on, min size mm, max size off, max size mm)
                            {"fontSizeMapUnitScale", "3x:0,0,1,1.5,0,0"},
                            {"fontWeight", "50"},
                            {"fontItalic", "0"},
                            {"textColor", contour ? "104,62,30,255" : "0,0,0,255"},
                            {"textOpacity", "1"},
                            {"multilineHeight", "1"}});
    xml.leaf("text-buffer", {{"bufferDraw", "1"},
                             {"bufferSize", number(0.15 * text_height)},
                             {"bufferSizeUnits", "MapUnit"},
                             {"bufferColor", "255,255,255,255"},
                             {"bufferOpacity", "0.8"},
                             {"bufferNoFill", "1"}});
    xml.close("text-style");
    xml.leaf("placement", {{"placement", "1"},   // over the point
                           {"quadOffset", "4"},  // centred on it
                           {"priority", "5"}});
    xml.leaf("rendering", {{"drawLabels", "1"},
                           {"obstacle", "0"},
                           {"scaleVisibility", "0"},
                           {"displayAll", "1"},  // placed by dtm: never hidden by QGIS
                           {"upsidedownLabels", "2"}});
    xml.open("dd_properties");
    xml.open("Option", {{"type", "Map"}});
    xml.option("name", "");
    xml.open("Option", {{"name", "properties"}, {"type", "Map"}});
    if (contour) {
        write_expression(xml, "LabelRotation", "-\"angle\"");
    } else {
        write_expression(xml, "PositionX", "\"label_x\"");
        write_expression(xml, "PositionY", "\"label_y\"");
        write_expression(xml, "Hali", "'Center'");
        write_expression(xml, "Vali", "'Half'");
    }
    xml.close("Option");
    xml.option("type", "collection");
    xml.close("Option");
    xml.close("dd_properties");
    xml.close("settings");
    xml.close("labeling");
}

void write_style(XmlWriter& xml, LabelLayer kind, double text_height) {
    if (kind == LabelLayer::contour_labels) {
        write_marker(xml, 0.0, "104,62,30,255");
    } else {
        write_marker(xml, 1.0, "0,0,0,255");
    }
    write_labeling(xml, kind, text_height);
}

}  // namespace

void write_label_layer(XmlWriter& xml,
                       const QgisProject& project,
                       const CrsInfo& crs,
                       LabelLayer kind) {
    const bool contour = kind == LabelLayer::contour_labels;
    open_maplayer(xml, "vector", "Point");
    const std::string layer = contour ? project.contour_label_layer : project.spot_layer;
    write_layer_head(xml, project, crs, contour ? contour_labels_id : spot_heights_id,
                     project_path(project.contours) + "|layername=" + layer,
                     contour ? "Contour labels" : "Spot heights", "ogr");
    write_style(xml, kind, project.label_height);
    xml.text("blendMode", "0");
    xml.text("featureBlendMode", "0");
    xml.text("layerOpacity", "1");
    xml.close("maplayer");
}

}  // namespace dtm::io::qgis

namespace dtm::io {

std::string label_layer_qml(LabelLayer kind, double text_height) {
    qgis::XmlWriter xml;
    xml.raw("<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>\n");
    xml.open("qgis", {{"version", "3.28.0-Firenze"},
                      {"styleCategories", "Symbology|Labeling"},
                      {"labelsEnabled", "1"}});
    qgis::write_style(xml, kind, text_height);
    xml.close("qgis");
    return xml.str();
}

}  // namespace dtm::io
