// SPDX-License-Identifier: MIT
// SurfaceSampler against brute force: every query located by scanning all triangles with the
// exact predicates, heights of a plane reproduced, the nearest vertex found by a full scan, on
// convex, constrained and non-convex TINs (boundary, hole), from several threads.
#include "dtm/algo/surface_sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/geom/predicates.hpp"

namespace {

using dtm::Point2;
using dtm::SurfaceSampler;
using dtm::TinLocation;

double plane(double x, double y) { return 2.0 * x - 3.0 * y + 100.0; }

dtm::TerrainInput random_points(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    dtm::TerrainInput in;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = u(rng);
        const double y = u(rng);
        in.points.push_back({x, y, plane(x, y)});
    }
    return in;
}

/// Every triangle that contains @p p (interior, edge or vertex), by a full scan.
std::vector<dtm::TriangleIndex> containing(const dtm::Tin& tin, Point2 p) {
    std::vector<dtm::TriangleIndex> found;
    for (dtm::TriangleIndex t = 0; t < tin.triangles.size(); ++t) {
        const auto& v = tin.triangles[t].v;
        bool inside = true;
        for (unsigned s = 0; s < 3 && inside; ++s) {
            inside =
                dtm::geom::orient2d(tin.vertex(v[(s + 1) % 3]), tin.vertex(v[(s + 2) % 3]), p) >= 0;
        }
        if (inside) found.push_back(t);
    }
    return found;
}

dtm::VertexIndex brute_nearest(const dtm::Tin& tin, Point2 p) {
    std::vector<bool> used(tin.vertices.size(), false);
    for (const auto& t : tin.triangles) {
        for (const auto v : t.v) used[v] = true;
    }
    double best = INFINITY;
    dtm::VertexIndex at = dtm::no_vertex;
    for (dtm::VertexIndex v = 0; v < tin.vertices.size(); ++v) {
        const double dx = tin.vertices[v].x - p.x;
        const double dy = tin.vertices[v].y - p.y;
        if (used[v] && dx * dx + dy * dy < best) {
            best = dx * dx + dy * dy;
            at = v;
        }
    }
    return at;
}

/// Locations of many random points (some beyond the data) agree with the full scan.
void expect_locations_match_brute_force(const dtm::Tin& tin, unsigned seed, std::size_t queries) {
    const SurfaceSampler sampler(tin);
    SurfaceSampler::Cursor cursor;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-10.0, 110.0);
    std::size_t inside = 0;
    for (std::size_t i = 0; i < queries; ++i) {
        const Point2 p{u(rng), u(rng)};
        if (i % 3 == 0) cursor = {};  // also walk from the start grid
        const TinLocation where = sampler.locate(p, cursor);
        const auto truth = containing(tin, p);
        ASSERT_EQ(where.kind == TinLocation::Kind::outside, truth.empty()) << p.x << " " << p.y;
        if (truth.empty()) {
            EXPECT_TRUE(std::isnan(sampler.height(p, cursor)));
            continue;
        }
        ++inside;
        EXPECT_NE(std::find(truth.begin(), truth.end(), where.edge.triangle), truth.end());
        EXPECT_EQ(where.kind == TinLocation::Kind::triangle, truth.size() == 1);
    }
    EXPECT_GT(inside, queries / 4);
}

TEST(SurfaceSampler, ReproducesAPlaneInsideAndIsExactOnVertices) {
    const dtm::Tin tin = dtm::triangulate(random_points(2000, 1)).tin;
    const SurfaceSampler sampler(tin);
    SurfaceSampler::Cursor cursor;
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(20.0, 80.0);
    for (int i = 0; i < 2000; ++i) {
        const Point2 p{u(rng), u(rng)};
        EXPECT_NEAR(sampler.height(p, cursor), plane(p.x, p.y), 1e-9);
    }
    for (const dtm::Point3& v : tin.vertices) {
        const TinLocation where = sampler.locate({v.x, v.y}, cursor);
        EXPECT_EQ(where.kind, TinLocation::Kind::vertex);
        EXPECT_EQ(sampler.height({v.x, v.y}, cursor), v.z);  // bit-exact
    }
}

TEST(SurfaceSampler, PointsOnAnEdgeGetTheSameHeightFromEitherTriangle) {
    // Integer lattice: edge midpoints are exact, and each interior edge has two triangles.
    dtm::TerrainInput in;
    for (int j = 0; j <= 10; ++j) {
        for (int i = 0; i <= 10; ++i)
            in.points.push_back({i * 1.0, j * 1.0, std::sin(i + 3.0 * j)});
    }
    const dtm::Tin tin = dtm::triangulate(in).tin;
    const SurfaceSampler sampler(tin);
    std::size_t checked = 0;
    for (dtm::TriangleIndex t = 0; t < tin.triangles.size(); ++t) {
        for (std::uint8_t s = 0; s < 3; ++s) {
            const dtm::HalfEdge e{t, s};
            const dtm::Point3& a = tin.vertex(dtm::origin(tin, e));
            const dtm::Point3& b = tin.vertex(dtm::destination(tin, e));
            const Point2 mid{(a.x + b.x) / 2.0, (a.y + b.y) / 2.0};
            SurfaceSampler::Cursor here{t};
            const TinLocation where = sampler.locate(mid, here);
            ASSERT_EQ(where.kind, TinLocation::Kind::edge);
            SurfaceSampler::Cursor fresh;
            EXPECT_EQ(sampler.height(mid, here), sampler.height(mid, fresh));
            EXPECT_NEAR(sampler.height(mid, here), (a.z + b.z) / 2.0, 1e-12);
            ++checked;
        }
    }
    EXPECT_EQ(checked, 3 * tin.triangles.size());
}

TEST(SurfaceSampler, LocatesLikeAFullScanOnAConvexTin) {
    expect_locations_match_brute_force(dtm::triangulate(random_points(500, 3)).tin, 4, 3000);
}

TEST(SurfaceSampler, LocatesLikeAFullScanOnAConstrainedTin) {
    dtm::TerrainInput in = random_points(800, 5);
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    for (int k = 0; k < 40; ++k) {  // long crossing breaklines: a far from Delaunay TIN
        dtm::Polyline line;
        for (int i = 0; i < 2; ++i) {
            const double x = u(rng);
            const double y = u(rng);
            line.points.push_back({x, y, plane(x, y)});
        }
        in.breaklines.push_back(line);
    }
    expect_locations_match_brute_force(dtm::triangulate(in).tin, 7, 3000);
}

TEST(SurfaceSampler, LocatesLikeAFullScanWithABoundaryAndAHole) {
    dtm::TerrainInput in = random_points(1500, 8);
    // a C-shaped boundary (the walk must leave and re-enter) and a square hole
    const std::vector<Point2> c{{5, 5},   {95, 5},  {95, 40}, {30, 40},
                                {30, 60}, {95, 60}, {95, 95}, {5, 95}};
    dtm::Polyline boundary;
    for (const Point2& p : c) boundary.points.push_back({p.x, p.y, plane(p.x, p.y)});
    boundary.closed = true;
    in.boundaries.push_back(boundary);
    dtm::Polyline hole;
    for (const Point2& p : std::vector<Point2>{{10, 70}, {20, 70}, {20, 80}, {10, 80}}) {
        hole.points.push_back({p.x, p.y, plane(p.x, p.y)});
    }
    hole.closed = true;
    in.holes.push_back(hole);
    const dtm::Tin tin = dtm::triangulate(in).tin;
    expect_locations_match_brute_force(tin, 9, 4000);
    const SurfaceSampler sampler(tin);
    SurfaceSampler::Cursor cursor;
    EXPECT_TRUE(std::isnan(sampler.height({60, 50}, cursor)));  // in the notch of the C
    EXPECT_TRUE(std::isnan(sampler.height({15, 75}, cursor)));  // in the hole
    EXPECT_NEAR(sampler.height({60, 80}, cursor), plane(60, 80), 1e-9);
}

TEST(SurfaceSampler, NearestVertexIsTheFullScansWithTiesToTheLowerIndex) {
    const dtm::Tin tin = dtm::triangulate(random_points(700, 10)).tin;
    const SurfaceSampler sampler(tin);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-50.0, 150.0);
    for (int i = 0; i < 2000; ++i) {
        const Point2 p{u(rng), u(rng)};
        ASSERT_EQ(sampler.nearest_vertex(p), brute_nearest(tin, p));
    }
    // Equidistant from two vertices: the lower index wins.
    dtm::Tin square;
    square.vertices = {{1, 0, 5}, {0, 0, 1}, {0, 1, 2}, {1, 1, 3}};
    square.triangles.resize(2);
    square.triangles[0].v = {1, 0, 3};
    square.triangles[1].v = {1, 3, 2};
    dtm::link_neighbours(square);
    const SurfaceSampler s2(square);
    EXPECT_EQ(s2.nearest_vertex({0.5, -1.0}), 0U);
    SurfaceSampler::Cursor cursor;
    EXPECT_EQ(s2.height_or_nearest({0.5, -1.0}, cursor), 5.0);
    EXPECT_EQ(s2.height_or_nearest({-3.0, 0.25}, cursor), 1.0);
}

TEST(SurfaceSampler, ConcurrentQueriesWithTheirOwnCursorsAgreeWithSequentialOnes) {
    dtm::TerrainInput in = random_points(3000, 12);
    dtm::Polyline boundary;
    for (const Point2& p : std::vector<Point2>{{10, 10}, {90, 10}, {50, 50}, {90, 90}, {10, 90}}) {
        boundary.points.push_back({p.x, p.y, plane(p.x, p.y)});
    }
    boundary.closed = true;
    in.boundaries.push_back(boundary);
    const dtm::Tin tin = dtm::triangulate(in).tin;
    std::vector<Point2> queries;
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-20.0, 120.0);
    for (int i = 0; i < 4000; ++i) queries.push_back({u(rng), u(rng)});
    std::vector<double> expected(queries.size());
    {
        const SurfaceSampler sampler(tin);
        SurfaceSampler::Cursor cursor;
        for (std::size_t i = 0; i < queries.size(); ++i) {
            expected[i] = sampler.height_or_nearest(queries[i], cursor);
        }
    }
    const SurfaceSampler shared(tin);  // lazy indices built under contention
    std::vector<std::vector<double>> got(4, std::vector<double>(queries.size()));
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < got.size(); ++t) {
        threads.emplace_back([&, t] {
            SurfaceSampler::Cursor cursor;
            for (std::size_t k = 0; k < queries.size(); ++k) {
                const std::size_t step[] = {1, 3, 7,
                                            11};  // coprime to 4000: a different order each
                const std::size_t i = (k * step[t]) % queries.size();
                got[t][i] = shared.height_or_nearest(queries[i], cursor);
            }
        });
    }
    for (std::thread& t : threads) t.join();
    for (const auto& g : got) {
        for (std::size_t i = 0; i < queries.size(); ++i) {
            ASSERT_EQ(g[i], expected[i]) << i;  // bit-identical
        }
    }
}

TEST(SurfaceSampler, EmptyTinHasNoHeights) {
    const dtm::Tin empty;
    const SurfaceSampler sampler(empty);
    SurfaceSampler::Cursor cursor;
    EXPECT_EQ(sampler.locate({0, 0}, cursor).kind, TinLocation::Kind::outside);
    EXPECT_TRUE(std::isnan(sampler.height_or_nearest({0, 0}, cursor)));
    EXPECT_EQ(sampler.nearest_vertex({0, 0}), dtm::no_vertex);
}

}  // namespace
