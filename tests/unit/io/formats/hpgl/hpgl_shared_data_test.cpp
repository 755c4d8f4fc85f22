// SPDX-License-Identifier: MIT
// Every real HP-GL file in the shared data set parses; label and line counts were checked by
// inspection (labels = ETX terminators in the file; pw.hpg draws 4 lines with each of 8 pens;
// test3-Model.PLT is one PE square). The UTF-8-mangled AutoCAD plot is an error with its offset.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/hpgl.hpp"
#include "io/formats/hpgl/hpgl_plot.hpp"
#include "support/test_support.hpp"

namespace {

using dtm::io::hpgl::Plot;

struct Expected {
    const char* file;
    std::size_t labels;
    std::size_t lines;
};

Plot plot_file(const std::string& relative, bool strict = true) {
    const auto path = dtm::test::shared_data_path(relative);
    dtm::io::hpgl::PlotOptions options;
    options.strict = strict;
    return dtm::io::hpgl::plot_hpgl(dtm::test::read_file(path), path, options);
}

class HpglSharedData : public testing::TestWithParam<Expected> {};

TEST_P(HpglSharedData, ParsesWithTheLabelsAndLinesItDraws) {
    if (!dtm::test::shared_data_available(GetParam().file)) GTEST_SKIP() << "shared data absent";
    const Plot plot = plot_file(GetParam().file);
    EXPECT_EQ(plot.labels.size(), GetParam().labels);
    EXPECT_EQ(plot.lines.size(), GetParam().lines);
    EXPECT_EQ(plot.problems, 0u);
}

TEST_P(HpglSharedData, ReaderReturnsNoTerrainWithoutPenRolesButSaysWhy) {
    if (!dtm::test::shared_data_available(GetParam().file)) GTEST_SKIP() << "shared data absent";
    const auto path = dtm::test::shared_data_path(GetParam().file);
    const auto result = dtm::io::read_hpgl({path, dtm::io::InputRole::points}, {});
    EXPECT_TRUE(result.terrain.breaklines.empty());
    const auto& w = result.summary.warnings;
    EXPECT_TRUE(std::any_of(w.begin(), w.end(),
                            [](const std::string& s) { return s.find("`hpgl.pens`") != s.npos; }));
}

INSTANTIATE_TEST_SUITE_P(Files,
                         HpglSharedData,
                         testing::Values(Expected{"hpgl-autocad-hpgl2/test1-Model.plt", 0, 1},
                                         Expected{"hpgl-autocad-hpgl2/test2a-Layout1.PLT", 0, 3},
                                         Expected{"hpgl-autocad-hpgl2/test3-Model.PLT", 0, 1},
                                         Expected{"hpgl-hp2xx/acad.hp", 0, 333},
                                         Expected{"hpgl-hp2xx/fill.plt", 16, 32},
                                         Expected{"hpgl-hp2xx/inter.hp", 0, 923},
                                         Expected{"hpgl-hp2xx/la.hp", 0, 34},
                                         Expected{"hpgl-hp2xx/pw.hpg", 0, 32},
                                         Expected{"hpgl-hp2xx/spectrum.plt", 60, 307},
                                         Expected{"hpgl-hp2xx/ul.hp", 21, 22},
                                         Expected{"hpgl-hp2xx/win_1.hp", 18, 149},
                                         Expected{"hpgl-instrument-plots/HP8595E-FM.hpgl", 47, 22},
                                         Expected{"hpgl-instrument-plots/R+S-analyzer.hpgl", 73,
                                                  47},
                                         Expected{"hpgl-instrument-plots/tektronix.hpgl", 0, 60}),
                         [](const testing::TestParamInfo<Expected>& param_info) {
                             std::string name = param_info.param.file;
                             for (char& c : name) {
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             }
                             return name;
                         });

TEST(HpglSharedData, AutocadSquareIsOnePeEncodedClosedSquare) {
    if (!dtm::test::shared_data_available("hpgl-autocad-hpgl2/test3-Model.PLT")) GTEST_SKIP();
    const Plot plot = plot_file("hpgl-autocad-hpgl2/test3-Model.PLT");
    ASSERT_EQ(plot.lines.size(), 1u);
    const auto& p = plot.lines[0].points;
    ASSERT_EQ(p.size(), 5u);
    EXPECT_EQ(p.front(), p.back());
    // 471 user units on a side; SC0,300 over IP0,0,1016,-1016: 1016/300 plotter units each.
    const double side = 471.0 * 1016.0 / 300.0;
    EXPECT_NEAR(std::abs(p[1].y - p[0].y), side, 1e-9);
    EXPECT_NEAR(std::abs(p[2].x - p[1].x), side, 1e-9);
}

TEST(HpglSharedData, PenWidthPlotDrawsFourLinesWithEachOfEightPens) {
    if (!dtm::test::shared_data_available("hpgl-hp2xx/pw.hpg")) GTEST_SKIP();
    const Plot plot = plot_file("hpgl-hp2xx/pw.hpg");
    std::array<int, 9> per_pen{};
    for (const auto& line : plot.lines) {
        ASSERT_GE(line.pen, 1);
        ASSERT_LE(line.pen, 8);
        ++per_pen[static_cast<std::size_t>(line.pen)];
        EXPECT_EQ(line.points.size(), 2u);
    }
    for (int pen = 1; pen <= 8; ++pen) EXPECT_EQ(per_pen[static_cast<std::size_t>(pen)], 4) << pen;
}

TEST(HpglSharedData, MangledAutocadPlotIsAnInputErrorNamingFileAndByte) {
    const std::string file = "hpgl-autocad-hpgl2/test-Model.PLT";
    if (!dtm::test::shared_data_available(file)) GTEST_SKIP();
    const auto path = dtm::test::shared_data_path(file);
    try {
        (void)dtm::io::read_hpgl({path, dtm::io::InputRole::points}, {});
        FAIL() << "no error";
    } catch (const dtm::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("test-Model.PLT"), std::string::npos) << what;
        EXPECT_NE(what.find("byte 130: invalid byte 0x80 in PE"), std::string::npos) << what;
        EXPECT_EQ(e.file(), path);
    }
}

TEST(HpglSharedData, MangledAutocadPlotIsReadWithWarningsWhenSkippingBadData) {
    const std::string file = "hpgl-autocad-hpgl2/test-Model.PLT";
    if (!dtm::test::shared_data_available(file)) GTEST_SKIP();
    dtm::io::ReadOptions options;
    options.skip_bad_lines = true;
    options.hpgl.pens = {{1, dtm::io::PenRole::soft_breakline}};
    const auto result = dtm::io::read_hpgl(
        {dtm::test::shared_data_path(file), dtm::io::InputRole::points}, options);
    EXPECT_GT(result.summary.skipped_lines, 0u);
    const auto& w = result.summary.warnings;
    EXPECT_TRUE(std::any_of(w.begin(), w.end(),
                            [](const std::string& s) { return s.rfind("byte 130: ", 0) == 0; }));
}

}  // namespace
