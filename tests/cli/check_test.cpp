// SPDX-License-Identifier: MIT
// `dtm check` on the sample against its check points plus points outside the surface: the
// statistics equal an independent numpy computation (tests/support/check_stats_oracle.py).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "support/analysis_fixtures.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

TEST(CliCheck, StatisticsEqualAnIndependentNumpyComputationAndOutsidePointsAreListed) {
    const dtm::test::ScratchDir dir;
    for (const char* out : {"tin.ply", "tin.2dm"}) {
        const auto r = dtm::test::build_sample_tin(dir / out, false);
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    // The sample's check points, one west of the boundary and one in the building (a hole).
    std::string points = dtm::test::read_file(dtm::test::sample_file("checkpoints.csv"));
    points += "OUT1,-750320.000,-1050100.000,300.0\nHOLE1,-750230.000,-1050065.000,330.0\n";
    dtm::test::write_file(dir / "points.csv", points);
    const auto r =
        dtm::test::run_dtm({"check", (dir / "tin.ply").string(), (dir / "points.csv").string(),
                            "-o", (dir / "residuals.csv").string(), "--stats",
                            (dir / "stats.json").string(), "--crs", "EPSG:5514", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("2 outside"), std::string::npos) << r.out;
    const std::string csv = dtm::test::read_file(dir / "residuals.csv");
    EXPECT_NE(csv.find("OUT1,"), std::string::npos);
    EXPECT_NE(csv.find(",outside\n"), std::string::npos);
    if (std::system("/usr/bin/python3 -c 'import numpy' >/dev/null 2>&1") != 0) {
        GTEST_SKIP() << "numpy not installed (apt-get install python3-numpy)";
    }
    const fs::path oracle =
        fs::path(DTM_TEST_DATA_DIR) / ".." / "support" / "check_stats_oracle.py";
    const std::string command =
        "/usr/bin/python3 '" + oracle.string() + "' '" + (dir / "tin.2dm").string() + "' '" +
        (dir / "points.csv").string() + "' '" + (dir / "residuals.csv").string() + "' '" +
        (dir / "stats.json").string() + "' > '" + (dir / "oracle.log").string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << dtm::test::read_file(dir / "oracle.log");
}

TEST(CliCheck, UnknownInterpolationIsABadUsage) {
    const dtm::test::ScratchDir dir;
    const auto r = dtm::test::run_dtm({"check", dtm::test::sample_file("points.csv").string(),
                                       dtm::test::sample_file("checkpoints.csv").string(), "-o",
                                       (dir / "r.csv").string(), "--interpolation", "spline",
                                       "--crs", "EPSG:5514", "--skip-bad-lines", "-q"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("spline"), std::string::npos) << r.err;
}

}  // namespace
