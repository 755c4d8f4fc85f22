// SPDX-License-Identifier: MIT
// ContourWriter: GeoPackage, shapefile (.prj), GeoJSON, DXF layers; LineStringZ with z = level,
// attributes elevation/index/closed; atomic output.
#include "dtm/io/contour_writer.hpp"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <memory>
#include <set>

#include "dtm/core/error.hpp"
#include "support/test_support.hpp"

namespace {

struct Closer {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

std::string epsg_wkt(int code) {
    OGRSpatialReference srs;
    srs.importFromEPSG(code);
    char* wkt = nullptr;
    srs.exportToWkt(&wkt);
    std::string text(wkt);
    CPLFree(wkt);
    return text;
}

void write_three(const std::filesystem::path& path, bool with_crs) {
    dtm::io::ContourWriter writer(path, {.crs_wkt = with_crs ? epsg_wkt(5514) : std::string()});
    const std::vector<dtm::Point3> open{{-750'000.0, -1'050'000.0, 100.0},
                                        {-749'990.0, -1'050'000.5, 100.0}};
    const std::vector<dtm::Point3> ring{{-750'000.0, -1'050'010.0, 105.0},
                                        {-749'995.0, -1'050'010.0, 105.0},
                                        {-749'995.0, -1'050'005.0, 105.0},
                                        {-750'000.0, -1'050'010.0, 105.0}};
    writer.add({100.0, 20, true}, open, false);
    writer.add({101.0, 21, false}, open, false);
    writer.add({105.0, 21, false}, ring, true);
    EXPECT_EQ(writer.feature_count(), 3U);
    EXPECT_FALSE(std::filesystem::exists(path));
    writer.commit();
}

void expect_attributes_and_z(const std::filesystem::path& path, bool check_crs) {
    Dataset ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    ASSERT_TRUE(ds) << path;
    OGRLayer* layer = ds->GetLayer(0);
    ASSERT_EQ(layer->GetFeatureCount(), 3);
    EXPECT_TRUE(wkbHasZ(layer->GetGeomType()));
    std::set<double> elevations;
    int index_count = 0, closed_count = 0;
    for (auto& feature : *layer) {
        const double elevation = feature->GetFieldAsDouble("elevation");
        elevations.insert(elevation);
        index_count += feature->GetFieldAsInteger("index");
        closed_count += feature->GetFieldAsInteger("closed");
        const OGRLineString* line = feature->GetGeometryRef()->toLineString();
        for (int i = 0; i < line->getNumPoints(); ++i) {
            EXPECT_EQ(line->getZ(i), elevation);
        }
    }
    EXPECT_EQ(elevations, (std::set<double>{100.0, 101.0, 105.0}));
    EXPECT_EQ(index_count, 1);
    EXPECT_EQ(closed_count, 1);
    if (check_crs) {
        ASSERT_NE(layer->GetSpatialRef(), nullptr);
        OGRSpatialReference expected;
        expected.importFromEPSG(5514);
        EXPECT_TRUE(layer->GetSpatialRef()->IsSame(&expected));
    }
}

TEST(ContourWriter, GeoPackageHasLineStringZWithElevationIndexClosedAndCrs) {
    const dtm::test::ScratchDir dir;
    write_three(dir / "c.gpkg", true);
    expect_attributes_and_z(dir / "c.gpkg", true);
}

TEST(ContourWriter, ShapefileComesWithAPrjAndNoTemporaryFilesRemain) {
    const dtm::test::ScratchDir dir;
    write_three(dir / "c.shp", true);
    expect_attributes_and_z(dir / "c.shp", true);
    EXPECT_TRUE(std::filesystem::exists(dir / "c.prj"));
    EXPECT_TRUE(std::filesystem::exists(dir / "c.dbf"));
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        EXPECT_EQ(entry.path().stem(), "c") << entry.path();
    }
}

TEST(ContourWriter, GeoJsonKeepsTheAttributes) {
    const dtm::test::ScratchDir dir;
    write_three(dir / "c.geojson", false);
    expect_attributes_and_z(dir / "c.geojson", false);
}

TEST(ContourWriter, DxfPutsIndexAndIntermediateContoursOnSeparateLayers) {
    const dtm::test::ScratchDir dir;
    write_three(dir / "c.dxf", false);
    Dataset ds(GDALDataset::Open((dir / "c.dxf").c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    ASSERT_TRUE(ds);
    std::multiset<std::string> layers;
    for (auto& feature : *ds->GetLayer(0)) {
        layers.insert(feature->GetFieldAsString("Layer"));
        const OGRLineString* line = feature->GetGeometryRef()->toLineString();
        EXPECT_TRUE(line->Is3D());
        EXPECT_GE(line->getZ(0), 100.0);
    }
    EXPECT_EQ(layers.count("CONTOUR_INDEX"), 1U);
    EXPECT_EQ(layers.count("CONTOUR"), 2U);
}

TEST(ContourWriter, VrtJoinsThePiecesInOrderIntoOneLayer) {
    const dtm::test::ScratchDir dir;
    write_three(dir / "a.gpkg", true);
    write_three(dir / "b.gpkg", true);
    dtm::io::write_contour_vrt(dir / "all.vrt", {dir / "a.gpkg", dir / "b.gpkg"},
                               {.crs_wkt = epsg_wkt(5514)});
    Dataset ds(GDALDataset::Open((dir / "all.vrt").c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    ASSERT_TRUE(ds);
    ASSERT_EQ(ds->GetLayerCount(), 1);
    OGRLayer* layer = ds->GetLayerByName("contours");
    ASSERT_NE(layer, nullptr);
    EXPECT_EQ(layer->GetFeatureCount(), 6);
    EXPECT_EQ(layer->GetLayerDefn()->GetGeomFieldCount(), 1);
    std::vector<double> elevations;
    for (auto& feature : *layer) elevations.push_back(feature->GetFieldAsDouble("elevation"));
    EXPECT_EQ(elevations, (std::vector<double>{100.0, 101.0, 105.0, 100.0, 101.0, 105.0}));
    ASSERT_NE(layer->GetSpatialRef(), nullptr);
    const std::string text = dtm::test::read_file(dir / "all.vrt");
    EXPECT_EQ(text.find(dir.path().string()), std::string::npos) << "piece paths are relative";
    EXPECT_THROW(
        dtm::io::write_contour_vrt(dir / "bad.vrt", {dir / "a.gpkg", dir / "missing.gpkg"}, {}),
        dtm::Error);
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.vrt"));
}

TEST(ContourWriter, UnknownExtensionIsAUsageError) {
    const dtm::test::ScratchDir dir;
    EXPECT_THROW(dtm::io::ContourWriter(dir / "c.xyz", {}), dtm::UsageError);
}

}  // namespace
