// SPDX-License-Identifier: MIT
// resolve_line_heights and triangulate() with 2-D lines: coincident survey points, the surface
// of the points for rings (inside: linear, beyond the hull: the nearest vertex), errors for hard
// breaklines without heights, soft breaklines left to the triangulator.
#include "dtm/algo/line_heights.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// The plane z = x + 2 y sampled at the corners and centre of [0, 100]^2.
dtm::TerrainInput plane_points() {
    dtm::TerrainInput in;
    in.points = {{0, 0, 0}, {100, 0, 100}, {100, 100, 300}, {0, 100, 200}, {50, 50, 150}};
    return in;
}

dtm::Polyline ring(std::initializer_list<dtm::Point2> corners, std::string source = "ring.csv:1") {
    dtm::Polyline line;
    for (const dtm::Point2& p : corners) line.points.push_back({p.x, p.y, nan});
    line.closed = true;
    line.source = std::move(source);
    return line;
}

TEST(LineHeights, RingVerticesTakeTheHeightOfTheSurface) {
    dtm::TerrainInput in = plane_points();
    in.boundaries.push_back(ring({{10.5, 10}, {90.5, 10}, {90.5, 90}, {10.5, 90}}));
    in.holes.push_back(ring({{40, 40}, {60, 40}, {60, 60}}));
    const dtm::LineHeightReport report = dtm::resolve_line_heights(in);
    EXPECT_EQ(report.from_surface, 7U);
    EXPECT_EQ(report.from_points, 0U);
    for (const auto* rings : {&in.boundaries, &in.holes}) {
        for (const dtm::Point3& p : (*rings)[0].points) EXPECT_NEAR(p.z, p.x + 2 * p.y, 1e-9);
    }
}

TEST(LineHeights, VerticesOnASurveyPointTakeItsHeightExactly) {
    dtm::TerrainInput in = plane_points();
    in.points.push_back({20, 30, 99.125});  // off the plane on purpose: the point wins
    dtm::Polyline line;
    line.points = {{20, 30, nan}, {50, 50, nan}};
    in.breaklines.push_back(line);
    in.soft_breaklines.push_back(line);
    in.boundaries.push_back(ring({{20, 30}, {100, 0}, {100, 100}}));
    const dtm::LineHeightReport report = dtm::resolve_line_heights(in);
    EXPECT_EQ(report.from_points, 2U + 2U + 3U);
    EXPECT_EQ(report.from_surface, 0U);
    EXPECT_EQ(in.breaklines[0].points[0].z, 99.125);
    EXPECT_EQ(in.soft_breaklines[0].points[1].z, 150.0);
    EXPECT_EQ(in.boundaries[0].points[0].z, 99.125);
}

TEST(LineHeights, RingVerticesBeyondTheHullTakeTheNearestVertex) {
    dtm::TerrainInput in = plane_points();
    in.boundaries.push_back(ring({{-10, -20}, {130, -5}, {120, 120}, {-5, 101}}));
    (void)dtm::resolve_line_heights(in);
    const auto& p = in.boundaries[0].points;
    EXPECT_EQ(p[0].z, 0.0);
    EXPECT_EQ(p[1].z, 100.0);
    EXPECT_EQ(p[2].z, 300.0);
    EXPECT_EQ(p[3].z, 200.0);
}

TEST(LineHeights, HardBreaklineVertexWithoutAHeightIsAnInputErrorNamingIt) {
    dtm::TerrainInput in = plane_points();
    dtm::Polyline line;
    line.points = {{0, 0, nan}, {5.5, 5, nan}};
    line.source = "bad.csv:1";
    in.breaklines.push_back(line);
    try {
        (void)dtm::resolve_line_heights(in);
        FAIL() << "no exception";
    } catch (const dtm::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("bad.csv:1"), std::string::npos) << what;
        EXPECT_NE(what.find("(5.500000, 5.000000)"), std::string::npos) << what;
        EXPECT_NE(what.find("`soft_breaklines`"), std::string::npos) << what;
    }
}

TEST(LineHeights, RingsNeedAtLeastThreeSurveyPoints) {
    dtm::TerrainInput in;
    in.points = {{0, 0, 1}, {1, 0, 1}};
    in.boundaries.push_back(ring({{0, 0.5}, {1, 0.5}, {0.5, 1}}));
    EXPECT_THROW((void)dtm::resolve_line_heights(in), dtm::InputError);
}

TEST(LineHeights, SoftBreaklineVerticesAreLeftToTheTriangulator) {
    dtm::TerrainInput in = plane_points();
    dtm::Polyline soft;
    soft.points = {{10, 20, nan}, {80, 70, nan}};
    in.soft_breaklines.push_back(soft);
    const dtm::LineHeightReport report = dtm::resolve_line_heights(in);
    EXPECT_EQ(report.from_points + report.from_surface, 0U);
    EXPECT_TRUE(std::isnan(in.soft_breaklines[0].points[0].z));
    const dtm::TriangulateResult result = dtm::triangulate(in);
    for (const dtm::Point3& v : result.tin.vertices) EXPECT_NEAR(v.z, v.x + 2 * v.y, 1e-9);
}

TEST(LineHeights, TriangulateWithTwoDimensionalRingsEqualsResolvingFirst) {
    dtm::TerrainInput in = plane_points();
    for (int i = 0; i < 200; ++i) {  // more points, off the plane, so the surface matters
        const double x = 3.0 + 0.47 * i;
        const double y = std::fmod(17.0 * i, 97.0) + 1.0;
        in.points.push_back({x, y, x + 2 * y + std::sin(i)});
    }
    in.boundaries.push_back(ring({{2, 1}, {98, 3}, {97, 99}, {1, 97}}));
    in.holes.push_back(ring({{40, 40}, {60, 41}, {55, 60}}));
    dtm::TerrainInput resolved = in;
    (void)dtm::resolve_line_heights(resolved);
    const dtm::TriangulateResult direct = dtm::triangulate(in);
    const dtm::TriangulateResult two_steps = dtm::triangulate(resolved);
    EXPECT_EQ(direct.line_heights.from_surface, 7U);
    EXPECT_EQ(two_steps.line_heights.from_surface, 0U);
    ASSERT_EQ(direct.tin.vertices.size(), two_steps.tin.vertices.size());
    for (std::size_t i = 0; i < direct.tin.vertices.size(); ++i) {
        EXPECT_EQ(direct.tin.vertices[i], two_steps.tin.vertices[i]) << i;
    }
    ASSERT_EQ(direct.tin.triangles.size(), two_steps.tin.triangles.size());
    for (std::size_t t = 0; t < direct.tin.triangles.size(); ++t) {
        EXPECT_EQ(direct.tin.triangles[t].v, two_steps.tin.triangles[t].v) << t;
    }
}

}  // namespace
