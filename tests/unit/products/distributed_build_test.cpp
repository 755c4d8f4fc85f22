// SPDX-License-Identifier: MIT
// products::distributed_build on 1 to 64 in-process ranks (R-E3, R-P5): the report's measures of
// the TIN (counts, extent, z range, planimetric and 3-D areas: exact sums), the chosen cell and
// interval and the DEM grid equal products::build's on one process for the same points, bit for
// bit; tin.ply equals the serial build's byte for byte; every listed output exists; a surface
// with no triangle leaves no folder. The DEM cells and contour lines themselves are compared in
// distributed_dem_test, distributed_contours_test and tests/mpi/build_mpi_check.py.
#include "dtm/products/distributed_build.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/io/formats/tin_tiles.hpp"
#include "dtm/products/build.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

std::string survey_csv(int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 300.0);
    std::string text = "x,y,z\n";
    char line[128];
    for (int i = 0; i < count; ++i) {
        const double x = -750'000.0 + std::round(u(rng) * 1000.0) / 1000.0;
        const double y = -1'050'000.0 + std::round(u(rng) * 800.0) / 1000.0;
        std::snprintf(line, sizeof line, "%.17g,%.17g,%.3f\n", x, y,
                      250.0 + 0.03 * (x + 750'000.0) + 4.0 * std::sin(y / 17.0));
        text += line;
    }
    return text;
}

dtm::products::BuildReport run(const fs::path& points,
                               const fs::path& out,
                               int ranks,
                               std::uint64_t ply_limit = 2147483647) {
    dtm::products::DistributedBuildOptions options;
    options.ply_limit = ply_limit;
    options.source.input = {points, dtm::io::InputRole::points};
    options.source.default_crs = "EPSG:5514";
    options.out_dir = out;
    std::vector<dtm::products::BuildReport> reports(static_cast<std::size_t>(ranks));
    dtm::dist::run_in_process(ranks, [&](dtm::dist::Comm& comm) {
        reports[static_cast<std::size_t>(comm.rank())] =
            dtm::products::distributed_build(comm, options, {});
    });
    return reports[0];
}

TEST(DistributedBuild, MeasuresAndRulesEqualTheSerialBuildOnAnyRankCount) {
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "points.csv", survey_csv(4000, 20261204));
    dtm::io::LoadOptions inputs;
    inputs.files.push_back({dir / "points.csv", dtm::io::InputRole::points});
    inputs.crs.default_crs = "EPSG:5514";
    const dtm::products::BuildReport serial = dtm::products::build(inputs, dir / "serial");
    const std::string serial_ply = dtm::test::read_file(dir / "serial" / "tin.ply");
    for (const int ranks : {1, 3, 7, 16, 64}) {
        const std::string what = std::to_string(ranks) + " ranks";
        const fs::path out = dir / ("dist" + std::to_string(ranks));
        const dtm::products::BuildReport r = run(dir / "points.csv", out, ranks);
        const dtm::SurfaceStats &a = serial.surface, &b = r.surface;
        EXPECT_EQ(b.vertex_count, a.vertex_count) << what;
        EXPECT_EQ(b.triangle_count, a.triangle_count) << what;
        EXPECT_EQ(b.extent.xmin, a.extent.xmin) << what;
        EXPECT_EQ(b.extent.ymax, a.extent.ymax) << what;
        EXPECT_EQ(b.z_min, a.z_min) << what;
        EXPECT_EQ(b.z_max, a.z_max) << what;
        EXPECT_EQ(b.planimetric_area, a.planimetric_area) << what;  // exact sums: bit for bit
        EXPECT_EQ(b.surface_area, a.surface_area) << what;
        EXPECT_EQ(r.dem.cell, serial.dem.cell) << what;
        EXPECT_EQ(r.dem.cols, serial.dem.cols) << what;
        EXPECT_EQ(r.dem.rows, serial.dem.rows) << what;
        EXPECT_EQ(r.contour_interval, serial.contour_interval) << what;
        EXPECT_EQ(r.contour_lines, serial.contour_lines) << what;
        ASSERT_TRUE(r.distributed.has_value()) << what;
        EXPECT_EQ(r.distributed->ranks, ranks) << what;
        EXPECT_EQ(r.distributed->survey_points, 4000U) << what;
        EXPECT_EQ(r.distributed->unused_vertices, 0U) << what;
        EXPECT_EQ(dtm::test::read_file(out / "tin.ply"), serial_ply) << what;
        for (const std::string& f : r.outputs) EXPECT_TRUE(fs::exists(out / f)) << what << f;
        EXPECT_TRUE(fs::exists(out / "dtm.qgs") && fs::exists(out / "surface.pvtp")) << what;
    }
}

TEST(DistributedBuild, BeyondOnePlyTheFolderHoldsTheTiledTin) {
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "points.csv", survey_csv(3000, 20261205));
    const dtm::products::BuildReport one = run(dir / "points.csv", dir / "one", 3);
    const dtm::products::BuildReport tiled = run(dir / "points.csv", dir / "tiled", 3, 1000);
    EXPECT_FALSE(fs::exists(dir / "tiled" / "tin.ply"));
    ASSERT_TRUE(fs::exists(dir / "tiled" / "tin.json"));
    const auto listed = [&](const std::string& name) {
        return std::find(tiled.outputs.begin(), tiled.outputs.end(), name) != tiled.outputs.end();
    };
    EXPECT_TRUE(listed("tin.json") && !listed("tin.ply"));
    EXPECT_EQ(std::count_if(tiled.outputs.begin(), tiled.outputs.end(),
                            [](const std::string& f) { return f.ends_with("-of-3.ply"); }),
              3);
    for (const std::string& f : tiled.outputs) EXPECT_TRUE(fs::exists(dir / "tiled" / f)) << f;
    const dtm::io::LoadedTin tin = dtm::io::read_tin_tiles(dir / "tiled" / "tin.json");
    dtm::io::write_tin_ply(tin.tin, dir / "back.ply", {.crs_wkt = tin.crs_wkt});
    EXPECT_EQ(dtm::test::read_file(dir / "back.ply"),
              dtm::test::read_file(dir / "one" / "tin.ply"));
    EXPECT_EQ(tiled.surface.triangle_count, one.surface.triangle_count);
    EXPECT_EQ(tiled.contour_lines, one.contour_lines);
}

TEST(DistributedBuild, AFailedRunLeavesNoFolder) {
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "points.csv", "x,y,z\n0,0,1\n1,1,2\n2,2,3\n3,3,4\n");  // collinear
    EXPECT_THROW(run(dir / "points.csv", dir / "out", 3), dtm::InputError);
    EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
