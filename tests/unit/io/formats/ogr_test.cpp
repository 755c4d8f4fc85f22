// SPDX-License-Identifier: MIT
// OGR reader: geometry kinds by role, --z-field, --where, --layer, CRS, real shapefiles.
#include "dtm/io/formats/ogr.hpp"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <string>

#include "dtm/core/error.hpp"
#include "support/test_support.hpp"

namespace {

using dtm::io::InputFile;
using dtm::io::InputRole;
using dtm::io::ReadOptions;
using dtm::io::ReadResult;

/// Writes a small vector file with GDAL from WKT geometries and one "elev" + "kind" attribute.
struct Feature {
    const char* wkt;
    double elev;
    const char* kind;
};

void write_vector(const std::filesystem::path& path,
                  const char* driver_name,
                  std::initializer_list<Feature> features,
                  int epsg = 5514,
                  const char* layer_name = "data") {
    GDALAllRegister();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name);
    ASSERT_NE(driver, nullptr);
    GDALDataset* ds = driver->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
    ASSERT_NE(ds, nullptr);
    OGRSpatialReference srs;
    srs.importFromEPSG(epsg);
    OGRLayer* layer = ds->CreateLayer(layer_name, &srs, wkbUnknown, nullptr);
    OGRFieldDefn elev("elev", OFTReal);
    OGRFieldDefn kind("kind", OFTString);
    layer->CreateField(&elev);
    layer->CreateField(&kind);
    for (const Feature& f : features) {
        OGRFeature* feature = OGRFeature::CreateFeature(layer->GetLayerDefn());
        OGRGeometry* g = nullptr;
        ASSERT_EQ(OGRGeometryFactory::createFromWkt(f.wkt, nullptr, &g), OGRERR_NONE) << f.wkt;
        feature->SetGeometryDirectly(g);
        feature->SetField("elev", f.elev);
        feature->SetField("kind", f.kind);
        ASSERT_EQ(layer->CreateFeature(feature), OGRERR_NONE);
        OGRFeature::DestroyFeature(feature);
    }
    GDALClose(ds);
}

ReadResult read(const std::filesystem::path& path, InputRole role, ReadOptions options = {}) {
    return dtm::io::read_ogr(InputFile{path, role}, options);
}

TEST(OgrReader, PolygonAsBoundaryGivesOuterBoundaryAndInnerHoles) {
    dtm::test::ScratchDir dir;
    write_vector(dir / "b.gpkg", "GPKG",
                 {{"POLYGON Z ((0 0 1,100 0 2,100 100 3,0 100 4,0 0 1),"
                   "(40 40 5,60 40 5,60 60 5,40 60 5,40 40 5))",
                   0, "site"}});
    const ReadResult r = read(dir / "b.gpkg", InputRole::boundary);
    ASSERT_EQ(r.terrain.boundaries.size(), 1u);
    ASSERT_EQ(r.terrain.holes.size(), 1u);
    EXPECT_TRUE(r.terrain.boundaries[0].closed);
    EXPECT_EQ(r.terrain.boundaries[0].points.size(), 4u);  // closing vertex dropped
    EXPECT_EQ(r.terrain.boundaries[0].points[2], (dtm::Point3{100, 100, 3}));
    EXPECT_EQ(r.summary.crs, "EPSG:5514");
    EXPECT_FALSE(r.crs_wkt.empty());
}

TEST(OgrReader, MixedLayerAsPositionalInputGivesPointsAndBreaklines) {
    dtm::test::ScratchDir dir;
    write_vector(dir / "m.gpkg", "GPKG",
                 {{"POINT Z (1 2 3)", 0, "pt"},
                  {"MULTIPOINT Z ((4 5 6),(7 8 9))", 0, "pt"},
                  {"LINESTRING Z (0 0 1,10 0 2)", 0, "edge"},
                  {"POLYGON Z ((20 20 1,30 20 1,30 30 1,20 20 1))", 0, "roof"}});
    const ReadResult r = read(dir / "m.gpkg", InputRole::points);
    EXPECT_EQ(r.terrain.points.size(), 3u);
    ASSERT_EQ(r.terrain.breaklines.size(), 2u);
    EXPECT_FALSE(r.terrain.breaklines[0].closed);
    EXPECT_TRUE(r.terrain.breaklines[1].closed);
    EXPECT_TRUE(r.terrain.boundaries.empty());
    EXPECT_NE(r.terrain.breaklines[0].source.find("feature"), std::string::npos);
}

TEST(OgrReader, DxfMixedLayerGivesPointsAndBreaklines) {
    dtm::test::ScratchDir dir;
    GDALAllRegister();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("DXF");
    ASSERT_NE(driver, nullptr);
    GDALDataset* ds = driver->Create((dir / "survey.dxf").c_str(), 0, 0, 0, GDT_Unknown, nullptr);
    ASSERT_NE(ds, nullptr);
    OGRLayer* layer = ds->CreateLayer("entities", nullptr, wkbUnknown, nullptr);
    for (const char* wkt :
         {"POINT Z (1 2 3)", "POINT Z (4 5 6)", "LINESTRING Z (0 0 1,10 0 2,10 10 3)"}) {
        OGRFeature* f = OGRFeature::CreateFeature(layer->GetLayerDefn());
        OGRGeometry* g = nullptr;
        ASSERT_EQ(OGRGeometryFactory::createFromWkt(wkt, nullptr, &g), OGRERR_NONE);
        f->SetGeometryDirectly(g);
        ASSERT_EQ(layer->CreateFeature(f), OGRERR_NONE);
        OGRFeature::DestroyFeature(f);
    }
    GDALClose(ds);
    const ReadResult r = read(dir / "survey.dxf", InputRole::points);
    ASSERT_EQ(r.terrain.points.size(), 2u);
    EXPECT_EQ(r.terrain.points[1], (dtm::Point3{4, 5, 6}));
    ASSERT_EQ(r.terrain.breaklines.size(), 1u);
    EXPECT_EQ(r.terrain.breaklines[0].points.size(), 3u);
    EXPECT_EQ(r.terrain.breaklines[0].points[2].z, 3.0);
    EXPECT_EQ(r.summary.format, "OGR DXF");
}

TEST(OgrReader, ZFieldGivesEveryVertexOfAContourItsHeight) {
    dtm::test::ScratchDir dir;
    write_vector(dir / "c.geojson", "GeoJSON",
                 {{"LINESTRING (0 0,10 0,10 10)", 250.0, "contour"},
                  {"LINESTRING (0 5,5 5)", 255.0, "contour"}},
                 4326);
    ReadOptions options;
    options.z_field = "elev";
    const ReadResult r = read(dir / "c.geojson", InputRole::breaklines, options);
    ASSERT_EQ(r.terrain.breaklines.size(), 2u);
    for (const auto& p : r.terrain.breaklines[0].points) EXPECT_EQ(p.z, 250.0);
    EXPECT_EQ(r.terrain.breaklines[1].points[1].z, 255.0);
}

TEST(OgrReader, TwoDimensionalPointsNeedAZField) {
    dtm::test::ScratchDir dir;
    write_vector(dir / "p.gpkg", "GPKG", {{"POINT (1 2)", 7.5, "pt"}});
    EXPECT_THROW((void)read(dir / "p.gpkg", InputRole::points), dtm::InputError);
    ReadOptions options;
    options.z_field = "elev";
    const ReadResult r = read(dir / "p.gpkg", InputRole::points, options);
    ASSERT_EQ(r.terrain.points.size(), 1u);
    EXPECT_EQ(r.terrain.points[0], (dtm::Point3{1, 2, 7.5}));
}

TEST(OgrReader, MissingZFieldNamesTheAvailableFields) {
    dtm::test::ScratchDir dir;
    write_vector(dir / "p.gpkg", "GPKG", {{"POINT Z (1 2 3)", 7.5, "pt"}});
    ReadOptions options;
    options.z_field = "height";
    try {
        (void)read(dir / "p.gpkg", InputRole::points, options);
        FAIL();
    } catch (const dtm::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("elev, kind"), std::string::npos) << e.what();
    }
}

TEST(OgrReader, WhereFiltersFeaturesAndBadFilterIsAnError) {
    dtm::test::ScratchDir dir;
    write_vector(
        dir / "w.gpkg", "GPKG",
        {{"LINESTRING Z (0 0 1,10 0 2)", 0, "edge"}, {"LINESTRING Z (0 5 1,10 5 2)", 0, "fence"}});
    ReadOptions options;
    options.where = "kind = 'edge'";
    EXPECT_EQ(read(dir / "w.gpkg", InputRole::breaklines, options).terrain.breaklines.size(), 1u);
    options.where = "no_such_column = 3";
    EXPECT_THROW((void)read(dir / "w.gpkg", InputRole::breaklines, options), dtm::InputError);
}

TEST(OgrReader, LayerChoiceAndUnknownLayerListsLayers) {
    dtm::test::ScratchDir dir;
    write_vector(dir / "l.gpkg", "GPKG", {{"POINT Z (1 2 3)", 0, "pt"}}, 5514, "spot_heights");
    ReadOptions options;
    options.layer = "spot_heights";
    EXPECT_EQ(read(dir / "l.gpkg", InputRole::points, options).terrain.points.size(), 1u);
    options.layer = "nope";
    try {
        (void)read(dir / "l.gpkg", InputRole::points, options);
        FAIL();
    } catch (const dtm::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("spot_heights"), std::string::npos);
    }
}

TEST(OgrReader, HolesInputTakesRingsAndPointSeeds) {
    dtm::test::ScratchDir dir;
    write_vector(
        dir / "h.gpkg", "GPKG",
        {{"POLYGON Z ((0 0 1,10 0 1,10 10 1,0 0 1))", 0, "lake"}, {"POINT (50 50)", 0, "seed"}});
    const ReadResult r = read(dir / "h.gpkg", InputRole::holes);
    EXPECT_EQ(r.terrain.holes.size(), 1u);
    ASSERT_EQ(r.terrain.hole_seeds.size(), 1u);
    EXPECT_EQ(r.terrain.hole_seeds[0], (dtm::Point2{50, 50}));
}

TEST(OgrReader, UnreadableFileIsAnInputError) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "x.shp", "not a shapefile");
    EXPECT_THROW((void)read(dir / "x.shp", InputRole::points), dtm::InputError);
}

TEST(OgrReaderRealData, JvfShapefilesCarryEpsg5514) {
    const std::string d = "points-cz-sjtsk-jvf-dtm/derived/";
    if (!dtm::test::shared_data_available(d + "zps_points_pointz.shp")) GTEST_SKIP();
    const ReadResult points =
        read(dtm::test::shared_data_path(d + "zps_points_pointz.shp"), InputRole::points);
    EXPECT_EQ(points.terrain.points.size(), 917u);
    EXPECT_EQ(points.summary.crs, "EPSG:5514");
    const ReadResult lines = read(dtm::test::shared_data_path(d + "zps_breaklines_polylinez.shp"),
                                  InputRole::breaklines);
    EXPECT_EQ(lines.terrain.breaklines.size(), 55u);
    EXPECT_EQ(lines.summary.crs, "EPSG:5514");
    for (const auto& l : lines.terrain.breaklines) {
        for (const auto& p : l.points) {
            EXPECT_LT(p.x, -520000.0);
            EXPECT_TRUE(std::isfinite(p.z));
        }
    }
}

TEST(OgrReaderRealData, LastoolsPolygonZWithMAndEmptyDbf) {
    const std::string f = "shp-lastools-breaklines/lake_breakline.shp";
    if (!dtm::test::shared_data_available(f)) GTEST_SKIP();
    const ReadResult hard = read(dtm::test::shared_data_path(f), InputRole::breaklines);
    ASSERT_EQ(hard.terrain.breaklines.size(), 3u);
    for (const auto& l : hard.terrain.breaklines) {
        EXPECT_TRUE(l.closed);
        EXPECT_GT(l.points.front().z, 2700.0);  // z, not m
    }
    const ReadResult holes = read(dtm::test::shared_data_path(f), InputRole::holes);
    EXPECT_EQ(holes.terrain.holes.size(), 3u);
}

}  // namespace
