// SPDX-License-Identifier: MIT
// Contours on the cubic and natural-neighbour surfaces: the refinement is a valid TIN whose
// vertices lie on the surface, the lines are closed around a hill, lie on the smooth surface,
// never cross each other, are smoother than the linear ones, and cross a hard breakline once.
#include <gtest/gtest.h>

#include <map>

#include "algo/detail/contour_refined.hpp"
#include "dtm/algo/contour.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/geom/predicates.hpp"
#include "support/surface_fixtures.hpp"

namespace {

using dtm::Interpolation;

double hill(double x, double y) {
    return 100.0 + 30.0 * std::exp(-((x - 50) * (x - 50) + (y - 50) * (y - 50)) / 900.0);
}

TEST(ContourSurface, RefinementIsAValidTinOnTheSurface) {
    const dtm::Tin tin = dtm::triangulate(dtm::test::sampled_terrain(hill, 120, 3)).tin;
    for (const Interpolation m : {Interpolation::cubic, Interpolation::natural}) {
        const dtm::TinInterpolant interpolant = dtm::TinInterpolant::prepare(tin, m);
        for (const unsigned subdivisions : {1U, 2U, 5U}) {
            std::vector<dtm::TriangleIndex> selected;
            for (dtm::TriangleIndex t = 0; t < tin.triangles.size(); t += (t % 3 == 0 ? 1 : 2)) {
                selected.push_back(t);
            }
            const dtm::Tin refined =
                dtm::detail::refine_for_contours(tin, interpolant, selected, subdivisions);
            EXPECT_EQ(refined.triangles.size(), selected.size() * 3 * subdivisions * subdivisions);
            const dtm::CheckReport report = dtm::verify_topology(refined);
            EXPECT_TRUE(report.ok()) << report.text();
            dtm::TinEvaluator eval(tin, interpolant);
            dtm::TriangleIndex hint = 0;
            for (std::size_t v = tin.vertices.size(); v < refined.vertices.size(); v += 7) {
                const dtm::Point3& p = refined.vertices[v];
                EXPECT_NEAR(p.z, eval.value_at(p.x, p.y, hint), 1e-9);
            }
        }
    }
}

/// True if segments (a, b) and (c, d) properly intersect (exact).
bool cross(const dtm::Point3& a, const dtm::Point3& b, const dtm::Point3& c, const dtm::Point3& d) {
    const int o1 = dtm::geom::orient2d(a, b, c), o2 = dtm::geom::orient2d(a, b, d);
    const int o3 = dtm::geom::orient2d(c, d, a), o4 = dtm::geom::orient2d(c, d, b);
    return o1 * o2 < 0 && o3 * o4 < 0;
}

/// Sum of the turning angles along a line (radians): how much it wiggles.
double turning(const std::vector<dtm::Point3>& line) {
    double sum = 0.0;
    for (std::size_t i = 1; i + 1 < line.size(); ++i) {
        const double a = std::atan2(line[i].y - line[i - 1].y, line[i].x - line[i - 1].x);
        const double b = std::atan2(line[i + 1].y - line[i].y, line[i + 1].x - line[i].x);
        double d = std::abs(b - a);
        sum += d > M_PI ? 2 * M_PI - d : d;
    }
    return sum;
}

TEST(ContourSurface, CubicContoursOfAHillAreClosedSmoothOnTheSurfaceAndNeverCross) {
    const dtm::Tin tin = dtm::triangulate(dtm::test::sampled_terrain(hill, 250, 8)).tin;
    dtm::ContourOptions options;
    options.interval = 5.0;
    options.surface = Interpolation::cubic;
    const std::vector<dtm::Contour> lines = dtm::contour(tin, options);
    ASSERT_FALSE(lines.empty());
    const dtm::TinInterpolant interpolant = dtm::TinInterpolant::prepare(tin, Interpolation::cubic);
    dtm::TinEvaluator eval(tin, interpolant);
    std::map<double, int> closed_per_level;
    dtm::TriangleIndex hint = 0;
    for (const dtm::Contour& c : lines) {
        for (const dtm::Point3& p : c.line) {
            ASSERT_EQ(p.z, c.level.value);
            // the points are the cubic's own crossings of the refinement's edges
            EXPECT_NEAR(eval.value_at(p.x, p.y, hint), c.level.value, 1e-7);
        }
        const double r = std::hypot(c.line[0].x - 50, c.line[0].y - 50);
        if (r < 35) {  // rings around the summit, away from the hull
            EXPECT_TRUE(c.closed) << "level " << c.level.value;
            closed_per_level[c.level.value] += c.closed ? 1 : 0;
        }
    }
    for (const auto& [level, count] : closed_per_level) {
        EXPECT_EQ(count, 1) << "one ring per level around the summit, level " << level;
    }
    for (std::size_t i = 0; i < lines.size(); ++i) {
        for (std::size_t j = i; j < lines.size(); ++j) {
            const auto& a = lines[i].line;
            const auto& b = lines[j].line;
            for (std::size_t p = 0; p + 1 < a.size(); ++p) {
                for (std::size_t q = 0; q + 1 < b.size(); ++q) {
                    if (i == j && q <= p + 1) continue;
                    ASSERT_FALSE(cross(a[p], a[p + 1], b[q], b[q + 1])) << i << " " << j;
                }
            }
        }
    }
    // Smoother than the linear contours of the same TIN: on the rings around the summit, the
    // sharpest corner of the cubic line is far gentler than the linear line's.
    dtm::ContourOptions linear_options = options;
    linear_options.surface = Interpolation::linear;
    const std::vector<dtm::Contour> linear_lines = dtm::contour(tin, linear_options);
    const auto sharpest = [](const std::vector<dtm::Contour>& all, double level) {
        double worst = 0.0;
        for (const auto& c : all) {
            if (c.level.value != level) continue;
            for (std::size_t i = 1; i + 1 < c.line.size(); ++i) {
                const std::vector<dtm::Point3> three{c.line[i - 1], c.line[i], c.line[i + 1]};
                worst = std::max(worst, turning(three));
            }
        }
        return worst * 180.0 / M_PI;
    };
    for (const double level : {110.0, 115.0, 120.0}) {
        const double cubic = sharpest(lines, level), linear = sharpest(linear_lines, level);
        EXPECT_LT(cubic, 0.35 * linear) << "level " << level << ": " << cubic << " vs " << linear;
    }
}

TEST(ContourSurface, NaturalNeighbourContoursAreClosedAndOnTheSurface) {
    const dtm::Tin tin = dtm::triangulate(dtm::test::sampled_terrain(hill, 200, 4)).tin;
    dtm::ContourOptions options;
    options.fixed_levels = {110.0, 120.0};
    options.surface = Interpolation::natural;
    const std::vector<dtm::Contour> lines = dtm::contour(tin, options);
    ASSERT_EQ(lines.size(), 2U);
    for (const auto& c : lines) {
        EXPECT_TRUE(c.closed);
    }
}

TEST(ContourSurface, ContourCrossesAHardBreaklineOnceWhereTheBreaklineHasItsLevel) {
    // A ridge z = 50 - |y - 50| + x/10 with its crest as a hard breakline: the contour of level
    // L meets the crest at the one point where the crest's (linear) height is L.
    const auto ridge = [](double x, double y) { return 50.0 - std::abs(y - 50.0) + x / 10.0; };
    dtm::TerrainInput input = dtm::test::sampled_terrain(ridge, 400, 17);
    dtm::Polyline crest;
    for (double x = 0; x <= 100; x += 10) crest.points.push_back({x, 50.0, ridge(x, 50.0)});
    input.breaklines.push_back(crest);
    const dtm::Tin tin = dtm::triangulate(input).tin;
    dtm::ContourOptions options;
    options.fixed_levels = {53.25};
    options.surface = Interpolation::cubic;
    const std::vector<dtm::Contour> lines = dtm::contour(tin, options);
    ASSERT_EQ(lines.size(), 1U);
    std::size_t on_crest = 0;
    for (const dtm::Point3& p : lines[0].line) {
        if (p.y == 50.0) {
            ++on_crest;
            EXPECT_NEAR(p.x, 32.5, 1e-9);
        }
    }
    EXPECT_EQ(on_crest, 1U);
}

}  // namespace
