// SPDX-License-Identifier: MIT
// products::build as a library call: every product in the folder in the report's order, the
// stages timed, options in the caller's wording, and nothing changed by a failed or cancelled run.
#include "dtm/products/build.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/products/rules.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;

namespace {

/// A 30 x 30 survey of a smooth hill, in local metres.
dtm::io::LoadOptions survey(const dtm::test::ScratchDir& dir)
{
    std::string text = "x,y,z\n";
    for (int j = 0; j < 30; ++j) {
        for (int i = 0; i < 30; ++i) {
            const double x = 2.0 * i + 0.3 * std::sin(j);
            const double y = 2.0 * j + 0.3 * std::cos(i);
            text += std::to_string(x) + "," + std::to_string(y) + "," +
                    std::to_string(100.0 + 5.0 * std::sin(x / 15.0) * std::cos(y / 20.0)) + "\n";
        }
    }
    dtm::test::write_file(dir / "points.csv", text);
    dtm::io::LoadOptions options;
    options.files.push_back({dir / "points.csv", dtm::io::InputRole::points});
    return options;
}

std::vector<std::string> names_in(const fs::path& folder)
{
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

TEST(Build, WritesEveryProductAndReportsThemInOrder)
{
    const dtm::test::ScratchDir dir;
    const dtm::products::BuildReport report = dtm::products::build(survey(dir), dir / "out");
    const std::vector<std::string> expected{"tin.ply",       "tin.2dm",       "surface.vtp",
                                            "dem.tif",       "hillshade.tif", "contours.gpkg",
                                            "dtm.qgs",       "report.json"};
    EXPECT_EQ(report.outputs, expected);
    std::vector<std::string> sorted = expected;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(names_in(dir / "out"), sorted);
    EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"out", "points.csv"}));
    std::vector<std::string> stages;
    for (const auto& t : report.timings) stages.push_back(t.stage);
    EXPECT_EQ(stages, (std::vector<std::string>{"read", "triangulate", "write_tin", "dem",
                                                "contours", "project"}));
    EXPECT_EQ(report.accounting.survey_points.total, 900u);
    EXPECT_EQ(report.surface.vertex_count, 900u);
    EXPECT_GT(report.contour_lines, 0u);
    EXPECT_GT(report.dem.cols, 0u);
    EXPECT_EQ(report.cell_rule, dtm::products::default_cell_rule);
}

TEST(Build, GivenCellAndIntervalAreReportedInTheCallersWording)
{
    const dtm::test::ScratchDir dir;
    dtm::products::BuildOptions options;
    options.cell = 0.5;
    options.interval = 0.25;
    const auto plain = dtm::products::build(survey(dir), dir / "a", options);
    EXPECT_EQ(plain.cell_rule, "given (`cell`)");
    EXPECT_EQ(plain.interval_rule, "given (`interval`)");
    EXPECT_EQ(plain.dem.cell, 0.5);
    EXPECT_EQ(plain.contour_interval, 0.25);
    options.wording = [](std::string_view text) {
        std::string s(text);
        s.replace(s.find('`'), s.rfind('`') - s.find('`') + 1, "--option");
        return s;
    };
    const auto worded = dtm::products::build(survey(dir), dir / "b", options);
    EXPECT_EQ(worded.cell_rule, "given (--option)");
    EXPECT_NE(dtm::test::read_file(dir / "b" / "report.json").find("given (--option)"),
              std::string::npos);
}

TEST(Build, CancelledRunLeavesTheFolderAsItWas)
{
    const dtm::test::ScratchDir dir;
    fs::create_directories(dir / "out");
    dtm::test::write_file(dir / "out" / "tin.ply", "earlier result");
    const dtm::Progress progress([](double, std::string_view what) { return what != "contour"; });
    EXPECT_THROW((void)dtm::products::build(survey(dir), dir / "out", {}, progress),
                 dtm::Cancelled);
    EXPECT_EQ(names_in(dir / "out"), std::vector<std::string>{"tin.ply"});
    EXPECT_EQ(dtm::test::read_file(dir / "out" / "tin.ply"), "earlier result");
    EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"out", "points.csv"}));
}

TEST(Build, OutputFolderThatIsAFileIsAnOptionError)
{
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "out", "a file");
    try {
        (void)dtm::products::build(survey(dir), dir / "out");
        FAIL() << "no exception";
    } catch (const dtm::OptionError& e) {
        EXPECT_EQ(e.field(), "out_dir");
        EXPECT_NE(std::string(e.what()).find("is a file, not a folder"), std::string::npos);
    }
    EXPECT_EQ(dtm::test::read_file(dir / "out"), "a file");
}

}  // namespace
