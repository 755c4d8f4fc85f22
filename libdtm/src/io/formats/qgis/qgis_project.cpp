// SPDX-License-Identifier: MIT
// QGIS project writer: the document skeleton (projectCrs, layer tree, map canvas, layer order,
// properties) and the CRS description. The layer elements are in qgis_project_layers.cpp.
//
// Format reference: the QGIS 3 project file as written by QgsProject::write (element names
// `qgis`, `projectCrs/spatialrefsys`, `layer-tree-group/layer-tree-layer`, `mapcanvas`,
// `projectlayers/maplayer`, `layerorder`, `properties/Paths/Absolute`). When a spatialrefsys
// carries no srsid QGIS builds the CRS from its `wkt`, so the WKT2 text is authoritative here and
// authid/proj are informative.
#include "dtm/io/formats/qgis_project.hpp"

#include <cpl_conv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdlib>
#include <fstream>

#include "dtm/core/error.hpp"
#include "qgis_project_xml.hpp"

namespace dtm::io {
namespace qgis {

std::string escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            case '\n':
                out += "&#xa;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string number(double value) {
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return {buffer.data(), result.ptr};
}

void XmlWriter::start_tag(std::string_view name, Attributes attributes) {
    out_.append(static_cast<std::size_t>(depth_) * 2, ' ');
    out_ += '<';
    out_ += name;
    for (const auto& [key, value] : attributes) {
        out_ += ' ';
        out_ += key;
        out_ += "=\"";
        out_ += escape(value);
        out_ += '"';
    }
}

void XmlWriter::open(std::string_view name, Attributes attributes) {
    start_tag(name, attributes);
    out_ += ">\n";
    ++depth_;
}

void XmlWriter::close(std::string_view name) {
    --depth_;
    out_.append(static_cast<std::size_t>(depth_) * 2, ' ');
    out_ += "</";
    out_ += name;
    out_ += ">\n";
}

void XmlWriter::leaf(std::string_view name, Attributes attributes) {
    start_tag(name, attributes);
    out_ += "/>\n";
}

void XmlWriter::text(std::string_view name, std::string_view value, Attributes attributes) {
    start_tag(name, attributes);
    out_ += '>';
    out_ += escape(value);
    out_ += "</";
    out_ += name;
    out_ += ">\n";
}

void XmlWriter::option(std::string_view name, std::string value) {
    leaf("Option", {{"name", std::string(name)}, {"type", "QString"}, {"value", std::move(value)}});
}

namespace {

std::string take_cpl_string(char* text) {
    std::string out = text != nullptr ? text : "";
    CPLFree(text);
    return out;
}

std::string proj_acronym(const std::string& proj) {
    const auto at = proj.find("+proj=");
    if (at == std::string::npos) {
        return {};
    }
    const auto end = proj.find(' ', at);
    return proj.substr(at + 6, end == std::string::npos ? std::string::npos : end - at - 6);
}

}  // namespace

CrsInfo describe_crs(const std::string& crs_wkt) {
    CrsInfo info;
    if (crs_wkt.empty()) {
        return info;
    }
    OGRSpatialReference srs;
    if (srs.SetFromUserInput(crs_wkt.c_str()) != OGRERR_NONE) {
        throw Error("qgis project: cannot interpret the CRS");
    }
    if (srs.GetAuthorityName(nullptr) == nullptr) {
        srs.AutoIdentifyEPSG();
    }
    const char* wkt2_options[] = {"FORMAT=WKT2_2018", nullptr};
    char* wkt = nullptr;
    srs.exportToWkt(&wkt, wkt2_options);
    info.wkt = take_cpl_string(wkt);
    char* proj = nullptr;
    srs.exportToProj4(&proj);
    info.proj = take_cpl_string(proj);
    info.projection_acronym = proj_acronym(info.proj);
    const char* authority = srs.GetAuthorityName(nullptr);
    const char* code = srs.GetAuthorityCode(nullptr);
    if (authority != nullptr && code != nullptr) {
        info.authid = std::string(authority) + ":" + code;
        info.srid = code;
    }
    info.description = srs.GetName() != nullptr ? srs.GetName() : "";
    // WKT2 carries an ID only at the top: look the ellipsoid up from the authority's definition.
    OGRSpatialReference full;
    const OGRSpatialReference& source = authority != nullptr && std::string(authority) == "EPSG" &&
                                                code != nullptr &&
                                                full.importFromEPSG(std::atoi(code)) == OGRERR_NONE
                                            ? full
                                            : srs;
    if (const char* ellipsoid_code = source.GetAuthorityCode("SPHEROID")) {
        info.ellipsoid_acronym = std::string("EPSG:") + ellipsoid_code;
    }
    info.geographic = srs.IsGeographic() != 0;
    return info;
}

void write_spatialrefsys(XmlWriter& xml, const CrsInfo& crs) {
    xml.open("spatialrefsys", {{"nativeFormat", "Wkt"}});
    xml.text("wkt", crs.wkt);
    xml.text("proj4", crs.proj);
    xml.text("srid", crs.srid);
    xml.text("authid", crs.authid);
    xml.text("description", crs.description);
    xml.text("projectionacronym", crs.projection_acronym);
    xml.text("ellipsoidacronym", crs.ellipsoid_acronym);
    xml.text("geographicflag", crs.geographic ? "true" : "false");
    xml.close("spatialrefsys");
}

std::string project_path(const std::filesystem::path& path) {
    std::string text = path.generic_string();
    if (path.is_relative() && text.rfind("./", 0) != 0 && text.rfind("../", 0) != 0) {
        text.insert(0, "./");
    }
    return text;
}

std::string contours_source(const QgisProject& project) {
    std::string source = project_path(project.contours);
    if (!project.contour_layer.empty()) {
        source += "|layername=" + project.contour_layer;
    }
    return source;
}

}  // namespace qgis

namespace {

using qgis::project_path;
using qgis::XmlWriter;

struct TreeEntry {
    std::string_view id;
    std::string name;
    std::string source;
    std::string_view provider;
    bool visible;
};

/// The layers present in @p project, top of the drawing order first.
std::vector<TreeEntry> tree_entries(const QgisProject& project) {
    std::vector<TreeEntry> entries;
    const auto in_contours = [&](const std::string& layer) {
        return project_path(project.contours) + "|layername=" + layer;
    };
    if (!project.contours.empty() && !project.spot_layer.empty()) {
        entries.push_back(
            {qgis::spot_heights_id, "Spot heights", in_contours(project.spot_layer), "ogr", true});
    }
    if (!project.contours.empty() && !project.contour_label_layer.empty()) {
        entries.push_back({qgis::contour_labels_id, "Contour labels",
                           in_contours(project.contour_label_layer), "ogr", true});
    }
    if (!project.cut_fill.empty()) {
        entries.push_back({qgis::zero_lines_id, "Zero lines",
                           qgis::cut_fill_source(project, "zero_lines"), "ogr", true});
        entries.push_back({qgis::cut_fill_id, "Cut and fill",
                           qgis::cut_fill_source(project, "cut_fill"), "ogr", true});
    }
    if (!project.contours.empty()) {
        entries.push_back(
            {qgis::contours_id, "Contours", qgis::contours_source(project), "ogr", true});
    }
    if (!project.mesh.empty()) {
        entries.push_back({qgis::mesh_id, "TIN (mesh)", project_path(project.mesh), "mdal",
                           project.mesh_visible});
    }
    if (!project.dem.empty()) {
        entries.push_back({qgis::dem_id, "DEM", project_path(project.dem), "gdal", true});
    }
    if (!project.hillshade.empty()) {
        entries.push_back(
            {qgis::hillshade_id, "Hillshade", project_path(project.hillshade), "gdal", true});
    }
    return entries;
}

void write_layer_tree(XmlWriter& xml, const std::vector<TreeEntry>& entries) {
    xml.open("layer-tree-group");
    xml.leaf("customproperties");
    for (const TreeEntry& e : entries) {
        xml.open("layer-tree-layer", {{"id", std::string(e.id)},
                                      {"name", e.name},
                                      {"source", e.source},
                                      {"providerKey", std::string(e.provider)},
                                      {"checked", e.visible ? "Qt::Checked" : "Qt::Unchecked"},
                                      {"expanded", "1"},
                                      {"legend_exp", ""}});
        xml.leaf("customproperties");
        xml.close("layer-tree-layer");
    }
    xml.open("custom-order", {{"enabled", "0"}});
    for (const TreeEntry& e : entries) {
        xml.text("item", e.id);
    }
    xml.close("custom-order");
    xml.close("layer-tree-group");
}

void write_canvas(XmlWriter& xml, const QgisProject& project, const qgis::CrsInfo& crs) {
    Box2 box = project.extent;
    if (box.empty()) {
        box = Box2{0.0, 0.0, 1.0, 1.0};
    }
    const double margin = 0.05 * std::max(box.xmax - box.xmin, box.ymax - box.ymin);
    xml.open("mapcanvas", {{"name", "theMapCanvas"}, {"annotationsVisible", "1"}});
    xml.text("units", crs.geographic ? "degrees" : "meters");
    xml.open("extent");
    xml.text("xmin", qgis::number(box.xmin - margin));
    xml.text("ymin", qgis::number(box.ymin - margin));
    xml.text("xmax", qgis::number(box.xmax + margin));
    xml.text("ymax", qgis::number(box.ymax + margin));
    xml.close("extent");
    xml.text("rotation", "0");
    xml.open("destinationsrs");
    qgis::write_spatialrefsys(xml, crs);
    xml.close("destinationsrs");
    xml.text("rendermaptile", "0");
    xml.close("mapcanvas");
}

void write_properties(XmlWriter& xml) {
    xml.open("properties");
    xml.open("Paths");
    xml.text("Absolute", "false", {{"type", "bool"}});
    xml.close("Paths");
    xml.open("Measurement");
    xml.text("DistanceUnits", "meters", {{"type", "QString"}});
    xml.text("AreaUnits", "m2", {{"type", "QString"}});
    xml.close("Measurement");
    // QGIS 3.x before 3.28 reads <projectCrs> only when on-the-fly projection is flagged here
    // (checked: QGIS 3.22 opens the project with an empty project CRS without it).
    xml.open("SpatialRefSys");
    xml.text("ProjectionsEnabled", "1", {{"type", "int"}});
    xml.close("SpatialRefSys");
    xml.close("properties");
}

}  // namespace

std::string qgis_project_xml(const QgisProject& project) {
    const qgis::CrsInfo crs = qgis::describe_crs(project.crs_wkt);
    const std::vector<TreeEntry> entries = tree_entries(project);
    XmlWriter xml;
    xml.raw("<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>\n");
    xml.open("qgis", {{"projectname", project.title}, {"version", "3.28.0-Firenze"}});
    xml.leaf("homePath", {{"path", ""}});
    xml.text("title", project.title);
    xml.leaf("transaction", {{"mode", "Disabled"}});
    xml.leaf("projectFlags", {{"set", ""}});
    xml.open("projectCrs");
    qgis::write_spatialrefsys(xml, crs);
    xml.close("projectCrs");
    write_layer_tree(xml, entries);
    write_canvas(xml, project, crs);
    xml.open("projectlayers");
    if (!project.contours.empty() && !project.spot_layer.empty()) {
        qgis::write_label_layer(xml, project, crs, LabelLayer::spot_heights);
    }
    if (!project.contours.empty() && !project.contour_label_layer.empty()) {
        qgis::write_label_layer(xml, project, crs, LabelLayer::contour_labels);
    }
    if (!project.cut_fill.empty()) {
        qgis::write_zero_lines_layer(xml, project, crs);
        qgis::write_cut_fill_layer(xml, project, crs);
    }
    if (!project.contours.empty()) {
        qgis::write_contours_layer(xml, project, crs);
    }
    if (!project.mesh.empty()) {
        qgis::write_mesh_layer(xml, project, crs);
    }
    if (!project.dem.empty()) {
        qgis::write_dem_layer(xml, project, crs);
    }
    if (!project.hillshade.empty()) {
        qgis::write_hillshade_layer(xml, project, crs);
    }
    xml.close("projectlayers");
    xml.open("layerorder");
    for (const TreeEntry& e : entries) {
        xml.leaf("layer", {{"id", std::string(e.id)}});
    }
    xml.close("layerorder");
    if (project.layout) {
        qgis::write_layouts(xml, project, crs);
    }
    write_properties(xml);
    xml.close("qgis");
    return xml.str();
}

void write_qgis_project(const QgisProject& project, const std::filesystem::path& path) {
    const std::string text = qgis_project_xml(project);
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(text.data(), static_cast<std::streamsize>(text.size()));
    file.close();
    if (!file) {
        throw Error("qgis project: cannot write " + path.string());
    }
}

}  // namespace dtm::io
