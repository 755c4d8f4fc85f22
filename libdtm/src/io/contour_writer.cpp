// SPDX-License-Identifier: MIT
// Contour output through OGR (GDAL's vector API): one LineStringZ feature per contour line.
// Features are written inside transactions of 50 000 (GeoPackage is an SQLite file: one
// transaction per feature would be very slow). DXF goes through dtm's own R12 writer (GDAL's
// DXF writer cannot write rotated, centred TEXT): it has no attribute table, the layer of each
// entity (CONTOUR_INDEX or CONTOUR) carries the index flag and the z the elevation.
#include "dtm/io/contour_writer.hpp"

#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <optional>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/formats/dxf.hpp"
#include "dtm/io/formats/qgis_project.hpp"
#include "io/detail/gdal_drivers.hpp"
#include "io/formats/qgis/qgis_project_xml.hpp"

namespace dtm::io {
namespace fs = std::filesystem;
namespace {

struct Format {
    const char* extension;
    const char* driver;
};
constexpr std::array<Format, 5> formats{{{"gpkg", "GPKG"},
                                         {"shp", "ESRI Shapefile"},
                                         {"dxf", "DXF"},
                                         {"geojson", "GeoJSON"},
                                         {"json", "GeoJSON"}}};

const Format& format_for(const fs::path& target) {
    const std::string ext = lower_extension(target);
    for (const Format& f : formats) {
        if (ext == f.extension) {
            return f;
        }
    }
    throw UsageError("contour: cannot write '." + ext + "' (" + target.string() +
                     "); use .gpkg, .shp, .dxf or .geojson");
}

[[noreturn]] void throw_ogr(const std::string& what) {
    throw Error("contour: " + what + ": " + CPLGetLastErrorMsg());
}

constexpr long long transaction_size = 50'000;

const std::array<DxfLayer, 5> dxf_layers{{{"CONTOUR", 32},
                                          {"CONTOUR_INDEX", 30},
                                          {"CONTOUR_LABELS", 30},
                                          {"SPOT_HEIGHTS", 7},
                                          {"SPOT_LABELS", 7}}};

}  // namespace

struct ContourWriter::State {
    AtomicOutput out;
    bool dxf = false;
    bool gpkg = false;
    std::optional<DxfWriter> dxf_writer;
    GDALDatasetH ds = nullptr;
    OGRLayerH layer = nullptr;
    OGRSpatialReferenceH srs = nullptr;
    int elevation_field = -1, index_field = -1, closed_field = -1;
    std::size_t features = 0;
    bool in_transaction = false;

    explicit State(const fs::path& target) : out(target) {}
    ~State() {
        if (ds != nullptr) {
            GDALClose(ds);
        }
        if (srs != nullptr) {
            OSRDestroySpatialReference(srs);
        }
    }
    void create_fields();
    OGRLayerH create_layer(const char* name, OGRwkbGeometryType type);
    void write_annotation_layers(const ContourAnnotation& a);
    void write_style(const char* table, LabelLayer kind, double text_height);
};

namespace {

int add_field(OGRLayerH layer, const char* name, OGRFieldType type, OGRFieldSubType sub) {
    OGRFieldDefnH f = OGR_Fld_Create(name, type);
    OGR_Fld_SetSubType(f, sub);
    const OGRErr err = OGR_L_CreateField(layer, f, TRUE);
    OGR_Fld_Destroy(f);
    if (err != OGRERR_NONE) {
        throw_ogr(std::string("cannot create the field ") + name);
    }
    return OGR_FD_GetFieldIndex(OGR_L_GetLayerDefn(layer), name);
}

void create_feature(OGRLayerH layer, OGRFeatureH feature, const char* what) {
    const OGRErr err = OGR_L_CreateFeature(layer, feature);
    OGR_F_Destroy(feature);
    if (err != OGRERR_NONE) throw_ogr(std::string("cannot write ") + what);
}

}  // namespace

void ContourWriter::State::create_fields() {
    elevation_field = add_field(layer, "elevation", OFTReal, OFSTNone);
    index_field = add_field(layer, "index", OFTInteger, OFSTBoolean);
    closed_field = add_field(layer, "closed", OFTInteger, OFSTBoolean);
}

OGRLayerH ContourWriter::State::create_layer(const char* name, OGRwkbGeometryType type) {
    OGRLayerH l = GDALDatasetCreateLayer(ds, name, type == wkbNone ? nullptr : srs, type, nullptr);
    if (l == nullptr) throw_ogr(std::string("cannot create the layer ") + name);
    return l;
}

/// The GeoPackage's default QGIS style of @p table (the layer_styles table QGIS reads).
void ContourWriter::State::write_style(const char* table, LabelLayer kind, double text_height) {
    OGRLayerH styles = GDALDatasetGetLayerByName(ds, "layer_styles");
    if (styles == nullptr) {
        styles = create_layer("layer_styles", wkbNone);
        for (const char* f : {"f_table_catalog", "f_table_schema", "f_table_name",
                              "f_geometry_column", "styleName", "styleQML", "styleSLD"}) {
            add_field(styles, f, OFTString, OFSTNone);
        }
        add_field(styles, "useAsDefault", OFTInteger, OFSTBoolean);
        for (const char* f : {"description", "owner", "ui"})
            add_field(styles, f, OFTString, OFSTNone);
        add_field(styles, "update_time", OFTDateTime, OFSTNone);
    }
    OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(styles));
    const auto set = [&](const char* field, const std::string& value) {
        OGR_F_SetFieldString(f, OGR_F_GetFieldIndex(f, field), value.c_str());
    };
    set("f_table_catalog", "");
    set("f_table_schema", "");
    set("f_table_name", table);
    set("f_geometry_column", "geom");
    set("styleName", table);
    set("styleQML", label_layer_qml(kind, text_height));
    set("styleSLD", "");
    OGR_F_SetFieldInteger(f, OGR_F_GetFieldIndex(f, "useAsDefault"), 1);
    set("description", "dtm: placed labels");
    set("owner", "");
    set("ui", "");
    create_feature(styles, f, "the layer style");
}

void ContourWriter::State::write_annotation_layers(const ContourAnnotation& a) {
    if (in_transaction && GDALDatasetCommitTransaction(ds) != OGRERR_NONE) {
        throw_ogr("cannot write " + out.target().string());
    }
    in_transaction = GDALDatasetStartTransaction(ds, FALSE) == OGRERR_NONE;
    OGRLayerH labels = create_layer("contour_labels", wkbPoint);
    const int text = add_field(labels, "text", OFTString, OFSTNone);
    const int level = add_field(labels, "level", OFTReal, OFSTNone);
    const int angle = add_field(labels, "angle", OFTReal, OFSTNone);
    const int height = add_field(labels, "height", OFTReal, OFSTNone);
    for (const ContourLabel& l : a.labels) {
        OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(labels));
        OGR_F_SetFieldString(f, text, l.text.c_str());
        OGR_F_SetFieldDouble(f, level, l.level);
        OGR_F_SetFieldDouble(f, angle, l.angle_deg());
        OGR_F_SetFieldDouble(f, height, a.text_height);
        OGRGeometryH g = OGR_G_CreateGeometry(wkbPoint);
        OGR_G_SetPoint_2D(g, 0, l.anchor.x, l.anchor.y);
        OGR_F_SetGeometryDirectly(f, g);
        create_feature(labels, f, "a contour label");
    }
    OGRLayerH spots = create_layer("spot_heights", wkbPoint25D);
    const int z = add_field(spots, "height", OFTReal, OFSTNone);
    const int kind = add_field(spots, "kind", OFTString, OFSTNone);
    const int label = add_field(spots, "label", OFTString, OFSTNone);
    const int lx = add_field(spots, "label_x", OFTReal, OFSTNone);
    const int ly = add_field(spots, "label_y", OFTReal, OFSTNone);
    for (const SpotAnnotation& s : a.spots) {
        OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(spots));
        OGR_F_SetFieldDouble(f, z, s.spot.point.z);
        OGR_F_SetFieldString(f, kind, to_string(s.spot.kind));
        if (s.box) {
            OGR_F_SetFieldString(f, label, s.text.c_str());
            OGR_F_SetFieldDouble(f, lx, s.box->centre.x);
            OGR_F_SetFieldDouble(f, ly, s.box->centre.y);
        }
        OGRGeometryH g = OGR_G_CreateGeometry(wkbPoint25D);
        OGR_G_SetPoint(g, 0, s.spot.point.x, s.spot.point.y, s.spot.point.z);
        OGR_F_SetGeometryDirectly(f, g);
        create_feature(spots, f, "a spot height");
    }
    write_style("contour_labels", LabelLayer::contour_labels, a.text_height);
    write_style("spot_heights", LabelLayer::spot_heights, a.text_height);
}

ContourWriter::ContourWriter(const fs::path& target, const ContourWriteOptions& options) {
    const Format& format = format_for(target);
    detail::register_gdal_drivers();
    state_ = std::make_unique<State>(target);
    State& s = *state_;
    s.dxf = std::string_view(format.driver) == "DXF";
    s.gpkg = std::string_view(format.driver) == "GPKG";
    if (s.dxf) {
        s.dxf_writer.emplace(s.out.temp_path(), dxf_layers);
        return;
    }
    GDALDriverH driver = GDALGetDriverByName(format.driver);
    if (driver == nullptr) {
        throw Error(std::string("contour: the GDAL driver ") + format.driver + " is not available");
    }
    s.ds = GDALCreate(driver, s.out.temp_path().c_str(), 0, 0, 0, GDT_Unknown, nullptr);
    if (s.ds == nullptr) {
        throw_ogr("cannot create " + target.string());
    }
    if (!options.crs_wkt.empty()) {
        s.srs = OSRNewSpatialReference(options.crs_wkt.c_str());
        if (s.srs == nullptr) {
            throw_ogr("the CRS is not valid WKT");
        }
        OSRSetAxisMappingStrategy(s.srs, OAMS_TRADITIONAL_GIS_ORDER);
    }
    const std::string name = format.driver == std::string_view("ESRI Shapefile")
                                 ? s.out.temp_path().stem().string()
                                 : options.layer;
    s.layer = GDALDatasetCreateLayer(s.ds, name.c_str(), s.srs, wkbLineString25D, nullptr);
    if (s.layer == nullptr) {
        throw_ogr("cannot create the layer in " + target.string());
    }
    s.create_fields();
}

ContourWriter::~ContourWriter() = default;

void ContourWriter::add(const ContourLevel& level, std::span<const Point3> line, bool closed) {
    State& s = *state_;
    if (s.dxf) {
        // a closed ring repeats its first point: the polyline's closed flag says it once
        const std::size_t n = closed && line.size() > 1 ? line.size() - 1 : line.size();
        s.dxf_writer->polyline(level.index ? "CONTOUR_INDEX" : "CONTOUR", line.first(n), closed);
        ++s.features;
        return;
    }
    if (!s.in_transaction) {
        s.in_transaction = GDALDatasetStartTransaction(s.ds, FALSE) == OGRERR_NONE;
    }
    OGRFeatureH feature = OGR_F_Create(OGR_L_GetLayerDefn(s.layer));
    OGR_F_SetFieldDouble(feature, s.elevation_field, level.value);
    OGR_F_SetFieldInteger(feature, s.index_field, level.index ? 1 : 0);
    OGR_F_SetFieldInteger(feature, s.closed_field, closed ? 1 : 0);
    OGRGeometryH geometry = OGR_G_CreateGeometry(wkbLineString25D);
    OGR_G_SetPointCount(geometry, static_cast<int>(line.size()));
    for (std::size_t i = 0; i < line.size(); ++i) {
        OGR_G_SetPoint(geometry, static_cast<int>(i), line[i].x, line[i].y, level.value);
    }
    OGR_F_SetGeometryDirectly(feature, geometry);
    const OGRErr err = OGR_L_CreateFeature(s.layer, feature);
    OGR_F_Destroy(feature);
    if (err != OGRERR_NONE) {
        throw_ogr("cannot write a contour at " + std::to_string(level.value));
    }
    ++s.features;
    if (s.in_transaction && s.features % transaction_size == 0) {
        if (GDALDatasetCommitTransaction(s.ds) != OGRERR_NONE) {
            throw_ogr("cannot write " + s.out.target().string());
        }
        s.in_transaction = false;
    }
}

bool ContourWriter::holds_annotation() const noexcept { return state_->dxf || state_->gpkg; }

void ContourWriter::add_annotation(const ContourAnnotation& a) {
    State& s = *state_;
    if (!holds_annotation()) {
        throw UsageError("contour: labels and spot heights need a .dxf or .gpkg output, not " +
                         s.out.target().string());
    }
    if (!s.dxf) {
        s.write_annotation_layers(a);
        return;
    }
    DxfWriter& w = *s.dxf_writer;
    for (const ContourLabel& l : a.labels) {
        w.text("CONTOUR_LABELS", {l.anchor.x, l.anchor.y, l.level}, a.text_height, l.angle_deg(),
               l.text, DxfWriter::Align::middle_centre);
    }
    for (const SpotAnnotation& spot : a.spots) {
        w.point("SPOT_HEIGHTS", spot.spot.point);
        if (!spot.box) continue;
        w.text("SPOT_LABELS", {spot.box->centre.x, spot.box->centre.y, spot.spot.point.z},
               a.text_height, 0.0, spot.text, DxfWriter::Align::middle_centre);
    }
}

void ContourWriter::commit() {
    State& s = *state_;
    if (s.dxf) {
        s.dxf_writer->finish();
        s.out.commit();
        return;
    }
    if (s.in_transaction && GDALDatasetCommitTransaction(s.ds) != OGRERR_NONE) {
        throw_ogr("cannot write " + s.out.target().string());
    }
    s.in_transaction = false;
    CPLErrorReset();
    GDALClose(s.ds);
    s.ds = nullptr;
    if (CPLGetLastErrorType() >= CE_Failure) {
        throw_ogr("cannot write " + s.out.target().string());
    }
    s.out.commit();
}

std::size_t ContourWriter::feature_count() const noexcept { return state_->features; }

bool contour_file_holds_annotation(const fs::path& target) {
    const std::string ext = lower_extension(target);
    return ext == "dxf" || ext == "gpkg";
}

std::vector<std::string> contour_extensions() {
    std::vector<std::string> out;
    for (const Format& f : formats) {
        out.emplace_back(f.extension);
    }
    return out;
}

void write_contour_vrt(const fs::path& target,
                       const std::vector<fs::path>& pieces,
                       const ContourWriteOptions& options) {
    detail::register_gdal_drivers();
    qgis::XmlWriter xml;
    xml.open("OGRVRTDataSource");
    xml.open("OGRVRTUnionLayer", {{"name", options.layer}});
    for (const fs::path& piece : pieces) {
        const bool beside = piece.parent_path() == target.parent_path();
        xml.open("OGRVRTLayer", {{"name", piece.stem().string()}});
        xml.text("SrcDataSource", beside ? piece.filename().string() : piece.string(),
                 {{"relativeToVRT", beside ? "1" : "0"}});
        xml.text("SrcLayer", options.layer);
        xml.close("OGRVRTLayer");
    }
    xml.close("OGRVRTUnionLayer");
    xml.close("OGRVRTDataSource");
    AtomicOutput out(target);
    {
        std::ofstream file(out.temp_path(), std::ios::binary);
        file << xml.str();
        if (!file.flush()) throw Error("contour: cannot write " + target.string());
    }
    for (const fs::path& piece : pieces) {  // each piece opens and holds the layer
        GDALDatasetH ds =
            GDALOpenEx(piece.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
        const bool holds =
            ds != nullptr && GDALDatasetGetLayerByName(ds, options.layer.c_str()) != nullptr;
        if (ds != nullptr) GDALClose(ds);
        if (!holds) {
            throw Error("contour: cannot open the layer " + options.layer + " of " +
                        piece.string() + " for the VRT " + target.string());
        }
    }
    CPLErrorReset();
    GDALDatasetH ds = GDALOpenEx(out.temp_path().c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY,
                                 nullptr, nullptr, nullptr);
    const bool opens = ds != nullptr && GDALDatasetGetLayerCount(ds) == 1 &&
                       OGR_L_GetFeatureCount(GDALDatasetGetLayer(ds, 0), 1) >= 0 &&
                       CPLGetLastErrorType() < CE_Failure;
    if (ds != nullptr) GDALClose(ds);
    if (!opens) throw_ogr("the VRT " + target.string() + " over the contour pieces does not open");
    out.commit();
}

}  // namespace dtm::io
