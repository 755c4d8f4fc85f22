// SPDX-License-Identifier: MIT
#include "dtm/algo/check_points.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "support/solid_fixtures.hpp"

namespace {

TEST(CheckPoints, HeightsOnAPlaneAndPointsOutsideListed) {
    const dtm::test::Square sq{-750000.0, -1050000.0, 20.0};
    const dtm::Tin tin = dtm::test::plane_tin(sq, 100.0, 0.1, 0.2, 50, 1);
    const dtm::LinearSurface surface(tin);
    const std::vector<dtm::Point3> points{{sq.x0 + 5, sq.y0 + 5, 101.6},    // 0.1 above
                                          {sq.x0 + 20, sq.y0 + 20, 106.0},  // a corner, exact
                                          {sq.x0 - 1, sq.y0 + 5, 0.0}};     // outside
    const auto r = dtm::check_points(surface, points);
    ASSERT_TRUE(r[0].inside);
    EXPECT_NEAR(r[0].surface_z, 101.5, 1e-9);
    EXPECT_NEAR(r[0].residual, 0.1, 1e-9);
    ASSERT_TRUE(r[1].inside);
    EXPECT_EQ(r[1].surface_z, 106.0);
    EXPECT_FALSE(r[2].inside);
    const dtm::CheckStatistics s = dtm::check_statistics(r);
    EXPECT_EQ(s.points, 3U);
    EXPECT_EQ(s.inside, 2U);
    EXPECT_EQ(s.outside, 1U);
    EXPECT_NEAR(s.max_abs, 0.1, 1e-9);
    EXPECT_EQ(s.max_abs_index, 0U);
}

// Clough-Tocher (with Nielson's gradients) and Sibson's natural neighbours both reproduce a
// plane: through InterpolatedSurface they must give the plane's heights, and nothing outside.
TEST(CheckPoints, SmoothSurfacesReproduceAPlane) {
    const dtm::test::Square sq{-750000.0, -1050000.0, 20.0};
    const dtm::Tin tin = dtm::test::plane_tin(sq, 100.0, 0.1, 0.2, 50, 1);
    for (const dtm::Interpolation method :
         {dtm::Interpolation::cubic, dtm::Interpolation::natural}) {
        const dtm::TinInterpolant interpolant = dtm::TinInterpolant::prepare(tin, method);
        const dtm::InterpolatedSurface surface(tin, interpolant);
        for (const auto& [dx, dy] :
             {std::pair{5.0, 5.0}, {0.3, 17.9}, {12.25, 0.0}, {20.0, 20.0}}) {
            double z = 0.0;
            ASSERT_TRUE(surface.height(sq.x0 + dx, sq.y0 + dy, z)) << dx << " " << dy;
            EXPECT_NEAR(z, 100.0 + 0.1 * dx + 0.2 * dy, 1e-6) << dtm::interpolation_name(method);
        }
        double z = 0.0;
        EXPECT_FALSE(surface.height(sq.x0 - 1.0, sq.y0 + 5.0, z));
    }
}

TEST(CheckPoints, StatisticsOfKnownResiduals) {
    std::vector<dtm::CheckResult> r;
    for (const double v : {0.1, -0.2, 0.3, -0.4, 0.5}) {
        r.push_back({true, 0.0, v});
    }
    r.push_back({false, 0.0, 0.0});
    const dtm::CheckStatistics s = dtm::check_statistics(r);
    EXPECT_NEAR(s.mean, 0.06, 1e-15);
    EXPECT_NEAR(s.rmse, std::sqrt((0.01 + 0.04 + 0.09 + 0.16 + 0.25) / 5.0), 1e-15);
    EXPECT_NEAR(s.std_dev, std::sqrt((0.0016 + 0.0676 + 0.0576 + 0.2116 + 0.1936) / 4.0), 1e-15);
    EXPECT_NEAR(s.p50, 0.3, 1e-15);
    EXPECT_NEAR(s.p90, 0.46, 1e-15);  // h = 3.6: 0.4 + 0.6 * 0.1
    EXPECT_EQ(s.min, -0.4);
    EXPECT_EQ(s.max, 0.5);
    EXPECT_EQ(s.outside, 1U);
}

}  // namespace
