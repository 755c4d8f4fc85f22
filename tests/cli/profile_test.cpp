// SPDX-License-Identifier: MIT
// `dtm profile`: products, a line outside the surface, and equality with QGIS's
// native:meshexportcrosssection on the same tin.2dm at its sample points (when PyQGIS exists).
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <cstdlib>
#include <string>

#include "support/analysis_fixtures.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

const char* lines_geojson =
    "{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\",\"properties\":{\"name\":"
    "\"EPSG:5514\"}},\"features\":[\n"
    "{\"type\":\"Feature\",\"properties\":{},\"geometry\":{\"type\":\"LineString\","
    "\"coordinates\":[[-750180,-1050160],[-750170,-1050100]]}},\n"
    "{\"type\":\"Feature\",\"properties\":{},\"geometry\":{\"type\":\"LineString\","
    "\"coordinates\":[[-750320,-1050150],[-750200,-1050120],[-750040,-1050100],"
    "[-750238.3,-1050070.1]]}},\n"
    "{\"type\":\"Feature\",\"properties\":{},\"geometry\":{\"type\":\"LineString\","
    "\"coordinates\":[[-750270,-1050065],[-750190,-1050065]]}}]}\n";

class CliProfile : public ::testing::Test {
protected:
    void SetUp() override {
        dtm::test::write_file(dir / "lines.geojson", lines_geojson);
        for (const char* out : {"tin.ply", "tin.2dm"}) {
            const auto r = dtm::test::build_sample_tin(dir / out, false);
            ASSERT_EQ(r.exit_code, 0) << r.err;
        }
    }
    dtm::test::ScratchDir dir;
};

TEST_F(CliProfile, WritesCsvGeoPackageDxfAndPlotWithGapsOutsideTheSurface) {
    const auto r =
        dtm::test::run_dtm({"profile", (dir / "tin.ply").string(), "--line",
                            (dir / "lines.geojson").string(), "-o", (dir / "out").string(), "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* f : {"profile.csv", "profile.gpkg", "profile.dxf", "profile.pdf"}) {
        EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
    }
    GDALAllRegister();
    GDALDataset* ds = GDALDataset::Open((dir / "out" / "profile.dxf").c_str(), GDAL_OF_VECTOR);
    ASSERT_NE(ds, nullptr);
    // Line 2 starts outside the boundary; line 3 crosses the building's hole (two runs).
    EXPECT_GE(ds->GetLayer(0)->GetFeatureCount(), 4);
    for (auto& f : *ds->GetLayer(0)) {
        EXPECT_TRUE(f->GetGeometryRef()->Is3D());
    }
    GDALClose(ds);
    const std::string csv = dtm::test::read_file(dir / "out" / "profile.csv");
    EXPECT_EQ(csv.rfind("line,surface,run,chainage,x,y,z\n", 0), 0U);
    EXPECT_NE(csv.find("\n3,tin,2,"), std::string::npos) << "expected a second run on line 3";
    EXPECT_EQ(csv.find("\n2,tin,1,0.000000,"), std::string::npos) << "line 2 starts outside";
}

TEST_F(CliProfile, ALineOutsideEverySurfaceIsAnErrorNamingTheFeature) {
    dtm::test::write_file(
        dir / "far.geojson",
        "{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\",\"properties\":"
        "{\"name\":\"EPSG:5514\"}},\"features\":[{\"type\":\"Feature\","
        "\"properties\":{},\"geometry\":{\"type\":\"LineString\",\"coordinates\":"
        "[[-740000,-1040000],[-739000,-1040000]]}}]}");
    const auto r =
        dtm::test::run_dtm({"profile", (dir / "tin.ply").string(), "--line",
                            (dir / "far.geojson").string(), "-o", (dir / "out").string(), "-q"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("far.geojson"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("outside every surface"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST_F(CliProfile, EqualsQgisMeshCrossSectionAtItsSamplePoints) {
    if (std::system("/usr/bin/python3 -c 'import qgis.core' >/dev/null 2>&1") != 0) {
        GTEST_SKIP() << "PyQGIS not installed (apt-get install python3-qgis qgis-providers)";
    }
    const auto r = dtm::test::run_dtm({"profile", (dir / "tin.ply").string(), "--line",
                                       (dir / "lines.geojson").string(), "-o",
                                       (dir / "out").string(), "-q", "--plot", "none"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const fs::path check = fs::path(DTM_TEST_DATA_DIR) / ".." / "support" / "qgis_profile_check.py";
    const std::string command =
        "QT_QPA_PLATFORM=offscreen /usr/bin/python3 '" + check.string() + "' '" +
        (dir / "tin.2dm").string() + "' '" + (dir / "lines.geojson").string() + "' '" +
        (dir / "out" / "profile.csv").string() + "' tin 0.5 '" + (dir / "qgis.csv").string() +
        "' > '" + (dir / "qgis.log").string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << dtm::test::read_file(dir / "qgis.log");
    std::printf("%s", dtm::test::read_file(dir / "qgis.log").c_str());
}

}  // namespace
