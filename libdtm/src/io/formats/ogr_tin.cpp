// SPDX-License-Identifier: MIT
// OGR TIN writer: triangles as PolygonZ features, inside one transaction (GeoPackage writes a
// few hundred thousand features per second that way, against a few hundred without).
#include "dtm/io/formats/ogr_tin.hpp"

#include <gdal_priv.h>
#include <ogr_feature.h>
#include <ogr_geometry.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/extension.hpp"
#include "io/detail/gdal_drivers.hpp"

namespace dtm::io {
namespace {

struct DatasetCloser {
    void operator()(GDALDataset* dataset) const noexcept { GDALClose(dataset); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

const char* driver_for(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    if (ext == "gpkg") {
        return "GPKG";
    }
    if (ext == "shp") {
        return "ESRI Shapefile";
    }
    throw UsageError("ogr tin: unknown extension '." + ext + "' for " + path.string() +
                     " (known: .gpkg, .shp)");
}

[[noreturn]] void fail(const std::string& what) {
    throw Error("ogr tin: " + what + ": " + CPLGetLastErrorMsg());
}

/// Steepest slope in degrees of the plane through the triangle.
double slope_degrees(const Point3& a, const Point3& b, const Point3& c) {
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    const double nx = uy * vz - uz * vy;
    const double ny = uz * vx - ux * vz;
    const double nz = ux * vy - uy * vx;
    return std::atan2(std::hypot(nx, ny), std::fabs(nz)) * 180.0 / std::numbers::pi;
}

OGRLayer* create_layer(GDALDataset& dataset,
                       const std::filesystem::path& path,
                       const std::string& crs_wkt) {
    OGRSpatialReference srs;
    const bool has_crs = !crs_wkt.empty();
    if (has_crs && srs.SetFromUserInput(crs_wkt.c_str()) != OGRERR_NONE) {
        throw Error("ogr tin: cannot interpret the CRS for " + path.string());
    }
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const std::string name = std::string(dataset.GetDriver()->GetDescription()) == "GPKG"
                                 ? std::string("tin")
                                 : path.stem().string();
    OGRLayer* layer =
        dataset.CreateLayer(name.c_str(), has_crs ? &srs : nullptr, wkbPolygon25D, nullptr);
    if (layer == nullptr) {
        fail("cannot create layer in " + path.string());
    }
    OGRFieldDefn id("id", OFTInteger64);
    OGRFieldDefn z_min("z_min", OFTReal);
    OGRFieldDefn z_max("z_max", OFTReal);
    OGRFieldDefn slope("slope_deg", OFTReal);
    for (OGRFieldDefn* field : {&id, &z_min, &z_max, &slope}) {
        if (layer->CreateField(field) != OGRERR_NONE) {
            fail("cannot create field in " + path.string());
        }
    }
    return layer;
}

void write_features(const Tin& tin, OGRLayer& layer, const std::filesystem::path& path) {
    for (std::size_t i = 0; i < tin.triangles.size(); ++i) {
        const Triangle& t = tin.triangles[i];
        const Point3& a = tin.vertices[t.v[0]];
        const Point3& b = tin.vertices[t.v[1]];
        const Point3& c = tin.vertices[t.v[2]];
        auto ring = std::make_unique<OGRLinearRing>();
        for (const Point3* p : {&a, &b, &c, &a}) {
            ring->addPoint(p->x, p->y, p->z);
        }
        OGRPolygon polygon;
        polygon.addRingDirectly(ring.release());
        OGRFeature feature(layer.GetLayerDefn());
        feature.SetField("id", static_cast<GIntBig>(i));
        feature.SetField("z_min", std::min({a.z, b.z, c.z}));
        feature.SetField("z_max", std::max({a.z, b.z, c.z}));
        feature.SetField("slope_deg", slope_degrees(a, b, c));
        feature.SetGeometry(&polygon);
        if (layer.CreateFeature(&feature) != OGRERR_NONE) {
            fail("cannot write triangle " + std::to_string(i) + " to " + path.string());
        }
    }
}

}  // namespace

void write_ogr_tin(const Tin& tin,
                   const std::filesystem::path& path,
                   const TinWriteOptions& options) {
    const char* driver_name = driver_for(path);
    detail::register_gdal_drivers();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name);
    if (driver == nullptr) {
        throw Error(std::string("ogr tin: GDAL has no ") + driver_name + " driver");
    }
    std::error_code ignored;
    if (std::filesystem::exists(path, ignored)) {
        driver->Delete(path.string().c_str());
    }
    DatasetPtr dataset(driver->Create(path.string().c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!dataset) {
        fail("cannot create " + path.string());
    }
    OGRLayer* layer = create_layer(*dataset, path, options.crs_wkt);
    const bool transaction = dataset->StartTransaction() == OGRERR_NONE;
    write_features(tin, *layer, path);
    if (transaction && dataset->CommitTransaction() != OGRERR_NONE) {
        fail("cannot commit " + path.string());
    }
    CPLErrorReset();
    dataset.reset();  // GDALClose flushes; GDAL 3.6 reports a failure only through CPLError
    if (CPLGetLastErrorType() == CE_Failure) {
        fail("cannot finish " + path.string());
    }
}

}  // namespace dtm::io
