// SPDX-License-Identifier: MIT
// Terrain from contour lines: flat triangles removed by skeleton points, every new height
// inside the true contour band, the DEM closer to the truth, summits estimated and reported,
// real flats (a spot height at the level, a flat outline) kept.
#include "dtm/algo/contour_flats.hpp"

#include <gtest/gtest.h>

#include "dtm/algo/rasterize.hpp"
#include "support/contour_terrain.hpp"

namespace {

using dtm::test::contour_terrain_z;

/// RMSE of the TIN's linear surface against the terrain on the cells of [10, 90]^2.
double dem_rmse(const dtm::Tin& tin) {
    const dtm::GridSpec spec{.xmin = 10.0, .ymax = 90.0, .cell = 0.5, .cols = 160, .rows = 160};
    const dtm::Grid grid = dtm::rasterize(tin, spec, {.nodata = -1.0F});
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t r = 0; r < spec.rows; ++r) {
        for (std::size_t c = 0; c < spec.cols; ++c) {
            if (grid.at(r, c) == -1.0F) continue;
            const double e = grid.at(r, c) - contour_terrain_z(spec.center_x(c), spec.center_y(r));
            sum += e * e;
            ++n;
        }
    }
    return std::sqrt(sum / static_cast<double>(n));
}

TEST(ContourFlats, FewFlatTrianglesNewHeightsInTheirBandAndABetterDem) {
    const dtm::TerrainInput input = dtm::test::contour_terrain_input(5.0, 2.0);
    ASSERT_GT(input.breaklines.size(), 15U);
    const dtm::TriangulateResult plain = dtm::triangulate(input);
    const dtm::ContourFlatsResult fixed = dtm::triangulate_contours(input);
    const dtm::ContourFlatsReport& r = fixed.report;
    EXPECT_EQ(r.contour_lines, input.breaklines.size());
    EXPECT_EQ(r.triangles_before, plain.tin.triangles.size());
    EXPECT_EQ(r.flat_before, dtm::count_flat_triangles(plain.tin));
    EXPECT_GT(r.flat_before, r.triangles_before / 20) << "the fixture must be terraced";
    EXPECT_LT(static_cast<double>(r.flat_after), 0.05 * static_cast<double>(r.triangles_after));
    EXPECT_EQ(r.flat_after, dtm::count_flat_triangles(fixed.triangulation.tin));
    EXPECT_EQ(r.points_added, fixed.added.size());
    // Every new point lies in the contour band the true terrain has there (allowing for the
    // contours' own tracing error).
    for (const dtm::Point3& p : fixed.added) {
        const double truth = contour_terrain_z(p.x, p.y);
        const double band = std::floor(truth / 5.0) * 5.0;
        EXPECT_GE(p.z, band - 0.3) << p.x << " " << p.y << " truth " << truth;
        EXPECT_LE(p.z, band + 5.3) << p.x << " " << p.y << " truth " << truth;
    }
    // Two summits inside closed contours without points: estimated and reported.
    ASSERT_GE(r.peaks.size(), 2U);
    for (const dtm::EstimatedPeak& peak : r.peaks) {
        EXPECT_TRUE(peak.summit);
        EXPECT_GT(peak.at.z, peak.contour);
        EXPECT_LE(peak.at.z, peak.contour + 2.5);  // at most half an interval up
        EXPECT_NEAR(peak.at.z, contour_terrain_z(peak.at.x, peak.at.y), 1.0);
    }
    const double before = dem_rmse(plain.tin), after = dem_rmse(fixed.triangulation.tin);
    EXPECT_LT(after, 0.85 * before) << "DEM RMSE " << before << " -> " << after;
}

TEST(ContourFlats, ASpotHeightAtTheLevelKeepsARealFlat) {
    // A closed contour at 100 with a spot height of 100 inside: a plateau (or a lake).
    dtm::TerrainInput input;
    dtm::Polyline ring, outer;
    for (int k = 0; k < 24; ++k) {
        const double a = 2 * M_PI * k / 24;
        ring.points.push_back({50 + 20 * std::cos(a), 50 + 20 * std::sin(a), 100.0});
        outer.points.push_back({50 + 40 * std::cos(a), 50 + 40 * std::sin(a), 90.0});
    }
    ring.closed = outer.closed = true;
    input.breaklines = {ring, outer};
    dtm::TerrainInput plateau = input;
    plateau.points.push_back({50.0, 50.0, 100.0});
    const dtm::ContourFlatsResult kept = dtm::triangulate_contours(plateau);
    EXPECT_EQ(kept.report.true_flats, 1U);
    EXPECT_TRUE(kept.report.peaks.empty());
    EXPECT_EQ(kept.report.flat_after, kept.report.flat_before);
    EXPECT_GT(kept.report.flat_after, 10U);
    // Without the spot height the same ring is a summit, estimated half an interval up.
    const dtm::ContourFlatsResult summit = dtm::triangulate_contours(input);
    ASSERT_EQ(summit.report.peaks.size(), 1U);
    EXPECT_TRUE(summit.report.peaks[0].summit);
    EXPECT_GT(summit.report.peaks[0].at.z, 100.0);
    EXPECT_LE(summit.report.peaks[0].at.z, 105.0);
    EXPECT_NEAR(summit.report.peaks[0].at.x, 50.0, 3.0);
    EXPECT_NEAR(summit.report.peaks[0].at.y, 50.0, 3.0);
    EXPECT_EQ(summit.report.flat_after, 0U);
    // Marked as a flat outline (a lake shore), it stays flat without a spot height.
    const dtm::ContourFlatsResult lake = dtm::triangulate_contours(input, {.flat_outlines = {0}});
    EXPECT_EQ(lake.report.true_flats, 1U);
    EXPECT_EQ(lake.report.flat_after, lake.report.flat_before);
}

TEST(ContourFlats, APitInsideAClosedContourGoesDown) {
    dtm::TerrainInput input;
    dtm::Polyline ring, outer;
    for (int k = 0; k < 30; ++k) {
        const double a = 2 * M_PI * k / 30;
        ring.points.push_back({50 + 15 * std::cos(a), 50 + 15 * std::sin(a), 80.0});
        outer.points.push_back({50 + 35 * std::cos(a), 50 + 35 * std::sin(a), 82.0});
    }
    ring.closed = outer.closed = true;
    input.breaklines = {ring, outer};
    const dtm::ContourFlatsResult r = dtm::triangulate_contours(input);
    ASSERT_EQ(r.report.peaks.size(), 1U);
    EXPECT_FALSE(r.report.peaks[0].summit);
    EXPECT_LT(r.report.peaks[0].at.z, 80.0);
    EXPECT_GE(r.report.peaks[0].at.z, 79.0);
    for (const dtm::Point3& p : r.added) {
        EXPECT_GE(p.z, 79.0);
        EXPECT_LE(p.z, 82.0);
    }
}

TEST(ContourFlats, InputWithoutFlatsIsLeftAlone) {
    dtm::TerrainInput input;
    for (int i = 0; i < 200; ++i) {
        const double x = (i * 37) % 100, y = (i * 53) % 97;
        input.points.push_back({x, y, x * 0.1 + y * 0.2});
    }
    const dtm::ContourFlatsResult r = dtm::triangulate_contours(input);
    EXPECT_EQ(r.report.flat_before, 0U);
    EXPECT_TRUE(r.added.empty());
    EXPECT_EQ(r.triangulation.tin.triangles.size(), dtm::triangulate(input).tin.triangles.size());
}

}  // namespace
