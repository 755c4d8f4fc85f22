// SPDX-License-Identifier: MIT
// `dtm build` output opened by QGIS itself (PyQGIS, headless): the project and every layer valid
// in EPSG:5514, and each layer rendered alone over its extent drew (tests/support/
// qgis_open_check.py). PyQGIS (Debian: python3-qgis) is installed by scripts/install-deps.sh: the
// test fails without it under CI=true and skips elsewhere.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/test_support.hpp"

namespace {

TEST(QgisOpen, BuildProjectOpensInQgisWithEveryLayerValidInSjtsk)
{
    if (std::system("/usr/bin/python3 -c 'import qgis.core' >/dev/null 2>&1") != 0) {
        const char* ci = std::getenv("CI");
        if (ci != nullptr && std::string(ci) == "true") {
            FAIL() << "PyQGIS not installed: scripts/install-deps.sh installs python3-qgis";
        }
        GTEST_SKIP() << "PyQGIS not installed (apt-get install python3-qgis)";
    }
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
                                "' '" + (out / "dtm.qgs").string() + "' '" + dir.path().string() + "' > '" +
                                (dir / "qgis.log").string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << dtm::test::read_file(dir / "qgis.log");
}

}  // namespace
