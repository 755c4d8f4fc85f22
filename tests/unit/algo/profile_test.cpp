// SPDX-License-Identifier: MIT
#include "dtm/algo/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dtm/algo/triangulate.hpp"
#include "dtm/geom/predicates.hpp"
#include "support/solid_fixtures.hpp"

namespace {

using dtm::Point3;
using dtm::test::Square;

/// Brute force: the height of the TIN at (x, y) from the first triangle containing it.
bool brute_height(const dtm::Tin& tin, double x, double y, double& z) {
    for (const dtm::Triangle& t : tin.triangles) {
        const Point3& a = tin.vertices[t.v[0]];
        const Point3& b = tin.vertices[t.v[1]];
        const Point3& c = tin.vertices[t.v[2]];
        const dtm::Point2 p{x, y};
        if (dtm::geom::orient2d(a, b, p) >= 0 && dtm::geom::orient2d(b, c, p) >= 0 &&
            dtm::geom::orient2d(c, a, p) >= 0) {
            const double d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
            const double l1 = ((x - a.x) * (c.y - a.y) - (y - a.y) * (c.x - a.x)) / d;
            const double l2 = ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)) / d;
            z = a.z + l1 * (b.z - a.z) + l2 * (c.z - a.z);
            return true;
        }
    }
    return false;
}

dtm::Tin grid_tin(int n, double x0, double y0, bool with_hole) {
    dtm::TerrainInput in;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const double x = i;
            const double y = j;
            in.points.push_back(
                {x0 + x, y0 + y, 100.0 + 0.3 * x - 0.2 * y + 0.05 * ((i * 7 + j * 3) % 5)});
        }
    }
    if (with_hole) {
        dtm::Polyline hole;
        for (const auto& [u, v] :
             std::vector<std::pair<double, double>>{{4, 4}, {6, 4}, {6, 6}, {4, 6}, {4, 4}}) {
            hole.points.push_back({x0 + u, y0 + v, 0.0});
        }
        in.holes.push_back(hole);
    }
    return dtm::triangulate(in).tin;
}

void expect_matches_brute_force(const dtm::Tin& tin, const dtm::Profile& p) {
    for (const dtm::ProfileRun& run : p.runs) {
        for (const dtm::ProfilePoint& q : run.points) {
            double z = 0.0;
            ASSERT_TRUE(brute_height(tin, q.x, q.y, z)) << q.x << " " << q.y;
            EXPECT_NEAR(q.z, z, 1e-9);
        }
    }
}

TEST(Profile, LineAcrossATinHasABreakpointAtEveryEdgeCrossing) {
    const double x0 = -750000.0;
    const double y0 = -1050000.0;
    const dtm::Tin tin = grid_tin(10, x0, y0, false);
    const dtm::TinSection section(tin);
    const std::vector<Point3> line{{x0 + 0.5, y0 + 0.25, 0}, {x0 + 9.7, y0 + 8.1, 0}};
    const dtm::Profile p = section.cut(line);
    ASSERT_EQ(p.runs.size(), 1U);
    const auto& pts = p.runs[0].points;
    EXPECT_EQ(pts.front().chainage, 0.0);
    EXPECT_NEAR(pts.back().chainage, p.length, 1e-12);
    for (std::size_t i = 1; i < pts.size(); ++i) {
        EXPECT_GT(pts[i].chainage, pts[i - 1].chainage);
    }
    // Crossings of the grid lines x = k and y = k and of one diagonal per cell at least.
    EXPECT_GE(pts.size(), 9U + 8U + 2U);
    expect_matches_brute_force(tin, p);
    // Between breakpoints the profile is linear: check the midpoints against the brute force.
    for (std::size_t i = 1; i < pts.size(); ++i) {
        double z = 0.0;
        ASSERT_TRUE(
            brute_height(tin, (pts[i].x + pts[i - 1].x) / 2, (pts[i].y + pts[i - 1].y) / 2, z));
        EXPECT_NEAR((pts[i].z + pts[i - 1].z) / 2, z, 1e-9);
    }
}

TEST(Profile, GapsWhereTheSurfaceIsAbsent) {
    const dtm::Tin tin = grid_tin(10, 0.0, 0.0, true);
    const dtm::TinSection section(tin);
    // From outside on the west, through the hole [4, 6]^2, out on the east.
    const std::vector<Point3> line{{-3.0, 5.0, 0}, {13.0, 5.0, 0}};
    const dtm::Profile p = section.cut(line);
    ASSERT_EQ(p.runs.size(), 2U);
    EXPECT_NEAR(p.runs[0].points.front().chainage, 3.0, 1e-12);
    EXPECT_NEAR(p.runs[0].points.back().chainage, 7.0, 1e-12);
    EXPECT_NEAR(p.runs[1].points.front().chainage, 9.0, 1e-12);
    EXPECT_NEAR(p.runs[1].points.back().chainage, 13.0, 1e-12);
    EXPECT_DOUBLE_EQ(p.length, 16.0);
    expect_matches_brute_force(tin, p);
    double z = 0.0;
    EXPECT_FALSE(dtm::profile_height(p, 8.0, z));
    EXPECT_TRUE(dtm::profile_height(p, 5.0, z));
}

TEST(Profile, AlongEdgesAndThroughVerticesAndAcrossPolylineVertices) {
    const dtm::Tin tin = grid_tin(10, 0.0, 0.0, false);
    const dtm::TinSection section(tin);
    // Along the grid line y = 3 (TIN edges), then diagonally through vertices, then along the
    // border x = 10.
    const std::vector<Point3> line{
        {0.0, 3.0, 0}, {7.0, 3.0, 0}, {9.0, 5.0, 0}, {10.0, 5.0, 0}, {10.0, 9.0, 0}};
    const dtm::Profile p = section.cut(line);
    ASSERT_EQ(p.runs.size(), 1U);
    EXPECT_NEAR(p.runs[0].points.back().chainage, 7.0 + std::sqrt(8.0) + 1.0 + 4.0, 1e-12);
    expect_matches_brute_force(tin, p);
    // Every grid vertex on the line is a breakpoint with its exact height.
    int vertices_hit = 0;
    for (const dtm::ProfilePoint& q : p.runs[0].points) {
        if (q.x == std::round(q.x) && q.y == std::round(q.y)) {
            ++vertices_hit;
        }
    }
    EXPECT_GE(vertices_hit, 8 + 2 + 1 + 4);
}

TEST(Profile, RandomLinesOnARandomTinMatchTheBruteForce) {
    const Square sq{-750000.0, -1050000.0, 100.0};
    const dtm::Tin tin = dtm::test::sampled_tin(sq, 400, 3, [](double x, double y) {
        return 300.0 + 0.01 * std::fmod(x * 7.0 + y * 3.0, 13.0);
    });
    const dtm::TinSection section(tin);
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(-20.0, 120.0);
    std::vector<std::vector<Point3>> lines;
    for (int i = 0; i < 30; ++i) {
        lines.push_back({{sq.x0 + u(rng), sq.y0 + u(rng), 0},
                         {sq.x0 + u(rng), sq.y0 + u(rng), 0},
                         {sq.x0 + u(rng), sq.y0 + u(rng), 0}});
    }
    const std::vector<dtm::Profile> profiles = section.cut_all(lines);
    ASSERT_EQ(profiles.size(), lines.size());
    for (std::size_t i = 0; i < lines.size(); ++i) {
        expect_matches_brute_force(tin, profiles[i]);
        // Sample the line densely: the profile has a height exactly where the brute force does.
        for (int k = 0; k <= 200; ++k) {
            const double c = std::min(profiles[i].length * k / 200.0, profiles[i].length);
            double remaining = c;
            Point3 at = lines[i][0];
            for (std::size_t s = 0; s + 1 < lines[i].size(); ++s) {
                const double l = std::hypot(lines[i][s + 1].x - lines[i][s].x,
                                            lines[i][s + 1].y - lines[i][s].y);
                const double t = std::min(remaining / l, 1.0);
                at = {lines[i][s].x + t * (lines[i][s + 1].x - lines[i][s].x),
                      lines[i][s].y + t * (lines[i][s + 1].y - lines[i][s].y), 0};
                if (remaining <= l) break;
                remaining -= l;
            }
            double zb = 0.0;
            double zp = 0.0;
            const bool inside = brute_height(tin, at.x, at.y, zb);
            const bool has = dtm::profile_height(profiles[i], c, zp);
            // Points within rounding of the border may go either way.
            if (inside == has) {
                if (inside) {
                    EXPECT_NEAR(zp, zb, 1e-6);
                }
            } else {
                const double e = 1e-6;
                EXPECT_TRUE(at.x < sq.x0 + e || at.x > sq.x0 + 100 - e || at.y < sq.y0 + e ||
                            at.y > sq.y0 + 100 - e)
                    << "line " << i << " chainage " << c;
            }
        }
    }
}

}  // namespace
