// SPDX-License-Identifier: MIT
// Lawson optimisation under every criterion: locally optimal results (checked independently by
// count_improvable_edges), breaklines kept, the global measure improved, maxmin-angle = the CDT
// (R15: from any start), identical output for every thread count, the flip budget honoured, and
// the data-dependent criteria lowering the interpolation error on a ridge terrain.
#include "dtm/algo/optimize.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/geom/predicates.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm {
namespace {

bool same_triangles(const Tin& a, const Tin& b) {
    if (a.triangles.size() != b.triangles.size()) return false;
    for (std::size_t i = 0; i < a.triangles.size(); ++i) {
        if (a.triangles[i].v != b.triangles[i].v || a.triangles[i].n != b.triangles[i].n)
            return false;
    }
    return true;
}

TerrainInput breakline_input() {
    TerrainInput input;
    input.points = test::random_points(600, 21);
    for (Point3& p : input.points) p.z = 0.02 * p.x + 5 * std::sin(p.y / 90.0);
    input.breaklines.push_back(Polyline{{{100, 100, 3}, {500, 420, 9}, {900, 300, 4}}, false, {}});
    input.breaklines.push_back(Polyline{{{200, 800, 1}, {800, 700, 2}}, false, {}});
    return input;
}

TEST(Optimize, EveryCriterionEndsLocallyOptimalKeepingBreaklines) {
    const TerrainInput input = breakline_input();
    const TriangulateResult cdt = triangulate(input);
    for (const Criterion c : all_criteria()) {
        Tin tin = cdt.tin;
        const OptimizeStats s = optimize_tin(tin, {.criterion = c});
        SCOPED_TRACE(std::string(criterion_name(c)));
        EXPECT_TRUE(s.converged);
        EXPECT_EQ(s.improvable_after, 0u);
        EXPECT_EQ(count_improvable_edges(tin, c), 0u);
        EXPECT_TRUE(verify_topology(tin).ok()) << verify_topology(tin).text();
        EXPECT_TRUE(verify_constraints(tin, input, cdt.input_to_vertex).ok());
        EXPECT_EQ(tin.vertices, cdt.tin.vertices);
        EXPECT_EQ(tin.constraints, cdt.tin.constraints);
        EXPECT_EQ(tin.triangles.size(), cdt.tin.triangles.size());
        if (c == Criterion::delaunay || c == Criterion::maxmin_angle) {
            EXPECT_EQ(s.flips, 0u);
            EXPECT_TRUE(same_triangles(tin, cdt.tin));
        } else {
            // The Delaunay TIN also minimises the largest circumradius (locally too).
            if (c != Criterion::minmax_circumradius) {
                EXPECT_GT(s.flips, 0u);
                EXPECT_GT(s.improvable_before, 0u);
            }
            // The global measure never gets worse.
            EXPECT_GE(compare_quality(quality_vector(tin, c), quality_vector(cdt.tin, c), c), 0);
        }
    }
}

TEST(Optimize, MaxMinAngleFromAnyStartGivesTheDelaunayTin) {  // R15
    TerrainInput input;
    input.points = test::random_points(800, 5);
    const Tin dt = triangulate(input).tin;
    for (const Criterion start : {Criterion::minmax_angle, Criterion::maxmin_area,
                                  Criterion::shortest_diagonal, Criterion::normal_jump}) {
        Tin tin = dt;
        (void)optimize_tin(tin, {.criterion = start});
        ASSERT_NE(test::triangle_set(tin), test::triangle_set(dt)) << criterion_name(start);
        const OptimizeStats s = optimize_tin(tin, {.criterion = Criterion::maxmin_angle});
        EXPECT_GT(s.flips, 0u);
        EXPECT_EQ(test::triangle_set(tin), test::triangle_set(dt)) << criterion_name(start);
        EXPECT_TRUE(verify_constrained_delaunay(tin).ok());
    }
}

TEST(Optimize, SameResultForEveryThreadCount) {
    const TriangulateResult cdt = triangulate(breakline_input());
    for (const Criterion c : {Criterion::minmax_angle, Criterion::normals_angle}) {
        Tin one = cdt.tin;
        Tin two = cdt.tin;
        Tin all = cdt.tin;
        const auto s1 = optimize_tin(one, {.criterion = c, .threads = 1});
        const auto s2 = optimize_tin(two, {.criterion = c, .threads = 2});
        (void)optimize_tin(all, {.criterion = c, .threads = 0});
        EXPECT_EQ(s1.flips, s2.flips);
        EXPECT_TRUE(same_triangles(one, two));
        EXPECT_TRUE(same_triangles(one, all));
    }
}

TEST(Optimize, FlipBudgetStopsAndSaysSo) {
    Tin tin = triangulate(breakline_input()).tin;
    const OptimizeStats s =
        optimize_tin(tin, {.criterion = Criterion::minmax_angle, .max_flips = 3});
    EXPECT_FALSE(s.converged);
    EXPECT_EQ(s.flips, 3u);
    EXPECT_GT(s.improvable_after, 0u);
    EXPECT_TRUE(verify_topology(tin).ok());
}

TEST(Optimize, CocircularGridTerminates) {
    TerrainInput input;
    input.points = test::tilted_grid(25, 25, 2.0, 0.3, 100, 100);
    const Tin dt = triangulate(input).tin;
    for (const Criterion c : all_criteria()) {
        Tin tin = dt;
        const OptimizeStats s = optimize_tin(tin, {.criterion = c});
        EXPECT_TRUE(s.converged) << criterion_name(c);
        EXPECT_EQ(count_improvable_edges(tin, c), 0u) << criterion_name(c);
        EXPECT_TRUE(verify_topology(tin).ok());
    }
}

/// z at (x, y) by linear interpolation in @p tin (brute force), NaN outside.
double interpolate(const Tin& tin, double x, double y) {
    const Point3 q{x, y, 0};
    for (const Triangle& t : tin.triangles) {
        const Point3& a = tin.vertices[t.v[0]];
        const Point3& b = tin.vertices[t.v[1]];
        const Point3& c = tin.vertices[t.v[2]];
        if (geom::orient2d(a, b, q) < 0 || geom::orient2d(b, c, q) < 0 ||
            geom::orient2d(c, a, q) < 0) {
            continue;
        }
        const double det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        const double l1 = ((x - a.x) * (c.y - a.y) - (y - a.y) * (c.x - a.x)) / det;
        const double l2 = ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)) / det;
        return a.z + l1 * (b.z - a.z) + l2 * (c.z - a.z);
    }
    return std::nan("");
}

TEST(Optimize, DataDependentCriteriaFollowARidge) {
    // A sharp ridge oblique to a jittered grid: Delaunay cuts across it, the data-dependent
    // criteria align edges with it (Dyn, Levin and Rippa's motivating case).
    auto f = [](double x, double y) { return 20.0 - 2.0 * std::abs(x - 0.6 * y - 10.0); };
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    TerrainInput input;
    for (int j = 0; j <= 30; ++j) {
        for (int i = 0; i <= 30; ++i) {
            const double x = i + jitter(rng);
            const double y = j + jitter(rng);
            input.points.push_back({x, y, f(x, y)});
        }
    }
    const Tin dt = triangulate(input).tin;
    auto rms = [&](const Tin& tin) {
        std::mt19937_64 r(9);
        std::uniform_real_distribution<double> u(2.0, 28.0);
        double sum = 0;
        int n = 0;
        for (int k = 0; k < 4000; ++k) {
            const double x = u(r), y = u(r);
            const double z = interpolate(tin, x, y);
            if (std::isnan(z)) continue;
            sum += (z - f(x, y)) * (z - f(x, y));
            ++n;
        }
        return std::sqrt(sum / n);
    };
    const double e_dt = rms(dt);
    for (const Criterion c : {Criterion::normals_angle, Criterion::normal_jump}) {
        Tin tin = dt;
        const OptimizeStats s = optimize_tin(tin, {.criterion = c});
        EXPECT_GT(s.flips, 0u);
        EXPECT_LT(s.after.sum, s.before.sum);
        EXPECT_LT(rms(tin), 0.8 * e_dt) << criterion_name(c) << ": " << rms(tin) << " vs " << e_dt;
    }
}

}  // namespace
}  // namespace dtm
