// SPDX-License-Identifier: MIT
// `dtm contour`: exit codes, GeoPackage / shapefile / DXF outputs that OGR opens with the CRS,
// LineStringZ at the level, elevation and index attributes, exact positions on a plane.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "support/test_support.hpp"

namespace {

struct Closer {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

/// Points of the plane z = 100 + (x - x0) on a jittered 11 x 11 grid: the contour of level L is
/// the straight line x = x0 + L - 100, whatever the triangulation.
std::filesystem::path write_ramp(const dtm::test::ScratchDir& dir) {
    std::ostringstream csv;
    csv.precision(12);
    csv << "x,y,z\n";
    for (int i = 0; i <= 10; ++i) {
        for (int j = 0; j <= 10; ++j) {
            const double dx = (i > 0 && i < 10) ? 0.013 * ((i * 7 + j * 3) % 5) : 0.0;
            csv << -750'000.0 + i + dx << ',' << -1'050'000.0 + j << ',' << 100.0 + i + dx << '\n';
        }
    }
    const auto path = dir / "ramp.csv";
    dtm::test::write_file(path, csv.str());
    return path;
}

Dataset open_vector(const std::filesystem::path& path) {
    GDALAllRegister();
    return Dataset(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
}

TEST(CliContour, GeoPackageHasLinesOnTheirLevelWithIndexAttributeAndCrs) {
    const dtm::test::ScratchDir dir;
    const auto r =
        dtm::test::run_dtm({"contour", write_ramp(dir).string(), "-o", (dir / "c.gpkg").string(),
                            "--interval", "0.5", "--index-every", "4", "--crs", "EPSG:5514", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Dataset ds = open_vector(dir / "c.gpkg");
    ASSERT_TRUE(ds);
    OGRLayer* layer = ds->GetLayer(0);
    ASSERT_NE(layer->GetSpatialRef(), nullptr);
    OGRSpatialReference expected;
    expected.importFromEPSG(5514);
    EXPECT_TRUE(layer->GetSpatialRef()->IsSame(&expected));
    std::map<double, int> index_of_level;
    for (auto& feature : *layer) {
        const double level = feature->GetFieldAsDouble("elevation");
        index_of_level[level] = feature->GetFieldAsInteger("index");
        const OGRLineString* line = feature->GetGeometryRef()->toLineString();
        ASSERT_GE(line->getNumPoints(), 2);
        for (int i = 0; i < line->getNumPoints(); ++i) {
            EXPECT_EQ(line->getZ(i), level);
            EXPECT_NEAR(line->getX(i), -750'000.0 + level - 100.0, 1e-6);
        }
    }
    // 100.5 ... 110: zmin = 100 is not cut (zmin < level); 110 = zmax is the eastern border line
    ASSERT_EQ(index_of_level.size(), 20U);
    EXPECT_EQ(index_of_level.at(101.0), 0);
    EXPECT_EQ(index_of_level.at(102.0), 1);  // 102 = 0.5 * 204, 204 % 4 == 0
    EXPECT_EQ(index_of_level.at(102.5), 0);
}

TEST(CliContour, ShapefileWithPrjAndDxfWithLayersAndFixedLevels) {
    const dtm::test::ScratchDir dir;
    const auto ramp = write_ramp(dir).string();
    auto r = dtm::test::run_dtm({"contour", ramp, "-o", (dir / "c.shp").string(), "--levels",
                                 "103,105.25", "--crs", "EPSG:5514", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "c.prj"));
    Dataset shp = open_vector(dir / "c.shp");
    ASSERT_TRUE(shp);
    EXPECT_EQ(shp->GetLayer(0)->GetFeatureCount(), 2);
    r = dtm::test::run_dtm(
        {"contour", ramp, "-o", (dir / "c.dxf").string(), "--interval", "1", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Dataset dxf = open_vector(dir / "c.dxf");
    ASSERT_TRUE(dxf);
    int index = 0, other = 0;
    for (auto& feature : *dxf->GetLayer(0)) {
        const std::string layer = feature->GetFieldAsString("Layer");
        index += layer == "CONTOUR_INDEX" ? 1 : 0;
        other += layer == "CONTOUR" ? 1 : 0;
    }
    EXPECT_EQ(index, 2);  // 105 and 110 of 101 ... 110 (every 5th by default)
    EXPECT_EQ(other, 8);
}

TEST(CliContour, BadUsageExitsWithTwoAndWritesNothing) {
    const dtm::test::ScratchDir dir;
    const auto ramp = write_ramp(dir).string();
    const auto out = (dir / "c.gpkg").string();
    EXPECT_EQ(dtm::test::run_dtm({"contour", ramp, "-o", out, "-q"}).exit_code, 2);  // no levels
    EXPECT_EQ(dtm::test::run_dtm({"contour", ramp, "-o", out, "--interval", "0", "-q"}).exit_code,
              2);
    EXPECT_EQ(
        dtm::test::run_dtm({"contour", ramp, "-o", out, "--interval", "1e-9", "-q"}).exit_code, 2);
    EXPECT_EQ(dtm::test::run_dtm(
                  {"contour", ramp, "-o", (dir / "c.xyz").string(), "--interval", "1", "-q"})
                  .exit_code,
              2);
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
