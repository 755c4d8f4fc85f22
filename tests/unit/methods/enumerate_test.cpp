// SPDX-License-Identifier: MIT
// [enumerate] Exact counts: the [HOSCH] 6-point set has 10 triangulations (R13) with the max-min
// optimum the Delaunay one and the min-max optimum T5 (R14); convex n-gons give Catalan numbers;
// known counts of small configurations; every triangulation valid and distinct; input refused
// beyond 12 points.
#include "methods/enumerate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "dtm/algo/criteria.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm::methods {
namespace {

MethodResult enumerate(const std::vector<Point3>& points) {
    return run_enumerate(MethodInput{points, {}}, MethodOptions{}, Progress{});
}

std::set<std::set<std::array<VertexIndex, 3>>> triangle_sets(const std::vector<Tin>& all) {
    std::set<std::set<std::array<VertexIndex, 3>>> out;
    for (const Tin& t : all) {
        std::set<std::array<VertexIndex, 3>> s;
        for (const Triangle& tri : t.triangles) {
            std::array<VertexIndex, 3> v = tri.v;
            std::sort(v.begin(), v.end());
            s.insert(v);
        }
        out.insert(s);
    }
    return out;
}

void expect_valid_and_distinct(const MethodResult& r, std::size_t n, std::size_t hull) {
    for (const Tin& t : r.all) {
        EXPECT_TRUE(verify_topology(t).ok()) << verify_topology(t).text();
        EXPECT_EQ(t.triangles.size(), 2 * n - 2 - hull);
    }
    EXPECT_EQ(triangle_sets(r.all).size(), r.all.size());
}

const std::vector<Point3> kHosch{{5, 9, 0},   {2, 5, 0},   {4, 2, 0},
                                 {7, 1.5, 0}, {8.5, 4, 0}, {5, 8, 0}};

TEST(Enumerate, HoschSetHasTenTriangulations) {
    const MethodResult r = enumerate(kHosch);
    ASSERT_EQ(r.all.size(), 10u);
    expect_valid_and_distinct(r, 6, 5);
    // The max-min optimum is the Delaunay triangulation (T10 = 126, 156, 236, 345, 356).
    TerrainInput input;
    input.points = kHosch;
    const auto delaunay = test::triangle_set(triangulate(input).tin);
    std::size_t maxmin = 0, minmax = 0;
    for (std::size_t i = 1; i < r.all.size(); ++i) {
        if (compare_quality(quality_vector(r.all[i], Criterion::maxmin_angle),
                            quality_vector(r.all[maxmin], Criterion::maxmin_angle),
                            Criterion::maxmin_angle) > 0) {
            maxmin = i;
        }
        if (compare_quality(quality_vector(r.all[i], Criterion::minmax_angle),
                            quality_vector(r.all[minmax], Criterion::minmax_angle),
                            Criterion::minmax_angle) > 0) {
            minmax = i;
        }
    }
    EXPECT_EQ(test::triangle_set(r.all[maxmin]), delaunay);
    // T5 = 126, 156, 236, 346, 456 (0-based: 015, 045, 125, 235, 345).
    const std::set<std::array<VertexIndex, 3>> t5{
        {0, 1, 5}, {0, 4, 5}, {1, 2, 5}, {2, 3, 5}, {3, 4, 5}};
    EXPECT_EQ(*triangle_sets({r.all[minmax]}).begin(), t5);
    // The stats name the same optima and the single Delaunay triangulation.
    const std::string idx = "\"index\": " + std::to_string(minmax + 1);
    EXPECT_NE(r.stats_json.find("\"minmax-angle\": {" + idx), std::string::npos) << r.stats_json;
    EXPECT_NE(r.stats_json.find("\"delaunay\": [" + std::to_string(maxmin + 1) + "]"),
              std::string::npos);
    EXPECT_NE(r.stats_json.find("\"triangulations\": 10"), std::string::npos);
}

TEST(Enumerate, ConvexPolygonsGiveCatalanNumbers) {
    const std::size_t catalan[] = {1, 1, 2, 5, 14, 42, 132, 429, 1430, 4862, 16796};
    for (std::size_t n = 3; n <= 12; ++n) {
        std::vector<Point3> pts;
        for (std::size_t i = 0; i < n; ++i) {
            const double a =
                2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n) + 0.1;
            pts.push_back({std::cos(a) * (1 + 0.01 * static_cast<double>(i)), std::sin(a), 0});
        }
        const MethodResult r = enumerate(pts);
        EXPECT_EQ(r.all.size(), catalan[n - 2]) << n;
        if (n <= 9) expect_valid_and_distinct(r, n, n);
    }
}

TEST(Enumerate, SmallConfigurations) {
    // A triangle with one point inside: 1. A square with its centre: 1 (both diagonals pass
    // through the centre, so it joins all four corners).
    EXPECT_EQ(enumerate({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}}).all.size(), 1u);
    EXPECT_EQ(enumerate({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 0}}).all.size(), 1u);
    // A square with an off-centre point: 3 (joined to all four corners, or either diagonal with
    // the point joined to the three corners of its half).
    const MethodResult off = enumerate({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {1, 2, 0}});
    EXPECT_EQ(off.all.size(), 3u);
    expect_valid_and_distinct(off, 5, 4);
    // Collinear points on the hull: a triangle with a midpoint on one side: 1 (two triangles).
    EXPECT_EQ(enumerate({{0, 0, 0}, {2, 0, 0}, {4, 0, 0}, {2, 3, 0}}).all.size(), 1u);
    // The 3 x 3 grid has 64 triangulations (a known count; heavily cocircular).
    std::vector<Point3> grid;
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) grid.push_back({double(i), double(j), 0});
    }
    const MethodResult g = enumerate(grid);
    expect_valid_and_distinct(g, 9, 8);
    EXPECT_EQ(g.all.size(), 64u);
}

TEST(Enumerate, RandomSetsMatchTriangleCountAndContainTheDelaunayOne) {
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        const auto pts = test::random_points(9, seed);
        const MethodResult r = enumerate(pts);
        TerrainInput input;
        input.points = pts;
        const auto dt = test::triangle_set(triangulate(input).tin);
        int found = 0;
        for (const Tin& t : r.all) found += test::triangle_set(t) == dt;
        EXPECT_EQ(found, 1);
        EXPECT_GT(r.all.size(), 10u);
    }
}

TEST(Enumerate, RefusesLargeOrDegenerateInput) {
    EXPECT_THROW((void)enumerate(test::random_points(13, 1)), InputError);
    EXPECT_THROW((void)enumerate({{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}), InputError);
    // Duplicates are merged and counted.
    const MethodResult r = enumerate({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 5}});
    EXPECT_EQ(r.all.size(), 1u);
    EXPECT_EQ(r.counters.extra.at("duplicates"), 1u);
}

}  // namespace
}  // namespace dtm::methods
