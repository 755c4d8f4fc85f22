// SPDX-License-Identifier: MIT
// `dtm tin` end to end: the real river survey with boundary and hole seeds, byte-identical output
// for every thread and tile count, stats and reports, contour input without its flat triangles
// (--z-field, --contours-fix-flats), bad input (exit 2, nothing written).
#include <gtest/gtest.h>

#include <fstream>
#include <iomanip>
#include <sstream>

#include "dtm/algo/validate.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/tin_file.hpp"
#include "support/contour_terrain.hpp"
#include "support/terrain_fixtures.hpp"
#include "support/test_support.hpp"

namespace dtm {
namespace {

using test::run_dtm;
using test::RunResult;
using test::ScratchDir;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

/// Writes random points (x y z per line, full precision) and returns the path.
std::filesystem::path write_points(const ScratchDir& dir, std::size_t count, std::uint32_t seed) {
    std::ostringstream text;
    text << std::setprecision(17);
    for (const Point3& p : test::random_points(count, seed, test::sjtsk_e, test::sjtsk_n)) {
        text << p.x << ' ' << p.y << ' ' << p.z << '\n';
    }
    const auto path = dir / "points.xyz";
    test::write_file(path, text.str());
    return path;
}

const std::string river = "points-breaklines-pputils-hurdville/";

/// `dtm tin` on the river survey's points, boundary and hole seeds, with the lines given by
/// @p lines_option and @p extra options, writing @p out.
RunResult run_river_survey(const char* lines_option,
                           const char* lines_file,
                           std::vector<std::string> extra,
                           const std::filesystem::path& out) {
    std::vector<std::string> args{
        "tin",        test::shared_data_path(river + "nodes.csv").string(),
        lines_option, test::shared_data_path(river + lines_file).string(),
        "--boundary", test::shared_data_path(river + "boundary.csv").string(),
        "--holes",    test::shared_data_path(river + "holes.csv").string(),
        "--check",    "--stats",
        "-o",         out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_dtm(args);
}

TEST(TinCli, RiverSurveyWithBoundaryAndHoleSeedsMatchesTrianglesCounts) {
    if (!test::shared_data_available(river + "nodes.csv")) GTEST_SKIP() << "shared data absent";
    ScratchDir dir;
    const RunResult r =
        run_river_survey("--soft-breaklines", "lines.csv", {"--snap", "0.001"}, dir / "h.ply");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // 5,552 points (124 duplicate positions) + 3,805 line + 1,417 boundary vertices snapped onto
    // them: 5,428 distinct positions. Triangle's reference CDT of the same survey has 5,422
    // vertices and 9,141 triangles; its pre-processing dropped 6 points that sit 2-6 mm from a
    // line vertex, which accounts for the few extra triangles here.
    EXPECT_TRUE(contains(r.out, "\"vertices\": 5428")) << r.out;
    const io::LoadedTin tin = io::read_tin_ply(dir / "h.ply");
    EXPECT_NEAR(static_cast<double>(tin.tin.triangles.size()), 9141.0, 20.0);
    EXPECT_TRUE(verify_topology(tin.tin).ok()) << verify_topology(tin.tin).text();
    EXPECT_TRUE(verify_constrained_delaunay(tin.tin).ok());
}

TEST(TinCli, RiverSurveyWith3dBreaklinesPassesTheCheckWithoutSnapping) {
    // lines3d.csv ends with the boundary ring again, rounded to millimetres, so it runs in and out
    // of the boundary by fractions of a millimetre: the pieces outside are clipped with the
    // outside triangles, and --check requires the breaklines only where they lie on the surface.
    if (!test::shared_data_available(river + "lines3d.csv")) GTEST_SKIP() << "shared data absent";
    ScratchDir dir;
    const RunResult r = run_river_survey("--breaklines", "lines3d.csv", {"-q"}, dir / "h.ply");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(contains(r.out, "\"intersections\": 0,")) << r.out;  // the ring crossings
}

TEST(TinCli, OutputIsByteIdenticalForEveryThreadAndTileCount) {
    ScratchDir dir;
    const auto points = write_points(dir, 50000, 3);
    std::string reference;
    for (const char* tiles : {"1", "2", "7", "64"}) {
        for (const char* threads : {"1", "2"}) {
            const auto out = dir / (std::string("t") + tiles + "_" + threads + ".ply");
            const RunResult r = run_dtm({"tin", points.string(), "-o", out.string(), "--tiles",
                                         tiles, "--threads", threads, "-q"});
            ASSERT_EQ(r.exit_code, 0) << r.err;
            const std::string bytes = test::read_file(out);
            if (reference.empty()) reference = bytes;
            EXPECT_TRUE(bytes == reference) << "tiles " << tiles << " threads " << threads;
        }
    }
}

TEST(TinCli, StatsPrintOneJsonObjectWithCountsAndTimings) {
    ScratchDir dir;
    const auto points = write_points(dir, 1000, 4);
    const RunResult r =
        run_dtm({"tin", points.string(), "-o", (dir / "t.ply").string(), "--stats"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* key :
         {"\"points_in\": 1000", "\"duplicates_merged\": 0", "\"vertices\": 1000",
          "\"triangles\":", "\"constrained_edges\": 0", "\"intersections\": 0",
          "\"read\":", "\"triangulate\":", "\"constrain\":", "\"write\":", "\"total\":"}) {
        EXPECT_TRUE(contains(r.out, key)) << key << " missing in " << r.out;
    }
}

TEST(TinCli, ContourLinesWithZFieldLoseTheirFlatTrianglesUnlessAskedNotTo) {
    ScratchDir dir;
    std::ostringstream json;
    json << std::setprecision(12) << R"({"type": "FeatureCollection", "crs": {"type": "name",)"
         << R"( "properties": {"name": "urn:ogc:def:crs:EPSG::5514"}}, "features": [)";
    const TerrainInput contours = test::contour_terrain_input(5.0, 2.0);
    for (std::size_t i = 0; i < contours.breaklines.size(); ++i) {
        const Polyline& line = contours.breaklines[i];
        json << (i ? "," : "") << R"({"type": "Feature", "properties": {"ELEV": )"
             << line.points[0].z << R"(}, "geometry": {"type": "LineString", "coordinates": [)";
        for (std::size_t k = 0; k <= line.points.size(); ++k) {
            if (k == line.points.size() && !line.closed) break;
            const Point3& p = line.points[k % line.points.size()];
            json << (k ? "," : "") << '[' << p.x << ',' << p.y << ']';
        }
        json << "]}}";
    }
    json << "]}";
    const auto path = dir / "contours.geojson";
    test::write_file(path, json.str());
    const RunResult fixed = run_dtm({"tin", path.string(), "--z-field", "ELEV", "-o",
                                     (dir / "a.ply").string(), "--check", "--stats"});
    ASSERT_EQ(fixed.exit_code, 0) << fixed.err;
    EXPECT_TRUE(contains(fixed.out, "\"contour_flats\": {\"flat_before\": ")) << fixed.out;
    const RunResult summary =
        run_dtm({"tin", path.string(), "--z-field", "ELEV", "-o", (dir / "b.ply").string()});
    ASSERT_EQ(summary.exit_code, 0) << summary.err;
    EXPECT_TRUE(contains(summary.err, "dtm tin: contour flats: ")) << summary.err;
    const RunResult kept =
        run_dtm({"tin", path.string(), "--z-field", "ELEV", "--no-contours-fix-flats", "-o",
                 (dir / "c.ply").string(), "--stats"});
    ASSERT_EQ(kept.exit_code, 0) << kept.err;
    EXPECT_FALSE(contains(kept.out, "contour_flats")) << kept.out;
    const RunResult both = run_dtm({"tin", path.string(), "--contours-fix-flats",
                                    "--no-contours-fix-flats", "-o", (dir / "d.ply").string()});
    EXPECT_EQ(both.exit_code, 2);
}

TEST(TinCli, ReportListsEveryMergedDuplicate) {
    ScratchDir dir;
    test::write_file(dir / "p.xyz", "0 0 1\n10 0 2\n0 10 3\n10 0 5\n10 10 4\n0 0 9\n");
    const RunResult r =
        run_dtm({"tin", (dir / "p.xyz").string(), "-o", (dir / "t.ply").string(), "--duplicates",
                 "max", "--report", (dir / "r.json").string(), "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string report = test::read_file(dir / "r.json");
    EXPECT_TRUE(contains(report, "\"duplicates_merged\": 2")) << report;
    EXPECT_TRUE(contains(report, "\"kept_input\": 1, \"merged_input\": 3, \"kept\": [10, 0, 5]"))
        << report;
}

TEST(TinCli, CollinearInputIsExitTwoAndWritesNothing) {
    ScratchDir dir;
    test::write_file(dir / "p.xyz", "0 0 1\n1 1 1\n2 2 1\n3 3 1\n");
    const auto out = dir / "t.ply";
    const RunResult r = run_dtm({"tin", (dir / "p.xyz").string(), "-o", out.string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "collinear")) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(TinCli, MalformedLineIsExitTwoNamingTheLineAndKeepsTheOldOutput) {
    ScratchDir dir;
    test::write_file(dir / "p.xyz", "0 0 1\n10 0 2\n0 10 abc\n10 10 4\n");
    const auto out = dir / "t.ply";
    test::write_file(out, "previous good file");
    const RunResult r = run_dtm({"tin", (dir / "p.xyz").string(), "-o", out.string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "p.xyz:3")) << r.err;
    EXPECT_EQ(test::read_file(out), "previous good file");
}

}  // namespace
}  // namespace dtm
