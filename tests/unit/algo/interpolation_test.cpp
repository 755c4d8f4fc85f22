// SPDX-License-Identifier: MIT
// The surfaces of a TIN through TinEvaluator: every vertex interpolated exactly, linear data
// reproduced by every method, the cubic surface C1 across edges with estimated gradients and
// creased along hard breaklines, the natural-neighbour surface continuous across barriers.
#include "dtm/algo/interpolation.hpp"

#include <gtest/gtest.h>

#include "dtm/algo/triangulate.hpp"
#include "dtm/geom/predicates.hpp"
#include "support/surface_fixtures.hpp"

namespace {

using dtm::Interpolation;
using dtm::TinEvaluator;
using dtm::TinInterpolant;

constexpr Interpolation all_methods[] = {Interpolation::linear, Interpolation::cubic,
                                         Interpolation::natural};

double hill(double x, double y) {
    return 200.0 + 20.0 * std::exp(-((x - 40) * (x - 40) + (y - 55) * (y - 55)) / 800.0) + 0.05 * x;
}

TEST(Interpolation, NamesRoundTrip) {
    for (const Interpolation m : all_methods) {
        EXPECT_EQ(dtm::parse_interpolation(dtm::interpolation_name(m)), m);
    }
    EXPECT_FALSE(dtm::parse_interpolation("bicubic").has_value());
}

TEST(Interpolation, EveryMethodInterpolatesEveryVertexExactly) {
    const dtm::Tin tin =
        dtm::triangulate(dtm::test::sampled_terrain(hill, 500, 4, -750000.0, -1050000.0)).tin;
    for (const Interpolation m : all_methods) {
        const TinInterpolant interpolant = TinInterpolant::prepare(tin, m);
        TinEvaluator eval(tin, interpolant);
        for (const auto& t : tin.triangles) {
            for (std::size_t i = 0; i < 3; ++i) {
                const dtm::Point3& p = tin.vertices[t.v[i]];
                ASSERT_EQ(eval.value(static_cast<dtm::TriangleIndex>(&t - tin.triangles.data()),
                                     p.x, p.y),
                          p.z)
                    << dtm::interpolation_name(m);
            }
        }
    }
}

TEST(Interpolation, EveryMethodReproducesLinearData) {
    const auto plane = [](double x, double y) { return 10.0 + 0.2 * x - 0.35 * y; };
    const dtm::Tin tin = dtm::triangulate(dtm::test::sampled_terrain(plane, 300, 8)).tin;
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.5, 99.5);
    for (const Interpolation m : all_methods) {
        const TinInterpolant interpolant = TinInterpolant::prepare(tin, m);
        TinEvaluator eval(tin, interpolant);
        dtm::TriangleIndex hint = 0;
        for (int k = 0; k < 500; ++k) {
            const double x = u(rng), y = u(rng);
            ASSERT_NEAR(eval.value_at(x, y, hint), plane(x, y), 1e-9) << dtm::interpolation_name(m);
        }
    }
}

/// Root-mean-square error against @p truth at random points in [10, 90]^2.
double rms_error(TinEvaluator& eval, const dtm::test::Terrain& truth, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(10.0, 90.0);
    double sum = 0.0;
    dtm::TriangleIndex hint = 0;
    for (int k = 0; k < 4000; ++k) {
        const double x = u(rng), y = u(rng);
        const double e = eval.value_at(x, y, hint) - truth(x, y);
        sum += e * e;
    }
    return std::sqrt(sum / 4000.0);
}

TEST(Interpolation, CubicAndNaturalBeatLinearOnASmoothHill) {
    const dtm::Tin tin = dtm::triangulate(dtm::test::sampled_terrain(hill, 400, 6)).tin;
    double rms[3];
    for (const Interpolation m : all_methods) {
        const TinInterpolant interpolant = TinInterpolant::prepare(tin, m);
        TinEvaluator eval(tin, interpolant);
        rms[static_cast<int>(m)] = rms_error(eval, hill, 77);
    }
    EXPECT_LT(rms[1], 0.5 * rms[0]) << "cubic " << rms[1] << " linear " << rms[0];
    // Sibson's C0 interpolant has the linear one's accuracy (its gain is smoothness)
    EXPECT_LT(rms[2], 1.2 * rms[0]) << "natural " << rms[2] << " linear " << rms[0];
}

/// Smallest angle of triangle @p t, in degrees.
double min_angle(const dtm::Tin& tin, std::size_t t) {
    double best = 180.0;
    for (std::size_t i = 0; i < 3; ++i) {
        const dtm::Point3& a = tin.vertices[tin.triangles[t].v[i]];
        const dtm::Point3& b = tin.vertices[tin.triangles[t].v[(i + 1) % 3]];
        const dtm::Point3& c = tin.vertices[tin.triangles[t].v[(i + 2) % 3]];
        const double u = std::atan2(b.y - a.y, b.x - a.x), v = std::atan2(c.y - a.y, c.x - a.x);
        double d = std::abs(u - v) * 180.0 / M_PI;
        best = std::min(best, d > 180.0 ? 360.0 - d : d);
    }
    return best;
}

TEST(Interpolation, CubicSurfaceIsC1AcrossTinEdges) {
    // The gradient just left and just right of an edge midpoint, 10^-4 edge lengths away: a C1
    // surface differs by O(10^-4) there, a kinked one by the kink. Slivers are left out (their
    // patches curve strongly, which a finite difference cannot tell from a kink).
    const dtm::Tin tin = dtm::triangulate(dtm::test::sampled_terrain(hill, 300, 12)).tin;
    const TinInterpolant interpolant = TinInterpolant::prepare(tin, Interpolation::cubic);
    TinEvaluator eval(tin, interpolant);
    const TinInterpolant linear_interpolant;
    TinEvaluator linear(tin, linear_interpolant);
    double worst_cubic = 0.0, worst_linear = 0.0;
    std::size_t edges = 0;
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        const auto& tri = tin.triangles[t];
        for (std::size_t e = 0; e < 3; ++e) {
            if (tri.n[e] == dtm::no_triangle || tri.n[e] < t || min_angle(tin, t) < 15 ||
                min_angle(tin, tri.n[e]) < 15) {
                continue;
            }
            ++edges;
            const dtm::Point3& a = tin.vertices[tri.v[(e + 1) % 3]];
            const dtm::Point3& b = tin.vertices[tri.v[(e + 2) % 3]];
            const double mx = 0.5 * (a.x + b.x), my = 0.5 * (a.y + b.y);
            const double len = std::hypot(b.x - a.x, b.y - a.y);
            const double nx = -(b.y - a.y) * 1e-4, ny = (b.x - a.x) * 1e-4;
            for (TinEvaluator* ev : {&eval, &linear}) {
                const auto g1 = dtm::test::fd_gradient(*ev, mx + nx, my + ny, 1e-6 * len);
                const auto g2 = dtm::test::fd_gradient(*ev, mx - nx, my - ny, 1e-6 * len);
                double& worst = ev == &eval ? worst_cubic : worst_linear;
                worst = std::max(worst, std::hypot(g1[0] - g2[0], g1[1] - g2[1]));
            }
        }
    }
    EXPECT_GT(edges, 300U);
    EXPECT_LT(worst_cubic, 2e-3) << "largest gradient jump across an edge";
    EXPECT_GT(worst_linear, 0.05) << "the check must see the kinks of the linear surface";
}

TEST(Interpolation, CubicCreasesAlongAHardBreaklineAndSmoothsAcrossASoftOne) {
    // A V-shaped ditch z = 2 |y - 50| + smooth terms, its floor given as a breakline.
    const auto ditch = [](double x, double y) {
        return 100.0 + 2.0 * std::abs(y - 50.0) + 0.001 * (x - 50) * (x - 50);
    };
    dtm::TerrainInput input = dtm::test::sampled_terrain(ditch, 500, 21);
    dtm::Polyline floor;
    for (double x = 0; x <= 100.0; x += 5.0) floor.points.push_back({x, 50.0, ditch(x, 50.0)});
    dtm::TerrainInput hard = input, soft = input;
    hard.breaklines.push_back(floor);
    soft.soft_breaklines.push_back(floor);
    const dtm::Tin hard_tin = dtm::triangulate(hard).tin;
    const dtm::Tin soft_tin = dtm::triangulate(soft).tin;
    const auto error_near_floor = [&](const dtm::Tin& tin, Interpolation m) {
        const TinInterpolant interpolant = TinInterpolant::prepare(tin, m);
        TinEvaluator eval(tin, interpolant);
        double worst = 0.0;
        dtm::TriangleIndex hint = 0;
        for (double x = 10; x <= 90; x += 0.7) {
            for (const double dy : {-1.5, -0.6, -0.1, 0.1, 0.6, 1.5}) {
                worst =
                    std::max(worst, std::abs(eval.value_at(x, 50 + dy, hint) - ditch(x, 50 + dy)));
            }
        }
        return worst;
    };
    const double cubic_hard = error_near_floor(hard_tin, Interpolation::cubic);
    const double linear_hard = error_near_floor(hard_tin, Interpolation::linear);
    const double cubic_soft = error_near_floor(soft_tin, Interpolation::cubic);
    EXPECT_LE(cubic_hard, linear_hard) << "the crease must be kept";
    EXPECT_LT(cubic_hard, 0.05);
    EXPECT_GT(cubic_soft, 4 * cubic_hard) << "a soft breakline is smoothed across";
    // Across the hard floor the gradient jumps by about 4 (slopes -2 and +2).
    const TinInterpolant interpolant = TinInterpolant::prepare(hard_tin, Interpolation::cubic);
    TinEvaluator eval(hard_tin, interpolant);
    const auto above = dtm::test::fd_gradient(eval, 37.3, 50.02, 1e-3);
    const auto below = dtm::test::fd_gradient(eval, 37.3, 49.98, 1e-3);
    EXPECT_NEAR(above[1] - below[1], 4.0, 0.2);
}

TEST(Interpolation, NaturalNeighbourIsContinuousAcrossABarrier) {
    const auto ditch = [](double x, double y) { return 2.0 * std::abs(y - 50.0) + 0.1 * x; };
    dtm::TerrainInput input = dtm::test::sampled_terrain(ditch, 300, 3);
    dtm::Polyline floor;
    for (double x = 0; x <= 100.0; x += 10.0) floor.points.push_back({x, 50.0, ditch(x, 50.0)});
    input.breaklines.push_back(floor);
    const dtm::Tin tin = dtm::triangulate(input).tin;
    const TinInterpolant interpolant = TinInterpolant::prepare(tin, Interpolation::natural);
    TinEvaluator eval(tin, interpolant);
    dtm::TriangleIndex hint = 0;
    for (double x = 5.3; x < 95; x += 3.1) {
        const double on = eval.value_at(x, 50.0, hint);
        EXPECT_NEAR(on, ditch(x, 50.0), 1e-9) << "linear along the breakline";
        EXPECT_NEAR(eval.value_at(x, 50.0 + 1e-7, hint), on, 1e-5);
        EXPECT_NEAR(eval.value_at(x, 50.0 - 1e-7, hint), on, 1e-5);
    }
}

TEST(Interpolation, LocateFindsTheTriangleOrNothing) {
    dtm::TerrainInput input = dtm::test::sampled_terrain(hill, 200, 5);
    dtm::Polyline hole;
    hole.points = {{30, 30, 0}, {60, 30, 0}, {60, 60, 0}, {30, 60, 0}};
    hole.closed = true;
    input.holes.push_back(hole);
    const dtm::Tin tin = dtm::triangulate(input).tin;
    EXPECT_EQ(dtm::locate_triangle(tin, 45, 45, 0), dtm::no_triangle);
    EXPECT_EQ(dtm::locate_triangle(tin, 150, 45, 0), dtm::no_triangle);
    const dtm::TriangleIndex t = dtm::locate_triangle(tin, 10.5, 80.25, 0);
    ASSERT_NE(t, dtm::no_triangle);
    for (std::size_t e = 0; e < 3; ++e) {
        EXPECT_GE(dtm::geom::orient2d(tin.vertices[tin.triangles[t].v[(e + 1) % 3]],
                                      tin.vertices[tin.triangles[t].v[(e + 2) % 3]],
                                      dtm::Point2{10.5, 80.25}),
                  0);
    }
}

}  // namespace
