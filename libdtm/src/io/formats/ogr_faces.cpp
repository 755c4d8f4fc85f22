// SPDX-License-Identifier: MIT
// OGR polygon-face writer: one PolygonZ feature per face of a pseudo-triangulation, in one
// transaction (as the OGR TIN writer).
#include "dtm/io/formats/ogr_faces.hpp"

#include <gdal_priv.h>
#include <ogr_feature.h>
#include <ogr_geometry.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <memory>

#include "dtm/core/error.hpp"
#include "io/detail/gdal_drivers.hpp"

namespace dtm::io {
namespace {

struct DatasetCloser {
    void operator()(GDALDataset* d) const noexcept { GDALClose(d); }
};

[[noreturn]] void fail(const std::string& what) {
    throw Error("ogr faces: " + what + ": " + CPLGetLastErrorMsg());
}

}  // namespace

void write_ogr_faces(std::span<const Point3> vertices,
                     const std::vector<std::vector<VertexIndex>>& faces,
                     const std::filesystem::path& path,
                     const std::string& crs_wkt,
                     std::string_view ext) {
    detail::register_gdal_drivers();
    const char* driver_name = ext == "gpkg" ? "GPKG" : "ESRI Shapefile";
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name);
    if (driver == nullptr)
        throw Error(std::string("ogr faces: GDAL has no ") + driver_name + " driver");
    std::error_code ignored;
    if (std::filesystem::exists(path, ignored)) driver->Delete(path.string().c_str());
    std::unique_ptr<GDALDataset, DatasetCloser> dataset(
        driver->Create(path.string().c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    if (!dataset) fail("cannot create " + path.string());
    OGRSpatialReference srs;
    const bool has_crs = !crs_wkt.empty();
    if (has_crs && srs.SetFromUserInput(crs_wkt.c_str()) != OGRERR_NONE) {
        throw Error("ogr faces: cannot interpret the CRS for " + path.string());
    }
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const std::string name = ext == "gpkg" ? std::string("faces") : path.stem().string();
    OGRLayer* layer =
        dataset->CreateLayer(name.c_str(), has_crs ? &srs : nullptr, wkbPolygon25D, nullptr);
    if (layer == nullptr) fail("cannot create a layer in " + path.string());
    OGRFieldDefn id("id", OFTInteger64);
    OGRFieldDefn corners("vertices", OFTInteger);
    OGRFieldDefn z_min("z_min", OFTReal);
    OGRFieldDefn z_max("z_max", OFTReal);
    for (OGRFieldDefn* field : {&id, &corners, &z_min, &z_max}) {
        if (layer->CreateField(field) != OGRERR_NONE)
            fail("cannot create a field in " + path.string());
    }
    const bool transaction = dataset->StartTransaction() == OGRERR_NONE;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const auto& f = faces[i];
        auto ring = std::make_unique<OGRLinearRing>();
        double lo = vertices[f.front()].z;
        double hi = lo;
        for (std::size_t k = 0; k <= f.size(); ++k) {
            const Point3& p = vertices[f[k % f.size()]];
            ring->addPoint(p.x, p.y, p.z);
            lo = std::min(lo, p.z);
            hi = std::max(hi, p.z);
        }
        OGRPolygon polygon;
        polygon.addRingDirectly(ring.release());
        OGRFeature feature(layer->GetLayerDefn());
        feature.SetField("id", static_cast<GIntBig>(i));
        feature.SetField("vertices", static_cast<int>(f.size()));
        feature.SetField("z_min", lo);
        feature.SetField("z_max", hi);
        feature.SetGeometry(&polygon);
        if (layer->CreateFeature(&feature) != OGRERR_NONE) {
            fail("cannot write face " + std::to_string(i) + " to " + path.string());
        }
    }
    if (transaction && dataset->CommitTransaction() != OGRERR_NONE)
        fail("cannot commit " + path.string());
    CPLErrorReset();
    dataset.reset();
    if (CPLGetLastErrorType() == CE_Failure) fail("cannot finish " + path.string());
}

}  // namespace dtm::io
