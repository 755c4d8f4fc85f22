// SPDX-License-Identifier: MIT
// Plotter state machine: scaling, relative moves, PE with user units, symbols, circles, arcs,
// joined strokes, pen 0, and label positions.
#include "io/formats/hpgl/hpgl_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/hpgl_plan_generator.hpp"

namespace {

using dtm::Point2;
using dtm::io::hpgl::MarkerKind;
using dtm::io::hpgl::Plot;

Plot plot(std::string_view bytes) { return dtm::io::hpgl::plot_hpgl(bytes, "test.plt", {}); }

TEST(HpglPlotter, ScaledUserUnitsMapOntoP1P2) {
    const Plot p = plot("IN;IP1000,2000,5000,4000;SC0,100,0,50;SP1;PU0,0;PD100,50;PR-50,0;");
    ASSERT_EQ(p.lines.size(), 1u);
    ASSERT_EQ(p.lines[0].points.size(), 3u);
    EXPECT_EQ(p.lines[0].points[0], (Point2{1000, 2000}));
    EXPECT_EQ(p.lines[0].points[1], (Point2{5000, 4000}));
    EXPECT_EQ(p.lines[0].points[2], (Point2{3000, 4000}));  // relative: -50 user units = -2000
}

TEST(HpglPlotter, PointFactorScalingAndScOffTurnsBackToPlotterUnits) {
    const Plot p = plot("IN;SC10,2,20,4,2;PU10,20;PD11,21;SC;PU0,0;PD5,5;");
    ASSERT_EQ(p.lines.size(), 2u);
    EXPECT_EQ(p.lines[0].points[0], (Point2{0, 0}));
    EXPECT_EQ(p.lines[0].points[1], (Point2{2, 4}));
    EXPECT_EQ(p.lines[1].points[1], (Point2{5, 5}));
}

TEST(HpglPlotter, PeCoordinatesAreUserUnitsWhenScaled) {
    using dtm::test::encode_pe_number;
    const std::string pe = "PE<=" + encode_pe_number(10) + encode_pe_number(10) +
                           encode_pe_number(5) + encode_pe_number(0) + ";";
    const Plot p = plot("IN;IP0,0,1000,1000;SC0,100,0,100;SP2;" + pe);
    ASSERT_EQ(p.lines.size(), 1u);
    EXPECT_EQ(p.lines[0].pen, 2);
    EXPECT_EQ(p.lines[0].points[0], (Point2{100, 100}));
    EXPECT_EQ(p.lines[0].points[1], (Point2{150, 100}));
}

TEST(HpglPlotter, SymbolModeMarksEveryVertexAndSmallCirclesAreMarkers) {
    const Plot p = plot("IN;SP1;SM*;PA10,10,20,20;SM;PA30,30;CI20;CI400;");
    ASSERT_EQ(p.markers.size(), 3u);
    EXPECT_EQ(p.markers[0].kind, MarkerKind::symbol);
    EXPECT_EQ(p.markers[1].at, (Point2{20, 20}));
    EXPECT_EQ(p.markers[2].kind, MarkerKind::circle);
    EXPECT_EQ(p.markers[2].at, (Point2{30, 30}));  // CI400 (10 mm) is no marker
}

TEST(HpglPlotter, ArcEndsWhereTheSweepSays) {
    const Plot p = plot("IN;SP1;PA1000,0;PD;AA0,0,90,10;");
    ASSERT_EQ(p.lines.size(), 1u);
    const auto& pts = p.lines[0].points;
    ASSERT_EQ(pts.size(), 10u);  // start + 9 chords of 10 degrees
    EXPECT_NEAR(pts.back().x, 0.0, 1e-9);
    EXPECT_NEAR(pts.back().y, 1000.0, 1e-9);
}

TEST(HpglPlotter, StrokesThatContinueWhereTheLastEndedAreJoined) {
    const Plot p = plot("IN;SP3;PA0,0;PD;PA10,0;PU;PD;PA10,10;PU;PA50,50;PD60,60;SP4;PD70,70;");
    ASSERT_EQ(p.lines.size(), 3u);
    EXPECT_EQ(p.lines[0].points.size(), 3u);  // 0,0 - 10,0 - 10,10
    EXPECT_EQ(p.lines[1].pen, 3);
    EXPECT_EQ(p.lines[2].pen, 4);  // a new pen starts a new line
}

TEST(HpglPlotter, PenZeroDrawsNothing) {
    const Plot p = plot("IN;SP0;PD10,10;LB1.5\x03SP1;PU10,10;PD20,20;");
    ASSERT_EQ(p.lines.size(), 1u);
    EXPECT_EQ(p.lines[0].points[0], (Point2{10, 10}));
    EXPECT_TRUE(p.labels.empty());
}

TEST(HpglPlotter, LabelIsAtThePenPositionAndAdvancesThePen) {
    const Plot p = plot("IN;SP1;SI0.1,0.2;PA100,200;LB12\x03PR0,0;PD0,0;");
    ASSERT_EQ(p.labels.size(), 1u);
    EXPECT_EQ(p.labels[0].at, (Point2{100, 200}));
    EXPECT_EQ(p.labels[0].text, "12");
    ASSERT_EQ(p.lines.size(), 1u);
    // Two characters of 1.5 x 0.1 cm = 0.3 cm = 120 plotter units.
    EXPECT_NEAR(p.lines[0].points[0].x, 220.0, 1e-9);
}

TEST(HpglPlotter, RotatedPageSwapsAxesForRelativeScalingPoints) {
    const Plot p = plot("IN;PS1000,500;RO90;IR0,100;SC0,1,0,1,2;PU0,0;PD1,1;");
    ASSERT_EQ(p.lines.size(), 1u);
    EXPECT_EQ(p.lines[0].points[0], (Point2{0, 1000}));  // 100 % of the rotated page height
}

}  // namespace
