// SPDX-License-Identifier: MIT
// `dtm map` on the bundled S-JTSK sample: the sheet at 1:500 with the extent asked for (pdfinfo:
// extent / scale), georeferenced in EPSG:5514 (gdalinfo), every label of the report found by
// pdftotext; bad requests exit with 2 and say why, leaving no file.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "support/pdf_tools.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

fs::path sample_dir() { return fs::path(DTM_TEST_DATA_DIR) / ".." / ".." / "samples" / "sjtsk"; }

std::vector<std::string> map_args(const fs::path& out, std::vector<std::string> extra) {
    const fs::path s = sample_dir();
    std::vector<std::string> args{"map",
                                  (s / "points.csv").string(),
                                  "--breaklines",
                                  (s / "breaklines.shp").string(),
                                  "--boundary",
                                  (s / "boundary.shp").string(),
                                  "--holes",
                                  (s / "building.shp").string(),
                                  "--crs",
                                  "EPSG:5514",
                                  "--skip-bad-lines",
                                  "-o",
                                  out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

TEST(MapCommand, SheetAtScaleGeoreferencedWithItsLabelsAndReport) {
    dtm::test::ScratchDir dir;
    const fs::path pdf = dir / "map.pdf";
    const fs::path report = dir / "map.json";
    // 200 x 140 m at 1:500: 400 x 280 mm
    const auto r = dtm::test::run_dtm(map_args(
        pdf, {"--scale", "500", "--extent", "-750280,-1050190,-750080,-1050050", "--title",
              "Horní Lhota", "--vertical-datum", "Bpv", "--report", report.string(), "-q"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(fs::exists(pdf));
    const std::string json = dtm::test::read_file(report);
    EXPECT_NE(json.find("\"georeferenced\": true"), std::string::npos) << json;
    EXPECT_NE(json.find("\"width_mm\": 400"), std::string::npos) << json;
    EXPECT_NE(json.find("\"height_mm\": 280"), std::string::npos) << json;
    if (!dtm::test::have_tool("pdfinfo") || !dtm::test::have_tool("pdftotext")) {
        GTEST_SKIP() << "no poppler-utils";
    }
    const auto [w, h] = dtm::test::pdf_page_mm(pdf);
    EXPECT_NEAR(w, 400.0, 0.5);
    EXPECT_NEAR(h, 280.0, 0.5);
    const std::vector<std::string> words = dtm::test::pdf_words(pdf);
    const std::multiset<std::string> found(words.begin(), words.end());
    // every label text of the report is a word of the page
    std::size_t labels = 0;
    for (std::size_t at = json.find("\"text\": \""); at != std::string::npos;
         at = json.find("\"text\": \"", at + 1)) {
        const std::size_t begin = at + 9;
        const std::string text = json.substr(begin, json.find('"', begin) - begin);
        EXPECT_GT(found.count(text), 0U) << text;
        ++labels;
    }
    EXPECT_GT(labels, 3U);
    EXPECT_GT(found.count("Horní"), 0U);
    EXPECT_GT(found.count("Bpv"), 0U);
    if (!dtm::test::have_tool("gdalinfo")) GTEST_SKIP() << "no gdalinfo";
    const std::string info = dtm::test::command_output("gdalinfo '" + pdf.string() + "'");
    EXPECT_NE(info.find("ID[\"EPSG\",5514]]"), std::string::npos) << info;
    EXPECT_NE(info.find("NEATLINE=POLYGON ((-750280 -1050050,-750280 -1050190,-750080 "
                        "-1050190,-750080 -1050050,-750280 -1050050))"),
              std::string::npos)
        << info;
}

TEST(MapCommand, BadRequestsExitWithTwoAndSayWhy) {
    dtm::test::ScratchDir dir;
    const fs::path pdf = dir / "map.pdf";
    auto r = dtm::test::run_dtm(map_args(pdf, {"--scale", "50", "-q"}));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("larger than A0"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("1:250 fits A0"), std::string::npos) << r.err;  // what would fit
    r = dtm::test::run_dtm(map_args(pdf, {"--scale", "500", "--extent", "1,2,1,5", "-q"}));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("extent is empty"), std::string::npos) << r.err;
    r = dtm::test::run_dtm(map_args(pdf, {"--scale", "500", "--spot-heights", "many", "-q"}));
    EXPECT_EQ(r.exit_code, 2);
    r = dtm::test::run_dtm(map_args(pdf, {"--scale", "500", "--paper", "A7", "-q"}));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("A4, A3"), std::string::npos) << r.err;
    r = dtm::test::run_dtm(
        map_args(dir / "map.svg", {"--scale", "500", "--paper", "A4", "--sheets", "-q"}));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("need a PDF"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(pdf));
    EXPECT_FALSE(fs::exists(dir / "map.svg"));
}

TEST(MapCommand, SummaryCountsLabelsAndSpotHeights) {
    dtm::test::ScratchDir dir;
    const auto r =
        dtm::test::run_dtm(map_args(dir / "map.png", {"--scale", "1000", "--dpi", "60"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("contour labels placed"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("spot heights"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir / "map.png"));
}

}  // namespace
