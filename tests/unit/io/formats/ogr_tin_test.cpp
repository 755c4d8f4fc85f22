// SPDX-License-Identifier: MIT
#include "dtm/io/formats/ogr_tin.hpp"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <memory>

#include "dtm/core/error.hpp"
#include "support/test_support.hpp"
#include "support/tin_fixture.hpp"

namespace {

struct Closer {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};

std::string epsg_5514_wkt() {
    OGRSpatialReference srs;
    srs.importFromEPSG(5514);
    char* wkt = nullptr;
    srs.exportToWkt(&wkt);
    std::string text(wkt);
    CPLFree(wkt);
    return text;
}

void expect_triangles_with_crs(const std::filesystem::path& path, const dtm::Tin& tin) {
    std::unique_ptr<GDALDataset, Closer> ds(
        GDALDataset::Open(path.string().c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    ASSERT_TRUE(ds) << path;
    ASSERT_EQ(ds->GetLayerCount(), 1);
    OGRLayer* layer = ds->GetLayer(0);
    EXPECT_EQ(layer->GetFeatureCount(), static_cast<GIntBig>(tin.triangles.size()));
    EXPECT_EQ(wkbFlatten(layer->GetGeomType()), wkbPolygon);
    EXPECT_TRUE(wkbHasZ(layer->GetGeomType()));
    const OGRSpatialReference* srs = layer->GetSpatialRef();
    ASSERT_NE(srs, nullptr);
    OGRSpatialReference copy(*srs);
    copy.AutoIdentifyEPSG();
    const char* code = copy.GetAuthorityCode(nullptr);
    EXPECT_STREQ(code, "5514");

    layer->ResetReading();
    std::unique_ptr<OGRFeature> feature(layer->GetNextFeature());
    ASSERT_TRUE(feature);
    const auto* polygon = feature->GetGeometryRef()->toPolygon();
    const OGRLinearRing* ring = polygon->getExteriorRing();
    ASSERT_EQ(ring->getNumPoints(), 4);
    const dtm::Point3& first = tin.vertices[tin.triangles[0].v[0]];
    EXPECT_EQ(ring->getX(0), first.x);
    EXPECT_EQ(ring->getY(0), first.y);
    EXPECT_EQ(ring->getZ(0), first.z);
    EXPECT_DOUBLE_EQ(
        feature->GetFieldAsDouble("z_max"),
        std::max({tin.vertices[tin.triangles[0].v[0]].z, tin.vertices[tin.triangles[0].v[1]].z,
                  tin.vertices[tin.triangles[0].v[2]].z}));
}

TEST(OgrTin, GeoPackageHoldsOnePolygonZPerTriangleWithCrs) {
    GDALAllRegister();
    const dtm::Tin tin = dtm::test::grid_tin(6);
    dtm::test::ScratchDir dir;
    dtm::io::TinWriteOptions options;
    options.crs_wkt = epsg_5514_wkt();
    dtm::io::write_ogr_tin(tin, dir / "tin.gpkg", options);
    expect_triangles_with_crs(dir / "tin.gpkg", tin);
}

TEST(OgrTin, ShapefileHoldsOnePolygonZPerTriangleWithPrj) {
    GDALAllRegister();
    const dtm::Tin tin = dtm::test::grid_tin(4);
    dtm::test::ScratchDir dir;
    dtm::io::TinWriteOptions options;
    options.crs_wkt = "EPSG:5514";
    dtm::io::write_ogr_tin(tin, dir / "tin.shp", options);
    EXPECT_TRUE(std::filesystem::exists(dir / "tin.prj"));
    expect_triangles_with_crs(dir / "tin.shp", tin);
}

TEST(OgrTin, RewritingReplacesTheOldFile) {
    GDALAllRegister();
    dtm::test::ScratchDir dir;
    dtm::io::TinWriteOptions options;
    options.crs_wkt = "EPSG:5514";
    dtm::io::write_ogr_tin(dtm::test::grid_tin(6), dir / "tin.gpkg", options);
    const dtm::Tin small = dtm::test::grid_tin(3);
    dtm::io::write_ogr_tin(small, dir / "tin.gpkg", options);
    expect_triangles_with_crs(dir / "tin.gpkg", small);
}

TEST(OgrTin, UnknownExtensionIsUsageError) {
    dtm::test::ScratchDir dir;
    EXPECT_THROW(dtm::io::write_ogr_tin(dtm::test::grid_tin(3), dir / "tin.kml", {}),
                 dtm::UsageError);
}

}  // namespace
