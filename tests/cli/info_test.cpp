// SPDX-License-Identifier: MIT
// `dtm info`: JSON and table output, every input kind, exit codes on bad input.
#include <gtest/gtest.h>

#include <string>

#include "support/test_support.hpp"

namespace {

using dtm::test::run_dtm;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(CliInfo, JsonListsEveryInputWithItsCounts) {
    const auto points = dtm::test::data_path("readers/czech_list.csv").string();
    const auto lines = dtm::test::data_path("readers/polylines.csv").string();
    const auto r = run_dtm({"info", points, "--breaklines", lines, "--crs", "EPSG:5514", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("{\"inputs\": [", 0), 0u) << r.out;
    EXPECT_TRUE(contains(r.out, "\"path\": \"" + points + "\"")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"crs\": \"EPSG:5514\"")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"points\": 4,")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"breaklines\": 2, \"breakline_vertices\": 6,")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"bbox\": [-745130.1, -1045123.12, -745118.75, -1045110.5]"))
        << r.out;
    EXPECT_TRUE(contains(r.out, "\"z_range\": [312.2, 313.05]")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"duplicates\": 0, \"skipped_lines\": 0")) << r.out;
}

TEST(CliInfo, TableShowsSkippedLinesAndWarnings) {
    const auto bad = dtm::test::data_path("readers/malformed.csv").string();
    const auto r = run_dtm({"info", bad, "--skip-bad-lines"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "skipped lines      2")) << r.out;
    EXPECT_TRUE(contains(r.out, "skipped line 4:")) << r.out;
}

TEST(CliInfo, BadLineExitsTwoWithLocation) {
    const auto bad = dtm::test::data_path("readers/malformed.csv").string();
    const auto r = run_dtm({"info", bad});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, bad + ":4:11: expected a number")) << r.err;
    EXPECT_TRUE(r.out.empty());
}

TEST(CliInfo, MissingFileIsAUsageError) {
    const auto r = run_dtm({"info", "/nonexistent/points.csv"});
    EXPECT_EQ(r.exit_code, 2);
}

TEST(CliInfo, HurdvilleSurveyWithBoundaryAndHoles) {
    const std::string d = "points-breaklines-pputils-hurdville/";
    if (!dtm::test::shared_data_available(d + "nodes.csv")) GTEST_SKIP();
    const auto p = [&](const char* f) { return dtm::test::shared_data_path(d + f).string(); };
    const auto r = run_dtm({"info", p("nodes.csv"), "--soft-breaklines", p("lines.csv"),
                            "--boundary", p("boundary.csv"), "--holes", p("holes.csv"), "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "\"points\": 5552,")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"duplicates\": 124,")) << r.out;
    // 3805 rows; the 84 closed lines do not repeat their first vertex
    EXPECT_TRUE(contains(r.out, "\"breaklines\": 156, \"breakline_vertices\": 3721,")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"boundaries\": 1,")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"holes\": 16,")) << r.out;
}

TEST(CliInfo, ShapefilesReportTheirPrjCrs) {
    const std::string f = "points-cz-sjtsk-jvf-dtm/derived/zps_points_pointz.shp";
    if (!dtm::test::shared_data_available(f)) GTEST_SKIP();
    const auto r = run_dtm({"info", dtm::test::shared_data_path(f).string(), "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "\"crs\": \"EPSG:5514\"")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"points\": 917,")) << r.out;
}

}  // namespace

namespace {

TEST(CliInputs, RepeatableRoleOptionsTakeOneFileEachAndLeavePositionalsAlone) {
    const auto lines = dtm::test::data_path("readers/polylines.csv").string();
    const auto points = dtm::test::data_path("readers/count_line.xyz").string();
    const auto r = run_dtm(
        {"info", "--breaklines", lines, points, "--holes", lines, "--holes", points, "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // order: positional points, then breaklines, then holes
    const auto first = r.out.find("\"path\": \"" + points +
                                  "\", \"format\": \"text\", \"crs\": "
                                  "null, \"points\": 3,");
    EXPECT_NE(first, std::string::npos) << r.out;
    EXPECT_TRUE(contains(r.out,
                         "\"points\": 0, \"triangles\": 0, \"breaklines\": 0, "
                         "\"breakline_vertices\": 0, \"boundaries\": 0, \"holes\": 3,"))
        << r.out;  // the point file given as --holes: 3 seeds
}

TEST(CliInputs, HurdvilleSurveyTriangulatesWithBoundaryAndHoles) {
    const std::string d = "points-breaklines-pputils-hurdville/";
    if (!dtm::test::shared_data_available(d + "nodes.csv")) GTEST_SKIP();
    const auto p = [&](const char* f) { return dtm::test::shared_data_path(d + f).string(); };
    dtm::test::ScratchDir dir;
    const auto out = (dir / "h.ply").string();
    const auto r = run_dtm({"tin", p("nodes.csv"), "--soft-breaklines", p("lines.csv"),
                            "--boundary", p("boundary.csv"), "--holes", p("holes.csv"), "--snap",
                            "0.001", "-q", "-o", out, "--stats"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "\"constrained_edges\":")) << r.out;
    EXPECT_FALSE(dtm::test::read_file(out).empty());
}

}  // namespace
