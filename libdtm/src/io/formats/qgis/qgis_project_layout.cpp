// SPDX-License-Identifier: MIT
// The print layout of a QGIS 3 project (`<Layouts><Layout>`), as QgsLayout::writeXml stores it:
// a page collection with one page item, then the items by type id (QgsLayoutItemRegistry:
// page 65638, map 65639, picture 65640, label 65641, legend 65642, shape 65643, scale bar
// 65646), each with position, size and a uuid by which the legend, scale bar and north arrow
// name their map. The map item carries the sheet's extent, its CRS and a cross grid with
// frame annotations (S-JTSK as positive Y, X through an annotation expression). Attributes QGIS
// fills with defaults are left out; tests/support/qgis_layout_check.py reads the result with
// PyQGIS.
#include <cstdio>
#include <string>

#include "qgis_project_xml.hpp"

namespace dtm::io::qgis {
namespace {

constexpr const char* map_uuid = "{5d1e0000-0000-4000-8000-00000000d7a1}";

std::string mm_pair(double a, double b) { return number(a) + "," + number(b) + ",mm"; }

std::string uuid(int n) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "{5d1e0000-0000-4000-8000-%012d}", n);
    return buf;
}

/// Opens the map item's LayoutItem at @p box (x, y, w, h).
void open_map_item(XmlWriter& xml, const std::array<double, 4>& box) {
    xml.open("LayoutItem", {{"type", "65639"},
                            {"uuid", map_uuid},
                            {"templateUuid", map_uuid},
                            {"id", "Map"},
                            {"position", mm_pair(box[0], box[1])},
                            {"positionOnPage", mm_pair(box[0], box[1])},
                            {"size", mm_pair(box[2], box[3])},
                            {"zValue", "1"},
                            {"visibility", "1"},
                            {"frame", "true"},
                            {"background", "true"},
                            {"outlineWidthM", "0.5,mm"},
                            {"referencePoint", "0"}});
}

void write_colours(XmlWriter& xml) {
    xml.leaf("FrameColor", {{"red", "0"}, {"green", "0"}, {"blue", "0"}, {"alpha", "255"}});
    xml.leaf("BackgroundColor",
             {{"red", "255"}, {"green", "255"}, {"blue", "255"}, {"alpha", "255"}});
}

void write_map_item(XmlWriter& xml, const QgisLayout& l, const CrsInfo& crs) {
    open_map_item(xml, {0.0, 0.0, l.width_mm, l.height_mm});
    write_colours(xml);
    xml.leaf("Extent", {{"xmin", number(l.extent.xmin)},
                        {"ymin", number(l.extent.ymin)},
                        {"xmax", number(l.extent.xmax)},
                        {"ymax", number(l.extent.ymax)}});
    xml.open("crs");
    write_spatialrefsys(xml, crs);
    xml.close("crs");
    xml.leaf("LayerSet");
    if (l.grid_interval > 0.0) {
        const std::string expression =
            l.sjtsk ? "CASE WHEN @grid_axis = 'x' THEN 'Y ' || format_number(-@grid_number, 0) "
                      "ELSE 'X ' || format_number(-@grid_number, 0) END"
                    : "CASE WHEN @grid_axis = 'x' THEN 'E ' || format_number(@grid_number, 0) "
                      "ELSE 'N ' || format_number(@grid_number, 0) END";
        xml.leaf("ComposerMapGrid", {{"name", "grid crosses"},
                                     {"uuid", uuid(900)},
                                     {"show", "1"},
                                     {"gridStyle", "1"},  // crosses
                                     {"crossLength", "3"},
                                     {"intervalX", number(l.grid_interval)},
                                     {"intervalY", number(l.grid_interval)},
                                     {"offsetX", "0"},
                                     {"offsetY", "0"},
                                     {"unit", "0"},  // map units
                                     {"showAnnotation", "1"},
                                     {"annotationFormat", "8"},  // custom expression
                                     {"annotationExpression", expression},
                                     {"annotationPrecision", "0"},
                                     {"leftAnnotationPosition", "0"},  // inside the frame
                                     {"rightAnnotationPosition", "0"},
                                     {"topAnnotationPosition", "0"},
                                     {"bottomAnnotationPosition", "0"},
                                     {"leftAnnotationDirection", "1"},  // vertical
                                     {"rightAnnotationDirection", "1"},
                                     {"topAnnotationDirection", "0"},
                                     {"bottomAnnotationDirection", "0"},
                                     {"frameAnnotationDistance", "1"},
                                     {"gridFrameStyle", "0"}});
    }
    xml.close("LayoutItem");
}

void write_label(XmlWriter& xml,
                 const std::string& text,
                 const std::array<double, 4>& box,
                 int z,
                 double size_pt) {
    xml.open("LayoutItem", {{"type", "65641"},
                            {"uuid", uuid(z)},
                            {"templateUuid", uuid(z)},
                            {"id", "Title block"},
                            {"labelText", text},
                            {"position", mm_pair(box[0], box[1])},
                            {"positionOnPage", mm_pair(box[0], box[1])},
                            {"size", mm_pair(box[2], box[3])},
                            {"zValue", std::to_string(z)},
                            {"visibility", "1"},
                            {"frame", "true"},
                            {"background", "true"},
                            {"marginX", "1.5"},
                            {"marginY", "1.5"},
                            {"halign", "1"},   // Qt::AlignLeft
                            {"valign", "32"},  // Qt::AlignTop
                            {"outlineWidthM", "0.35,mm"},
                            {"htmlState", "0"}});
    write_colours(xml);
    xml.leaf("LabelFont",
             {{"description", "DejaVu Sans," + number(size_pt) + ",-1,5,50,0,0,0,0,0"}});
    xml.leaf("FontColor", {{"red", "0"}, {"green", "0"}, {"blue", "0"}, {"alpha", "255"}});
    xml.close("LayoutItem");
}

}  // namespace

void write_layouts(XmlWriter& xml, const QgisProject& project, const CrsInfo& crs) {
    const QgisLayout& l = *project.layout;
    xml.open("Layouts");
    xml.open("Layout", {{"name", l.name}, {"units", "mm"}, {"printResolution", "300"}});
    xml.open("PageCollection");
    xml.open("LayoutItem", {{"type", "65638"},
                            {"uuid", uuid(0)},
                            {"size", mm_pair(l.width_mm, l.height_mm)},
                            {"position", "0,0,mm"},
                            {"positionOnPage", "0,0,mm"},
                            {"zValue", "0"},
                            {"visibility", "1"},
                            {"background", "true"}});
    write_colours(xml);
    xml.close("LayoutItem");
    xml.leaf("GuideCollection", {{"visible", "1"}});
    xml.close("PageCollection");
    write_map_item(xml, l, crs);
    // north arrow (QGIS's own SVG, synchronised with the map's true north)
    xml.open("LayoutItem", {{"type", "65640"},
                            {"uuid", uuid(2)},
                            {"templateUuid", uuid(2)},
                            {"id", "North arrow"},
                            {"file", ":/images/north_arrows/layout_default_north_arrow.svg"},
                            {"mode", "2"},  // SVG
                            {"resizeMode", "0"},
                            {"mapUuid", map_uuid},
                            {"northMode", "1"},  // true north
                            {"position", mm_pair(l.north_box[0], l.north_box[1])},
                            {"positionOnPage", mm_pair(l.north_box[0], l.north_box[1])},
                            {"size", mm_pair(l.north_box[2], l.north_box[3])},
                            {"zValue", "2"},
                            {"visibility", "1"},
                            {"frame", "false"},
                            {"background", "false"}});
    write_colours(xml);
    xml.close("LayoutItem");
    xml.open("LayoutItem", {{"type", "65646"},
                            {"uuid", uuid(3)},
                            {"templateUuid", uuid(3)},
                            {"id", "Scale bar"},
                            {"mapUuid", map_uuid},
                            {"style", "Single Box"},
                            {"unitType", "meters"},
                            {"unitLabel", "m"},
                            {"numSegments", "4"},
                            {"numSegmentsLeft", "0"},
                            {"segmentSizeMode", "1"},  // fit the width
                            {"minBarWidth", number(l.scale_bar_box[2] * 0.5)},
                            {"maxBarWidth", number(l.scale_bar_box[2] * 0.9)},
                            {"numMapUnitsPerScaleBarUnit", "1"},
                            {"height", "1.5"},
                            {"position", mm_pair(l.scale_bar_box[0], l.scale_bar_box[1])},
                            {"positionOnPage", mm_pair(l.scale_bar_box[0], l.scale_bar_box[1])},
                            {"size", mm_pair(l.scale_bar_box[2], l.scale_bar_box[3])},
                            {"zValue", "3"},
                            {"visibility", "1"},
                            {"frame", "false"},
                            {"background", "true"}});
    write_colours(xml);
    xml.close("LayoutItem");
    xml.open("LayoutItem", {{"type", "65642"},
                            {"uuid", uuid(4)},
                            {"templateUuid", uuid(4)},
                            {"id", "Legend"},
                            {"title", "Legend"},
                            {"map_uuid", map_uuid},
                            {"resizeToContents", "1"},
                            // anchored at its lower right corner: it grows up and to the left,
                            // away from the title block
                            {"referencePoint", "8"},
                            {"position", mm_pair(l.legend_box[0] + l.legend_box[2],
                                                 l.legend_box[1] + l.legend_box[3])},
                            {"positionOnPage", mm_pair(l.legend_box[0] + l.legend_box[2],
                                                       l.legend_box[1] + l.legend_box[3])},
                            {"size", mm_pair(l.legend_box[2], l.legend_box[3])},
                            {"zValue", "4"},
                            {"visibility", "1"},
                            {"frame", "true"},
                            {"background", "true"}});
    write_colours(xml);
    xml.close("LayoutItem");
    std::string text = l.title + "\n";
    for (const auto& [name, value] : l.fields) text += name + ": " + value + "\n";
    text += "Surveyor:                    Signature:";
    write_label(xml, text, l.title_box, 5, 7.0);
    xml.close("Layout");
    xml.close("Layouts");
}

}  // namespace dtm::io::qgis
