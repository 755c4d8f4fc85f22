// SPDX-License-Identifier: MIT
#include "dtm/algo/surface_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

/// A square of side a split along its diagonal, at a large S-JTSK offset, on the plane
/// z = z0 + g x (g = slope).
dtm::Tin tilted_square(double a, double g, double x0, double y0) {
    dtm::Tin tin;
    tin.vertices = {{x0, y0, 100.0},
                    {x0 + a, y0, 100.0 + g * a},
                    {x0 + a, y0 + a, 100.0 + g * a},
                    {x0, y0 + a, 100.0}};
    tin.triangles.resize(2);
    tin.triangles[0].v = {0, 1, 2};
    tin.triangles[1].v = {0, 2, 3};
    return tin;
}

TEST(SurfaceStats, PlanimetricAreaOfSquareAtLargeOffsetIsExact) {
    const auto stats = dtm::surface_stats(tilted_square(10.0, 0.0, -750000.0, -1050000.0));
    EXPECT_DOUBLE_EQ(stats.planimetric_area, 100.0);
    EXPECT_DOUBLE_EQ(stats.surface_area, 100.0);
}

TEST(SurfaceStats, SurfaceAreaOfTiltedPlaneIsPlanimetricOverCosine) {
    const double g = 0.75;  // slope 3:4, so 1 / cos = 1.25
    const auto stats = dtm::surface_stats(tilted_square(8.0, g, -750000.0, -1050000.0));
    EXPECT_NEAR(stats.planimetric_area, 64.0, 1e-9);
    EXPECT_NEAR(stats.surface_area, 64.0 * 1.25, 1e-9);
}

TEST(SurfaceStats, ExtentAndZRangeIgnoreVerticesNoTriangleUses) {
    dtm::Tin tin = tilted_square(2.0, 1.0, 5.0, 7.0);
    tin.vertices.push_back({1000.0, 1000.0, -50.0});  // isolated, e.g. merged away
    const auto stats = dtm::surface_stats(tin);
    EXPECT_EQ(stats.vertex_count, 5u);
    EXPECT_EQ(stats.triangle_count, 2u);
    EXPECT_DOUBLE_EQ(stats.extent.xmin, 5.0);
    EXPECT_DOUBLE_EQ(stats.extent.xmax, 7.0);
    EXPECT_DOUBLE_EQ(stats.extent.ymax, 9.0);
    EXPECT_DOUBLE_EQ(stats.z_min, 100.0);
    EXPECT_DOUBLE_EQ(stats.z_max, 102.0);
}

TEST(SurfaceStats, EmptyTinHasZeroAreaAndEmptyExtent) {
    const auto stats = dtm::surface_stats(dtm::Tin{});
    EXPECT_EQ(stats.planimetric_area, 0.0);
    EXPECT_TRUE(stats.extent.empty());
}

}  // namespace

namespace {

TEST(AccountInputs, EveryInputPointIsUsedMergedOrRemovedExactlyOnce) {
    dtm::TriangulateResult result;
    result.tin = tilted_square(1.0, 0.0, 0.0, 0.0);
    result.tin.vertices.push_back({5.0, 5.0, 0.0});  // vertex 4: in no triangle (outside)
    // Inputs: 0..3 survey points on the square corners, 4 a duplicate of 0, 5 outside,
    // then line vertices 6 (corner 2) and 7 (duplicate of 6).
    result.input_to_vertex = {0, 1, 2, 3, 0, 4, 2, 2};
    result.merges.push_back({0, 4, {}, {}});
    result.merges.push_back({6, 7, {}, {}});
    const dtm::InputAccounting a = dtm::account_inputs(result, 6);
    EXPECT_EQ(a.survey_points.total, 6u);
    EXPECT_EQ(a.survey_points.used, 4u);
    EXPECT_EQ(a.survey_points.merged, 1u);
    EXPECT_EQ(a.survey_points.removed, 1u);
    EXPECT_EQ(a.line_vertices.total, 2u);
    EXPECT_EQ(a.line_vertices.used, 1u);
    EXPECT_EQ(a.line_vertices.merged, 1u);
    EXPECT_EQ(a.line_vertices.removed, 0u);
}

}  // namespace
