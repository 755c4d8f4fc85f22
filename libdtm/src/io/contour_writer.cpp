// SPDX-License-Identifier: MIT
// Contour output through OGR (GDAL's vector API): one LineStringZ feature per contour line.
// Features are written inside transactions of 50 000 (GeoPackage is an SQLite file: one
// transaction per feature would be very slow). DXF has no attribute table: the layer of each
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
#include <mutex>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/extension.hpp"

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

}  // namespace

struct ContourWriter::State {
    AtomicOutput out;
    bool dxf = false;
    GDALDatasetH ds = nullptr;
    OGRLayerH layer = nullptr;
    OGRSpatialReferenceH srs = nullptr;
    int elevation_field = -1, index_field = -1, closed_field = -1, dxf_layer_field = -1;
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
};

void ContourWriter::State::create_fields() {
    if (dxf) {
        dxf_layer_field = OGR_FD_GetFieldIndex(OGR_L_GetLayerDefn(layer), "Layer");
        return;
    }
    const auto add = [this](const char* name, OGRFieldType type, OGRFieldSubType sub) {
        OGRFieldDefnH f = OGR_Fld_Create(name, type);
        OGR_Fld_SetSubType(f, sub);
        const OGRErr err = OGR_L_CreateField(layer, f, TRUE);
        OGR_Fld_Destroy(f);
        if (err != OGRERR_NONE) {
            throw_ogr(std::string("cannot create the field ") + name);
        }
        return OGR_FD_GetFieldIndex(OGR_L_GetLayerDefn(layer), name);
    };
    elevation_field = add("elevation", OFTReal, OFSTNone);
    index_field = add("index", OFTInteger, OFSTBoolean);
    closed_field = add("closed", OFTInteger, OFSTBoolean);
}

ContourWriter::ContourWriter(const fs::path& target, const ContourWriteOptions& options) {
    const Format& format = format_for(target);
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
    state_ = std::make_unique<State>(target);
    State& s = *state_;
    s.dxf = std::string_view(format.driver) == "DXF";
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
    if (!s.in_transaction) {
        s.in_transaction = GDALDatasetStartTransaction(s.ds, FALSE) == OGRERR_NONE;
    }
    OGRFeatureH feature = OGR_F_Create(OGR_L_GetLayerDefn(s.layer));
    if (s.dxf) {
        OGR_F_SetFieldString(feature, s.dxf_layer_field, level.index ? "CONTOUR_INDEX" : "CONTOUR");
    } else {
        OGR_F_SetFieldDouble(feature, s.elevation_field, level.value);
        OGR_F_SetFieldInteger(feature, s.index_field, level.index ? 1 : 0);
        OGR_F_SetFieldInteger(feature, s.closed_field, closed ? 1 : 0);
    }
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

void ContourWriter::commit() {
    State& s = *state_;
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

std::vector<std::string> contour_extensions() {
    std::vector<std::string> out;
    for (const Format& f : formats) {
        out.emplace_back(f.extension);
    }
    return out;
}

}  // namespace dtm::io
