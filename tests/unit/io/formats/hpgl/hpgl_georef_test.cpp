// SPDX-License-Identifier: MIT
// Georeferencing of plotter units: scale/origin/rotation, control points (similarity, affine
// least squares with residuals), the control-file format and its errors; pen option parsing.
#include "io/formats/hpgl/hpgl_georef.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "dtm/core/error.hpp"
#include "support/test_support.hpp"

namespace {

using dtm::Point2;
using dtm::io::hpgl::ControlPoint;
using dtm::io::hpgl::fit_control_points;
using dtm::io::hpgl::make_georeference;

TEST(HpglGeoref, ScaleMakesOnePlotterUnitOneFortiethMillimetreTimesScale) {
    dtm::io::HpglOptions o;
    o.scale = 500;
    o.origin_e = -745000;
    o.origin_n = -1045000;
    const auto g = make_georeference(o);
    const Point2 p = g.transform.apply({40, 0});  // 1 mm on paper = 0.5 m at 1:500
    EXPECT_EQ(p.x, -744999.5);
    EXPECT_EQ(p.y, -1045000.0);
    EXPECT_TRUE(g.notes.empty());
}

TEST(HpglGeoref, RotationIsCounterClockwiseAndExactForQuarterTurns) {
    dtm::io::HpglOptions o;
    o.scale = 1000;
    o.rotation_deg = 90;
    const auto g = make_georeference(o);
    const Point2 p = g.transform.apply({40, 0});  // 1 m along plan x -> 1 m north
    EXPECT_EQ(p.x, 0.0);
    EXPECT_EQ(p.y, 1.0);
}

TEST(HpglGeoref, WithoutOptionsCoordinatesArePlotterMillimetresWithANote) {
    const auto g = make_georeference({});
    EXPECT_EQ(g.transform.apply({400, 80}), (Point2{10, 2}));
    ASSERT_EQ(g.notes.size(), 1u);
    EXPECT_NE(g.notes[0].find("millimetres"), std::string::npos);
}

TEST(HpglGeoref, TwoControlPointsGiveTheExactSimilarity) {
    const std::vector<ControlPoint> c{{{0, 0}, {100, 200}},
                                      {{400, 0}, {100, 205}}};  // 10 mm -> 5 m north
    const auto t = fit_control_points(c, "c.csv");
    const Point2 p = t.apply({0, 400});  // plan y -> west
    EXPECT_NEAR(p.x, 95.0, 1e-12);
    EXPECT_NEAR(p.y, 200.0, 1e-12);
}

TEST(HpglGeoref, AffineLeastSquaresRecoversAnAffineMapAndReportsResiduals) {
    dtm::test::ScratchDir dir;
    const auto f = [](Point2 p) {
        return Point2{-700000.0 + 0.02 * p.x + 0.003 * p.y, -1100000.0 - 0.001 * p.x + 0.015 * p.y};
    };
    std::string csv = "# plan corners\npx;py;E;N\n";
    for (const Point2 p :
         {Point2{0, 0}, Point2{8000, 0}, Point2{8000, 6000}, Point2{0, 6000}, Point2{4000, 3000}}) {
        const Point2 g = f(p);
        char row[160];
        std::snprintf(row, sizeof row, "%.17g;%.17g;%.17g;%.17g\n", p.x, p.y, g.x, g.y);
        csv += row;
    }
    dtm::test::write_file(dir / "c.csv", csv);
    dtm::io::HpglOptions o;
    o.control_file = (dir / "c.csv").string();
    const auto g = make_georeference(o);
    const Point2 q = g.transform.apply({1234, 567});
    EXPECT_NEAR(q.x, f({1234, 567}).x, 1e-7);
    EXPECT_NEAR(q.y, f({1234, 567}).y, 1e-7);
    ASSERT_EQ(g.notes.size(), 6u);  // five residuals and the summary
    EXPECT_NE(g.notes[0].find("control point 1: residual 0.0000 m"), std::string::npos)
        << g.notes[0];
    EXPECT_NE(g.notes[5].find("affine transform from 5 control points"), std::string::npos);
}

TEST(HpglGeoref, ResidualsShowAMisplacedControlPoint) {
    // Three corners of a 1 m square and a fourth 0.2 m off: the fit spreads it, 0.05 m each.
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "c.csv", "0,0,0,0\n40,0,1,0\n40,40,1,1\n0,40,0,1.2\n");
    dtm::io::HpglOptions o;
    o.control_file = (dir / "c.csv").string();
    const auto g = make_georeference(o);
    EXPECT_NE(g.notes[3].find("control point 4: residual 0.0500 m"), std::string::npos)
        << g.notes[3];
}

TEST(HpglGeoref, ControlHeaderWithPxMmMeansPaperMillimetres) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "c.csv", "px_mm,py_mm,E,N\n0,0,100,200\n10,0,105,200\n");
    const auto points = dtm::io::hpgl::read_control_points(dir / "c.csv");
    ASSERT_EQ(points.size(), 2u);
    EXPECT_EQ(points[1].plotter, (Point2{400, 0}));
    const auto t = fit_control_points(points, "c.csv");
    EXPECT_NEAR(t.apply({400, 400}).y, 205.0, 1e-12);  // 1:500
}

TEST(HpglGeoref, CollinearOrTooFewControlPointsAreInputErrors) {
    EXPECT_THROW((void)fit_control_points({{{0, 0}, {0, 0}}}, "c.csv"), dtm::InputError);
    EXPECT_THROW((void)fit_control_points({{{0, 0}, {0, 0}}, {{0, 0}, {5, 5}}}, "c.csv"),
                 dtm::InputError);
    EXPECT_THROW(
        (void)fit_control_points({{{0, 0}, {0, 0}}, {{1, 1}, {1, 1}}, {{2, 2}, {2, 2}}}, "c.csv"),
        dtm::InputError);
}

TEST(HpglGeoref, BadControlFileLineIsReportedWithLineAndColumn) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "c.csv", "px,py,E,N\n0,0,10,10\n40,x,20,20\n");
    try {
        (void)dtm::io::hpgl::read_control_points(dir / "c.csv");
        FAIL() << "no error";
    } catch (const dtm::InputError& e) {
        EXPECT_EQ(e.line(), 3u);
        EXPECT_EQ(e.column(), 4u);
        EXPECT_NE(std::string(e.what()).find("px,py,E,N"), std::string::npos);
    }
    dtm::test::write_file(dir / "d.csv", "0,0,10\n");
    EXPECT_THROW((void)dtm::io::hpgl::read_control_points(dir / "d.csv"), dtm::InputError);
}

TEST(HpglGeoref, ScaleAndControlTogetherAreAUsageError) {
    dtm::io::HpglOptions o;
    o.scale = 500;
    o.control_file = "c.csv";
    EXPECT_THROW((void)make_georeference(o), dtm::UsageError);
}

}  // namespace
