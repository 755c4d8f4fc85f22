// SPDX-License-Identifier: MIT
// Spot heights from labels and markers, crosses, and heights along lines by pen role.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "io/formats/hpgl/hpgl_plan.hpp"
#include "support/hpgl_plan_generator.hpp"

namespace {

using dtm::Point2;
using dtm::io::PenRole;
using dtm::io::hpgl::build_terrain_plan;
using dtm::io::hpgl::parse_height_label;
using dtm::io::hpgl::Plot;
using dtm::io::hpgl::TerrainPlan;

TerrainPlan plan_of(std::string_view bytes, const dtm::io::HpglOptions& options = {}) {
    Plot plot = dtm::io::hpgl::plot_hpgl(bytes, "test.plt", {});
    return build_terrain_plan(plot, options);
}

bool has_warning(const TerrainPlan& plan, std::string_view text) {
    return std::any_of(plan.warnings.begin(), plan.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

TEST(HpglHeightLabel, DecimalNumbersWithPointOrCommaAreHeights) {
    EXPECT_EQ(parse_height_label("312.45", false), 312.45);
    EXPECT_EQ(parse_height_label("312,45", false), 312.45);
    EXPECT_EQ(parse_height_label(" -3.5\r\n", false), -3.5);
    EXPECT_EQ(parse_height_label("0.07", false), 0.07);
}

TEST(HpglHeightLabel, IntegersOnlyWhenAllowedAndTextNever) {
    EXPECT_FALSE(parse_height_label("312", false));
    EXPECT_EQ(parse_height_label("312", true), 312.0);
    for (const char* text : {"", ".", "1:500", "12.3.4", "312.45 m", "P 12", "1e3", "--1.0"}) {
        EXPECT_FALSE(parse_height_label(text, true)) << text;
    }
}

TEST(HpglSpotHeights, CrossCentreIsTheMarker) {
    // A cross of two 2 mm strokes centred on 1000,1000; the label 1.5 mm away.
    const auto plan =
        plan_of("IN;SP1;PU960,1000;PD1040,1000;PU1000,960;PD1000,1040;PU;PA1060,1040;LB250.10\x03");
    ASSERT_EQ(plan.spots.size(), 1u);
    EXPECT_TRUE(plan.spots[0].on_marker);
    EXPECT_EQ(plan.spots[0].at, (Point2{1000, 1000}));
    EXPECT_EQ(plan.spots[0].z, 250.1);
    EXPECT_EQ(plan.crosses, 1u);
}

TEST(HpglSpotHeights, CrossDrawnAsArmsFromItsCentreIsAMarker) {
    const auto plan = plan_of(
        "IN;SP1;PU500,500;PD540,500;PU500,500;PD460,500;PU500,500;PD500,540;PU500,500;"
        "PD500,460;PU;PA560,540;LB12.5\x03");
    EXPECT_EQ(plan.crosses, 1u);
    ASSERT_EQ(plan.spots.size(), 1u);
    EXPECT_EQ(plan.spots[0].at, (Point2{500, 500}));
}

TEST(HpglSpotHeights, CrossWhoseStrokeTheNextMoveExtendedIsStillFound) {
    // PE leaves the pen down after a drawn pair, so "PA" to the label draws on from the cross.
    using dtm::test::encode_pe_number;
    const std::string cross = "PE<=" + encode_pe_number(960) + encode_pe_number(1000) +
                              encode_pe_number(80) + encode_pe_number(0) + "<" +
                              encode_pe_number(-40) + encode_pe_number(-40) + encode_pe_number(0) +
                              encode_pe_number(80) + ";";
    const auto plan = plan_of("IN;SP1;" + cross + "PA1060,1040;LB250.10\x03");
    EXPECT_EQ(plan.crosses, 1u);
    ASSERT_EQ(plan.spots.size(), 1u);
    EXPECT_EQ(plan.spots[0].at, (Point2{1000, 1000}));
}

TEST(HpglSpotHeights, CornersAndLongStrokesAreNoCrosses) {
    const auto plan =
        plan_of("IN;SP1;PU0,0;PD80,0;PU0,0;PD0,80;PU2000,0;PD3000,0;PU2500,-500;PD2500,500;");
    EXPECT_EQ(plan.crosses, 0u);
}

TEST(HpglSpotHeights, NearestMarkerWinsAndServesOneLabel) {
    // Two symbol markers; label A is nearer to the first, label B too but must take the second.
    const auto plan = plan_of("IN;SP1;SM*;PA0,0;PA100,0;SM;PA10,0;LB1.5\x03PA20,0;LB2.5\x03");
    ASSERT_EQ(plan.spots.size(), 2u);
    EXPECT_EQ(plan.spots[0].at, (Point2{0, 0}));
    EXPECT_EQ(plan.spots[1].at, (Point2{100, 0}));
}

TEST(HpglSpotHeights, CrowdedMarkersFollowThePlansLabelOffset) {
    // Every label 1 mm right, 0.5 mm up of its symbol (samples/sjtsk/plan_500.hpgl, byte 129834):
    // the label of the symbol at 877,4918 is nearer to the symbol at 956,4937 than to its own.
    std::string bytes = "IN;SP1;";
    for (const auto& [x, y, z] : {std::tuple{956, 4937, "314.77"}, std::tuple{954, 5018, "314.78"},
                                  std::tuple{877, 4918, "314.69"}, std::tuple{3000, 3000, "300.00"},
                                  std::tuple{4000, 3000, "301.00"}}) {
        bytes += "SM*;PU" + std::to_string(x) + "," + std::to_string(y) + ";SM;PU" +
                 std::to_string(x + 40) + "," + std::to_string(y + 20) + ";LB" + z + "\x03";
    }
    const auto plan = plan_of(bytes);
    ASSERT_EQ(plan.spots.size(), 5u);
    EXPECT_EQ(plan.labels_without_marker, 0u);
    EXPECT_EQ(plan.spots[0].at, (Point2{956, 4937}));
    EXPECT_EQ(plan.spots[1].at, (Point2{954, 5018}));
    EXPECT_EQ(plan.spots[2].at, (Point2{877, 4918}));
}

TEST(HpglSpotHeights, LabelWithoutMarkerKeepsItsPositionAndIsCounted) {
    const auto plan = plan_of("IN;SP1;PA0,0;CI10;PA500,500;LB7.25\x03");
    ASSERT_EQ(plan.spots.size(), 1u);
    EXPECT_FALSE(plan.spots[0].on_marker);
    EXPECT_EQ(plan.spots[0].at, (Point2{500, 500}));
    EXPECT_EQ(plan.labels_without_marker, 1u);
    EXPECT_TRUE(has_warning(plan, "1 height labels have no marker"));
}

TEST(HpglSpotHeights, MarkerRadiusIsMillimetresOnPaper) {
    dtm::io::HpglOptions options;
    options.marker_radius_mm = 1.0;  // 40 plotter units
    const auto near = plan_of("IN;SP1;PA0,0;CI10;PA39,0;LB1.0\x03", options);
    const auto far = plan_of("IN;SP1;PA0,0;CI10;PA41,0;LB1.0\x03", options);
    EXPECT_TRUE(near.spots[0].on_marker);
    EXPECT_FALSE(far.spots[0].on_marker);
}

TEST(HpglSpotHeights, VerticesOfAPointsPenAreMarkers) {
    dtm::io::HpglOptions options;
    options.pens[5] = PenRole::points;
    const auto plan =
        plan_of("IN;SP5;PU0,0;PD;PU;PA400,0;PD;PA410,0;PU;SP1;PA20,20;LB3.0\x03PA430,20;LB4.0\x03",
                options);
    ASSERT_EQ(plan.spots.size(), 2u);
    EXPECT_TRUE(plan.spots[0].on_marker);
    EXPECT_TRUE(plan.spots[1].on_marker);
    EXPECT_EQ(plan.spots[1].at, (Point2{410, 0}));
}

TEST(HpglLineHeights, VerticesTakeSpotHeightsAndInterpolateByDistance) {
    dtm::io::HpglOptions options;
    options.pens[2] = PenRole::breakline;
    // Spot heights at 0,0 (10.0) and 1000,0 (20.0); the line runs from -500 to 1500 through them.
    const auto plan = plan_of(
        "IN;SP1;PA0,0;CI10;PA40,40;LB10.0\x03PA1000,0;CI10;PA1040,40;LB20.0\x03"
        "SP2;PU-500,0;PD0,0,250,0,1000,0,1500,0;",
        options);
    ASSERT_EQ(plan.lines.size(), 1u);
    const auto& p = plan.lines[0].points;
    ASSERT_EQ(p.size(), 5u);
    EXPECT_EQ(plan.lines[0].role, PenRole::breakline);
    EXPECT_EQ(plan.lines[0].height_vertices, 2u);
    EXPECT_EQ(p[0].z, 10.0);  // before the first: its height
    EXPECT_EQ(p[1].z, 10.0);
    EXPECT_DOUBLE_EQ(p[2].z, 12.5);
    EXPECT_EQ(p[3].z, 20.0);
    EXPECT_EQ(p[4].z, 20.0);
}

TEST(HpglLineHeights, ClosedRingInterpolatesAroundTheClosure) {
    dtm::io::HpglOptions options;
    options.pens[4] = PenRole::hole;
    const auto plan = plan_of(
        "IN;SP1;PA0,0;CI10;PA40,40;LB10.0\x03PA1000,0;CI10;PA1040,40;LB20.0\x03"
        "SP4;PU0,0;PD1000,0,1000,1000,0,1000,0,0;",
        options);
    ASSERT_EQ(plan.lines.size(), 1u);
    const auto& line = plan.lines[0];
    EXPECT_TRUE(line.closed);
    ASSERT_EQ(line.points.size(), 4u);                      // the repeated start is dropped
    EXPECT_DOUBLE_EQ(line.points[2].z, 20.0 - 10.0 / 3.0);  // 1000 of 3000 back towards 10.0
    EXPECT_DOUBLE_EQ(line.points[3].z, 10.0 + 10.0 / 3.0);
}

TEST(HpglLineHeights, BreaklineWithoutSpotHeightsBecomesSoft) {
    dtm::io::HpglOptions options;
    options.pens[2] = PenRole::breakline;
    const auto plan =
        plan_of("IN;SP1;PA0,0;CI10;PA40,40;LB10.0\x03SP2;PU5000,5000;PD6000,5000;", options);
    ASSERT_EQ(plan.lines.size(), 1u);
    EXPECT_EQ(plan.lines[0].role, PenRole::soft_breakline);
    EXPECT_TRUE(std::isnan(plan.lines[0].points[0].z));  // no height: the triangulator computes it
    EXPECT_TRUE(has_warning(plan, "made soft"));
}

TEST(HpglLineHeights, OpenBoundaryIsClosedWithAWarningAndUnnamedPensAreCounted) {
    dtm::io::HpglOptions options;
    options.pens[3] = PenRole::boundary;
    const auto plan = plan_of("IN;SP3;PU0,0;PD1000,0,1000,1000;SP6;PU0,0;PD5,5;", options);
    ASSERT_EQ(plan.lines.size(), 1u);
    EXPECT_TRUE(plan.lines[0].closed);
    EXPECT_TRUE(has_warning(plan, "not a closed ring"));
    EXPECT_TRUE(has_warning(plan, "no spot height on its vertices"));
    EXPECT_TRUE(std::isnan(plan.lines[0].points[0].z));
    EXPECT_EQ(plan.ignored_lines, 1u);
    EXPECT_TRUE(has_warning(plan, "pen:lines 6:1"));
}

}  // namespace
