// SPDX-License-Identifier: MIT
// `dtm build` output opened by QGIS itself (PyQGIS, headless): the project and every layer valid
// in EPSG:5514, and each layer rendered alone over its extent drew (tests/support/
// qgis_open_check.py). PyQGIS (Debian: python3-qgis) is installed by scripts/install-deps.sh: the
// test fails without it under CI=true and skips elsewhere.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/test_support.hpp"

namespace {

#define DTM_REQUIRE_PYQGIS()                                                                     \
    do {                                                                                         \
        if (std::system("/usr/bin/python3 -c 'import qgis.core' >/dev/null 2>&1") != 0) {        \
            const char* ci = std::getenv("CI");                                                  \
            if (ci != nullptr && std::string(ci) == "true") {                                    \
                FAIL() << "PyQGIS not installed: scripts/install-deps.sh installs python3-qgis"; \
            }                                                                                    \
            GTEST_SKIP() << "PyQGIS not installed (apt-get install python3-qgis)";               \
        }                                                                                        \
    } while (false)

TEST(QgisOpen, BuildProjectOpensInQgisWithEveryLayerValidInSjtsk) {
    DTM_REQUIRE_PYQGIS();
    const std::filesystem::path samples =
        std::filesystem::path(DTM_TEST_DATA_DIR) / ".." / ".." / "samples" / "sjtsk";
    const std::filesystem::path check =
        std::filesystem::path(DTM_TEST_DATA_DIR) / ".." / "support" / "qgis_open_check.py";
    dtm::test::ScratchDir dir;
    const auto out = dir / "out";
    const dtm::test::RunResult r = dtm::test::run_dtm(
        {"build", (samples / "points.csv").string(), "--breaklines",
         (samples / "breaklines.shp").string(), "--boundary", (samples / "boundary.shp").string(),
         "--holes", (samples / "building.shp").string(), "--crs", "EPSG:5514", "--skip-bad-lines",
         "-q", "-o", out.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string command = "QT_QPA_PLATFORM=offscreen /usr/bin/python3 '" + check.string() +
                                "' '" + (out / "dtm.qgs").string() + "' '" + dir.path().string() +
                                "' > '" + (dir / "qgis.log").string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << dtm::test::read_file(dir / "qgis.log");

    // The print layout: the sheet of map.pdf (A3 at the map's scale, its extent, EPSG:5514,
    // grid crosses), with the scale bar, legend and north arrow linked to the map.
    const std::filesystem::path layout_check =
        std::filesystem::path(DTM_TEST_DATA_DIR) / ".." / "support" / "qgis_layout_check.py";
    const std::string layout_command = "QT_QPA_PLATFORM=offscreen /usr/bin/python3 '" +
                                       layout_check.string() + "' '" + (out / "dtm.qgs").string() +
                                       "' 2>/dev/null";
    std::string printed;
    if (FILE* pipe = ::popen(layout_command.c_str(), "r")) {
        char buffer[4096];
        std::size_t n = 0;
        while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) printed.append(buffer, n);
        ::pclose(pipe);
    }
    EXPECT_NE(printed.find("page 420.000 297.000"), std::string::npos) << printed;
    EXPECT_NE(printed.find("scale 1000.000"), std::string::npos) << printed;
    EXPECT_NE(printed.find("crs EPSG:5514"), std::string::npos) << printed;
    EXPECT_NE(printed.find("grid 1 100.0"), std::string::npos) << printed;
    EXPECT_NE(printed.find("scalebar 1 linked 1"), std::string::npos) << printed;
    EXPECT_NE(printed.find("legend 1 linked 1"), std::string::npos) << printed;
    EXPECT_NE(printed.find("picture 1 linked 1"), std::string::npos) << printed;
    EXPECT_NE(printed.find("title Contour map"), std::string::npos) << printed;
    // the layout's extent is map.pdf's neat line
    const std::string json = dtm::test::read_file(out / "report.json");
    EXPECT_NE(json.find("\"map\""), std::string::npos) << json;
}

// The distributed layout (one rank's here; mpirun writes more pieces of the same kinds): the
// GDAL VRT over the DEM tiles and the OGR VRT over the contour pieces open in QGIS as a valid
// raster and a valid line layer in EPSG:5514 that draw.
TEST(QgisOpen, DistributedDemAndContourVrtsOpenInQgis) {
    DTM_REQUIRE_PYQGIS();
    const std::filesystem::path points =
        std::filesystem::path(DTM_TEST_DATA_DIR) / ".." / ".." / "samples" / "sjtsk" / "points.csv";
    const std::filesystem::path check =
        std::filesystem::path(DTM_TEST_DATA_DIR) / ".." / "support" / "qgis_layers_check.py";
    dtm::test::ScratchDir dir;
    const dtm::test::RunResult dem =
        dtm::test::run_dtm({"grid", points.string(), "--crs", "EPSG:5514", "--skip-bad-lines",
                            "--cell", "1", "-q", "-o", (dir / "dem.vrt").string()});
    ASSERT_EQ(dem.exit_code, 0) << dem.err;
    const dtm::test::RunResult lines = dtm::test::run_dtm(
        {"contour", points.string(), "--crs", "EPSG:5514", "--skip-bad-lines", "--interval", "1",
         "--no-labels", "-q", "-o", (dir / "contours.vrt").string()});
    ASSERT_EQ(lines.exit_code, 0) << lines.err;
    const std::string command = "QT_QPA_PLATFORM=offscreen /usr/bin/python3 '" + check.string() +
                                "' 'raster:" + (dir / "dem.vrt").string() +
                                "' 'vector:" + (dir / "contours.vrt").string() + "' > '" +
                                (dir / "qgis.log").string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << dtm::test::read_file(dir / "qgis.log");
}

}  // namespace
