// SPDX-License-Identifier: MIT
// Delimited text reader: layout detection, located errors, polyline lists, real PDAL variants.
#include "dtm/io/formats/csv.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include <cmath>
#include <string>

#include "dtm/core/error.hpp"
#include "support/test_support.hpp"

namespace {

using dtm::io::InputFile;
using dtm::io::InputRole;
using dtm::io::LoadOptions;
using dtm::io::ReadResult;

ReadResult read(const std::filesystem::path& path, InputRole role = InputRole::points,
                LoadOptions options = {})
{
    return dtm::io::read_csv(InputFile{path, role}, options);
}

ReadResult parse(std::string_view text, InputRole role = InputRole::points,
                 LoadOptions options = {})
{
    return dtm::io::parse_csv_text(text, InputFile{"mem.csv", role}, options);
}

std::string error_of(std::string_view text, LoadOptions options = {})
{
    try {
        (void)parse(text, InputRole::points, options);
    } catch (const dtm::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(CsvReader, CzechListWithBomCrlfDecimalCommaAndQuotedCodes)
{
    const ReadResult r = read(dtm::test::data_path("readers/czech_list.csv"));
    ASSERT_EQ(r.terrain.points.size(), 4u);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].x, 1045123.12);  // by name: "X" is x, "Y" is y
    EXPECT_DOUBLE_EQ(r.terrain.points[0].y, 745123.45);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].z, 312.45);
    ASSERT_EQ(r.labels.ids.size(), 4u);
    EXPECT_EQ(r.labels.ids[1], "4002");
    EXPECT_EQ(r.labels.codes[1], "plot; dreveny");
    EXPECT_EQ(r.labels.codes[2], "");
    EXPECT_EQ(r.summary.skipped_lines, 0u);
}

TEST(CsvReader, HeaderlessListWithIntegerFirstColumnIsIdXYZ)
{
    const ReadResult r = read(dtm::test::data_path("readers/czech_list_noheader.txt"));
    ASSERT_EQ(r.terrain.points.size(), 4u);
    EXPECT_DOUBLE_EQ(r.terrain.points[3].x, 745118.75);
    EXPECT_DOUBLE_EQ(r.terrain.points[3].y, 1045112.25);
    EXPECT_DOUBLE_EQ(r.terrain.points[3].z, 312.20);
    EXPECT_EQ(r.labels.ids[3], "4004");
}

TEST(CsvReader, TabDelimiterWithDecimalComma)
{
    const ReadResult r = read(dtm::test::data_path("readers/tab_decimal_comma.txt"));
    ASSERT_EQ(r.terrain.points.size(), 3u);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].x, 100.5);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].y, 200.25);
    EXPECT_DOUBLE_EQ(r.terrain.points[2].z, 12.0);
}

TEST(CsvReader, QuotedHeaderNamesExtraColumnsAndCodes)
{
    const ReadResult r = read(dtm::test::data_path("readers/quoted_extra.csv"));
    ASSERT_EQ(r.terrain.points.size(), 3u);
    EXPECT_DOUBLE_EQ(r.terrain.points[1].x, 501.1);
    EXPECT_DOUBLE_EQ(r.terrain.points[1].y, 601.2);
    EXPECT_DOUBLE_EQ(r.terrain.points[1].z, 10.6);
    EXPECT_EQ(r.labels.codes[0], "TREE");
    EXPECT_EQ(r.labels.ids[2], "3");
}

TEST(CsvReader, PointCountFirstLineAndBlankRuns)
{
    const ReadResult r = read(dtm::test::data_path("readers/count_line.xyz"));
    ASSERT_EQ(r.terrain.points.size(), 3u);
    EXPECT_EQ(r.terrain.points[2], (dtm::Point3{7.0, 8.0, 9.0}));
    EXPECT_TRUE(r.summary.warnings.empty());
}

TEST(CsvReader, PointCountMismatchIsAWarning)
{
    const ReadResult r = parse("5\n1 2 3\n4 5 6\n");
    EXPECT_EQ(r.terrain.points.size(), 2u);
    ASSERT_EQ(r.summary.warnings.size(), 1u);
    EXPECT_NE(r.summary.warnings[0].find("declares 5"), std::string::npos);
}

TEST(CsvReader, ColumnsOptionOverridesTheOrder)
{
    LoadOptions options;
    options.columns = "id,y,x,z,code";
    const ReadResult r = parse("A;1,5;2,5;3,5;k\nB;4;5;6;\n", InputRole::points, options);
    ASSERT_EQ(r.terrain.points.size(), 2u);
    EXPECT_EQ(r.terrain.points[0], (dtm::Point3{2.5, 1.5, 3.5}));
    EXPECT_EQ(r.labels.ids[0], "A");
    EXPECT_EQ(r.labels.codes[0], "k");
}

TEST(CsvReader, CommentsSignsExponentsAndSemicolonHeader)
{
    const ReadResult r = parse("// exported\n# another comment\nE;N;Elev\n+1e2;-2.5E1;.5\n");
    ASSERT_EQ(r.terrain.points.size(), 1u);
    EXPECT_EQ(r.terrain.points[0], (dtm::Point3{100.0, -25.0, 0.5}));
}

TEST(CsvReader, BadNumberNamesFileLineColumnAndText)
{
    const std::string what = error_of("x,y,z\n1,2,3\n4,5,oops\n");
    EXPECT_NE(what.find("mem.csv:3:5:"), std::string::npos) << what;
    EXPECT_NE(what.find("'oops'"), std::string::npos) << what;
    EXPECT_NE(what.find("expected a number"), std::string::npos) << what;
}

TEST(CsvReader, ShortLineIsAnErrorNamingTheLine)
{
    const std::string what = error_of("x y z\n1 2 3\n4 5\n");
    EXPECT_NE(what.find("mem.csv:3:"), std::string::npos) << what;
    EXPECT_NE(what.find("expected at least 3 fields, found 2"), std::string::npos) << what;
}

TEST(CsvReader, InfinityAndNanAreNotNumbers)
{
    EXPECT_NE(error_of("1 2 inf\n").find("'inf'"), std::string::npos);
    EXPECT_NE(error_of("1 2 nan\n").find("'nan'"), std::string::npos);
}

TEST(CsvReader, SkipBadLinesCountsThemAndKeepsTheRest)
{
    LoadOptions options;
    options.skip_bad_lines = true;
    const ReadResult r = read(dtm::test::data_path("readers/malformed.csv"), InputRole::points,
                              options);
    EXPECT_EQ(r.terrain.points.size(), 4u);
    EXPECT_EQ(r.summary.skipped_lines, 2u);
    ASSERT_EQ(r.summary.warnings.size(), 2u);
    EXPECT_NE(r.summary.warnings[0].find("line 4:"), std::string::npos);
    EXPECT_NE(r.summary.warnings[1].find("line 6:"), std::string::npos);
}

TEST(CsvReader, MalformedFileFailsAtTheFirstBadLine)
{
    try {
        (void)read(dtm::test::data_path("readers/malformed.csv"));
        FAIL() << "expected an InputError";
    } catch (const dtm::InputError& e) {
        EXPECT_EQ(e.line(), 4u);
        EXPECT_EQ(e.column(), 11u);
        EXPECT_NE(std::string(e.what()).find("'abc'"), std::string::npos);
    }
}

TEST(CsvReader, UnterminatedQuoteIsLocated)
{
    try {
        (void)read(dtm::test::data_path("readers/unclosed_quote.csv"));
        FAIL() << "expected an InputError";
    } catch (const dtm::InputError& e) {
        EXPECT_EQ(e.line(), 3u);
        EXPECT_NE(std::string(e.what()).find("closing quote"), std::string::npos);
    }
}

TEST(CsvReader, PointsWithoutZColumnAreRejected)
{
    EXPECT_NE(error_of("x,y\n1,2\n").find("expected a z column"), std::string::npos);
}

TEST(CsvReader, UnknownColumnsWordIsRejected)
{
    LoadOptions options;
    options.columns = "x,y,depth";
    EXPECT_NE(error_of("1 2 3\n", options).find("'depth'"), std::string::npos);
}

TEST(CsvReader, EmptyFileIsAnError)
{
    EXPECT_NE(error_of("\n# only a comment\n").find("empty file"), std::string::npos);
}

/// A point list of about 12 MB (more than the parallel reader's chunk threshold): "id;Y;X;Z;code"
/// rows with comments, blank lines and CRLF ends, and bad rows at the given line numbers.
std::string large_point_list(const std::vector<std::size_t>& bad_lines)
{
    std::string text = "id;x;y;z;code\r\n";
    std::size_t line = 1;
    for (std::size_t i = 0; text.size() < (std::size_t{12} << 20); ++i) {
        ++line;
        if (std::find(bad_lines.begin(), bad_lines.end(), line) != bad_lines.end()) {
            text += "P" + std::to_string(i) + ";-750000.5;oops;301.25;X\r\n";
        } else if (i % 997 == 0) {
            text += "# comment\r\n";
        } else if (i % 991 == 0) {
            text += "\r\n";
        } else {
            text += "P" + std::to_string(i) + ";" + std::to_string(-750000.0 - 0.001 * static_cast<double>(i)) + ";" +
                    std::to_string(-1050000.0 + 0.002 * static_cast<double>(i)) + ";" + std::to_string(300 + i % 7) +
                    ";C" + std::to_string(i % 5) + "\r\n";
        }
    }
    return text;
}

ReadResult parse_with_threads(std::string_view text, int threads, LoadOptions options)
{
    tbb::task_arena arena(threads);
    return arena.execute([&] { return parse(text, InputRole::points, options); });
}

TEST(CsvReader, LargeFileParsedInParallelEqualsTheSequentialPass)
{
    LoadOptions skip;
    skip.skip_bad_lines = true;
    const std::string text = large_point_list({5, 90001, 180002, 250003});
    const ReadResult one = parse_with_threads(text, 1, skip);
    const ReadResult two = parse_with_threads(text, 2, skip);
    ASSERT_GT(one.terrain.points.size(), 200000u);
    ASSERT_EQ(one.terrain.points.size(), two.terrain.points.size());
    for (std::size_t i = 0; i < one.terrain.points.size(); ++i) {
        ASSERT_EQ(one.terrain.points[i].x, two.terrain.points[i].x) << "point " << i;
        ASSERT_EQ(one.terrain.points[i].y, two.terrain.points[i].y) << "point " << i;
        ASSERT_EQ(one.terrain.points[i].z, two.terrain.points[i].z) << "point " << i;
    }
    EXPECT_EQ(one.labels.ids, two.labels.ids);
    EXPECT_EQ(one.labels.codes, two.labels.codes);
    EXPECT_EQ(one.summary.skipped_lines, 4u);
    EXPECT_EQ(two.summary.skipped_lines, 4u);
    EXPECT_EQ(one.summary.warnings, two.summary.warnings);
    ASSERT_EQ(two.summary.warnings.size(), 4u);
    EXPECT_NE(two.summary.warnings[3].find("skipped line 250003:"), std::string::npos)
        << two.summary.warnings[3];
}

TEST(CsvReader, LargeFileParsedInParallelReportsTheFirstBadLine)
{
    // Bad rows in a late chunk and an early one: the error names the earlier line.
    const std::string text = large_point_list({240001, 120007});
    for (const int threads : {1, 2}) {
        try {
            (void)parse_with_threads(text, threads, {});
            ADD_FAILURE() << "no error with " << threads << " threads";
        } catch (const dtm::InputError& e) {
            EXPECT_NE(std::string(e.what()).find("mem.csv:120007:"), std::string::npos)
                << threads << " threads: " << e.what();
        }
    }
}

TEST(CsvReader, PolylinesGroupedByShapeIdClosingRepeatedFirstVertex)
{
    const ReadResult r = read(dtm::test::data_path("readers/polylines.csv"),
                              InputRole::breaklines);
    ASSERT_EQ(r.terrain.breaklines.size(), 2u);
    EXPECT_EQ(r.terrain.breaklines[0].points.size(), 3u);
    EXPECT_FALSE(r.terrain.breaklines[0].closed);
    EXPECT_EQ(r.terrain.breaklines[1].points.size(), 3u);
    EXPECT_TRUE(r.terrain.breaklines[1].closed);
    EXPECT_NE(r.terrain.breaklines[0].source.find("polylines.csv:2"), std::string::npos);
    ASSERT_EQ(r.summary.warnings.size(), 1u);  // shape 3 has one vertex
    EXPECT_NE(r.summary.warnings[0].find("too short"), std::string::npos);
}

TEST(CsvReader, SoftBreaklinesWithoutZCarryNaN)
{
    const ReadResult r = parse("1,0.5,0\n1,5,5.5\n2,1.5,1\n2,2,3\n", InputRole::soft_breaklines);
    ASSERT_EQ(r.terrain.soft_breaklines.size(), 2u);
    EXPECT_TRUE(std::isnan(r.terrain.soft_breaklines[0].points[0].z));
}

TEST(CsvReader, HolesWithoutLineIdAreSeeds)
{
    const ReadResult r = parse("10.5,20.5\n30,40\n", InputRole::holes);
    ASSERT_EQ(r.terrain.hole_seeds.size(), 2u);
    EXPECT_EQ(r.terrain.hole_seeds[1], (dtm::Point2{30.0, 40.0}));
    EXPECT_TRUE(r.terrain.holes.empty());
}

TEST(CsvReader, BoundaryWithoutLineIdIsOneClosedRingPerBlankSeparatedBlock)
{
    const ReadResult r = parse("0 0 1\n10 0 1\n10 10 1\n\n20 20 2\n30 20 2\n30 30 2\n",
                               InputRole::boundary);
    ASSERT_EQ(r.terrain.boundaries.size(), 2u);
    EXPECT_TRUE(r.terrain.boundaries[0].closed);
    EXPECT_EQ(r.terrain.boundaries[1].points.size(), 3u);
}

TEST(CsvReader, LatLonColumnsReportWgs84)
{
    const ReadResult r = read(dtm::test::data_path("readers/gnss_latlon.csv"));
    ASSERT_EQ(r.terrain.points.size(), 3u);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].x, 14.4214);  // x = longitude
    EXPECT_DOUBLE_EQ(r.terrain.points[0].y, 50.0875);
    EXPECT_EQ(r.crs_wkt, "EPSG:4326");
    EXPECT_EQ(r.labels.ids[1], "B");
}

TEST(CsvReader, GeometryColumnIsDetected)
{
    EXPECT_TRUE(dtm::io::csv_has_geometry_column("id,WKT\n1,\"POINT (1 2)\"\n"));
    EXPECT_FALSE(dtm::io::csv_has_geometry_column("id,x,y,z\n1,2,3,4\n"));
}

// Every PDAL text variant either parses to the right counts or fails with a located error.
struct Variant {
    const char* file;
    std::size_t points;  ///< 0: must fail with a located InputError
};

class PdalTextVariants : public ::testing::TestWithParam<Variant> {};

TEST_P(PdalTextVariants, ParsesToTheRightCountOrFailsLocated)
{
    const std::string rel = std::string("points-pdal-text-variants/") + GetParam().file;
    if (!dtm::test::shared_data_available(rel)) GTEST_SKIP() << "shared data absent: " << rel;
    const auto path = dtm::test::shared_data_path(rel);
    if (GetParam().points == 0) {
        try {
            (void)read(path);
            FAIL() << "expected an InputError";
        } catch (const dtm::InputError& e) {
            EXPECT_EQ(e.file(), path);
            EXPECT_GT(e.line(), 0u);
        }
        return;
    }
    const ReadResult r = read(path);
    EXPECT_EQ(r.terrain.points.size(), GetParam().points);
    for (const auto& p : r.terrain.points) EXPECT_TRUE(std::isfinite(p.z));
}

INSTANTIATE_TEST_SUITE_P(
    Files, PdalTextVariants,
    ::testing::Values(Variant{"autzen-bmx-largersample.txt", 103},
                      Variant{"autzen-point-format-3.txt", 106}, Variant{"autzen.pts", 10},
                      Variant{"badheader.txt", 0}, Variant{"crlf_test.txt", 10},
                      Variant{"data.xyz", 400}, Variant{"decimate_file_grid.txt", 81},
                      Variant{"missingheader.txt", 5}, Variant{"quoted.txt", 9},
                      Variant{"utm17_1.txt", 10}, Variant{"utm17_2.txt", 10},
                      Variant{"utm17_3.txt", 11}));

TEST(CsvReaderRealData, AutzenPointFormat3MapsXYZAmongColourColumns)
{
    const std::string rel = "points-pdal-text-variants/autzen-point-format-3.txt";
    if (!dtm::test::shared_data_available(rel)) GTEST_SKIP();
    const ReadResult r = read(dtm::test::shared_data_path(rel));
    ASSERT_FALSE(r.terrain.points.empty());
    EXPECT_EQ(r.terrain.points[0], (dtm::Point3{636083.30, 849398.65, 407.35}));
}

TEST(CsvReaderRealData, HurdvillePolylineAndSeedFiles)
{
    const std::string dir = "points-breaklines-pputils-hurdville/";
    if (!dtm::test::shared_data_available(dir + "lines.csv")) GTEST_SKIP();
    const auto p = [&](const char* f) { return dtm::test::shared_data_path(dir + f); };
    const ReadResult lines = read(p("lines.csv"), InputRole::soft_breaklines);
    EXPECT_EQ(lines.terrain.soft_breaklines.size(), 156u);
    std::size_t vertices = 0;
    for (const auto& l : lines.terrain.soft_breaklines) vertices += l.points.size() + l.closed;
    EXPECT_EQ(vertices, 3805u);
    const ReadResult lines3d = read(p("lines3d.csv"), InputRole::breaklines);
    EXPECT_EQ(lines3d.terrain.breaklines.size(), 157u);
    const ReadResult boundary = read(p("boundary.csv"), InputRole::boundary);
    ASSERT_EQ(boundary.terrain.boundaries.size(), 1u);
    EXPECT_TRUE(boundary.terrain.boundaries[0].closed);
    EXPECT_EQ(boundary.terrain.boundaries[0].points.size(), 1416u);  // 1417 rows, last repeats
    const ReadResult holes = read(p("holes.csv"), InputRole::holes);
    EXPECT_EQ(holes.terrain.hole_seeds.size(), 16u);
    const ReadResult nodes = read(p("nodes.csv"));
    EXPECT_EQ(nodes.terrain.points.size(), 5552u);
}

}  // namespace
