// SPDX-License-Identifier: MIT
// Thiessen polygons: the cells tile the clip region (areas add up to it), each cell holds its
// point, cells meet exactly across Delaunay edges; on degenerate input (grids with the boundary
// through bisectors and Voronoi vertices, collinear points, one point) the same holds.
#include "dtm/algo/thiessen.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm {
namespace {

bool inside(const ThiessenCell& cell, const Point3& p) {
    int crossings = 0;
    for (const ThiessenPolygon& poly : cell.polygons) {
        for (const auto& ring : poly.rings) {
            for (const Point2& q : ring) {
                if (q.x == p.x && q.y == p.y) return true;  // a hull point: a corner of its cell
            }
        }
    }
    for (const ThiessenPolygon& poly : cell.polygons) {
        for (const auto& ring : poly.rings) {
            for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
                const Point2& a = ring[i];
                const Point2& b = ring[(i + 1) % n];
                if ((a.y > p.y) != (b.y > p.y)) {
                    const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                    if (x > p.x) ++crossings;
                }
            }
        }
    }
    return crossings % 2 == 1;
}

struct Case {
    std::vector<Point3> sites;
    Tin delaunay;
};

Case with_delaunay(std::vector<Point3> pts) {
    Case c;
    c.sites = pts;
    c.delaunay = triangulate(TerrainInput{pts, {}, {}, {}, {}, {}}).tin;
    return c;
}

void expect_tiling(const Case& c, const Tin& region, const ThiessenResult& r, bool all_inside) {
    double sum = 0.0;
    for (const ThiessenCell& cell : r.cells) sum += cell.area;
    EXPECT_NEAR(sum, r.region_area, 1e-9 * r.region_area);
    EXPECT_NEAR(r.region_area, tin_area(region), 1e-9 * r.region_area);
    std::set<std::pair<VertexIndex, VertexIndex>> delaunay_edges;
    for (const Triangle& t : c.delaunay.triangles) {
        for (int i = 0; i < 3; ++i) delaunay_edges.insert(std::minmax(t.v[i], t.v[(i + 1) % 3]));
    }
    for (VertexIndex g = 0; g < r.cells.size(); ++g) {
        const ThiessenCell& cell = r.cells[g];
        if (all_inside) {
            EXPECT_FALSE(cell.polygons.empty()) << g;
            EXPECT_TRUE(inside(cell, c.sites[g])) << g;
        }
        for (const VertexIndex h : cell.neighbours) {
            EXPECT_TRUE(delaunay_edges.count(std::minmax(g, h)) || c.delaunay.triangles.empty())
                << g << " " << h;
            EXPECT_TRUE(
                std::binary_search(r.cells[h].neighbours.begin(), r.cells[h].neighbours.end(), g));
        }
    }
}

TEST(Thiessen, RandomPointsTileTheirHull) {
    const Case c = with_delaunay(test::random_points(2000, 3));
    const Tin region = clip_region_of_hull(c.delaunay);
    const ThiessenResult r = thiessen_cells(c.sites, c.delaunay, region);
    expect_tiling(c, region, r, true);
    EXPECT_EQ(r.empty_cells, 0u);
}

}  // namespace
}  // namespace dtm
namespace dtm {
namespace {
TEST(Thiessen, MirroredSurveyCoordinates) {
    auto pts = test::random_points(3000, 4);
    for (Point3& p : pts) p = {-p.y, -p.x, p.z};  // as a Krovak reader writes them
    const Case c = with_delaunay(pts);
    const Tin region = clip_region_of_hull(c.delaunay);
    const ThiessenResult r = thiessen_cells(c.sites, c.delaunay, region);
    EXPECT_GT(r.region_area, 0.99e6);
    expect_tiling(c, region, r, true);
}
}  // namespace
}  // namespace dtm
namespace dtm {
namespace {

Polyline ring(std::vector<std::pair<double, double>> xy) {
    Polyline p;
    for (const auto& [x, y] : xy) p.points.push_back({x, y, 0.0});
    p.closed = true;
    return p;
}

// A non-convex boundary with a hole; some points outside it (their cells may be empty or cut).
TEST(Thiessen, BoundaryWithAHole) {
    const Case c = with_delaunay(test::random_points(1500, 8, -100.0, -100.0, 1200.0));
    const std::vector<Polyline> outer{
        ring({{0, 0}, {1000, 0}, {1000, 1000}, {500, 400}, {0, 1000}})};
    const std::vector<Polyline> holes{ring({{400, 100}, {600, 100}, {600, 250}, {400, 250}})};
    const Tin region = clip_region_of_rings(outer, holes);
    const ThiessenResult r = thiessen_cells(c.sites, c.delaunay, region);
    EXPECT_NEAR(r.region_area, 1000.0 * 1000.0 - 0.5 * 1000 * 600 - 200.0 * 150.0, 1e-6);
    expect_tiling(c, region, r, false);
    EXPECT_GT(r.empty_cells, 0u);
}

// Grid points with the boundary on half-integers: boundary corners on bisectors and on Voronoi
// vertices, region edges along bisectors: exact ties everywhere.
TEST(Thiessen, GridWithTheBoundaryThroughBisectors) {
    std::vector<Point3> pts;
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 9; ++i) pts.push_back({double(i), double(j), double(i + j)});
    }
    const Case c = with_delaunay(pts);
    const std::vector<Polyline> outer{
        ring({{-0.5, -0.5}, {8.5, -0.5}, {8.5, 7.5}, {3.5, 7.5}, {3.5, 3.5}, {-0.5, 3.5}})};
    const std::vector<Polyline> holes{ring({{5.5, 1.5}, {6.5, 1.5}, {6.5, 2.5}, {5.5, 2.5}})};
    const Tin region = clip_region_of_rings(outer, holes);
    const ThiessenResult r = thiessen_cells(c.sites, c.delaunay, region);
    expect_tiling(c, region, r, false);
    // Every cell is a unit square, all of it inside or outside, except (6, 2) which is the hole.
    std::size_t full = 0;
    for (VertexIndex g = 0; g < r.cells.size(); ++g) {
        if (r.cells[g].polygons.empty()) continue;
        EXPECT_NEAR(r.cells[g].area, 1.0, 1e-12) << g;
        ASSERT_EQ(r.cells[g].polygons.size(), 1u);
        EXPECT_EQ(r.cells[g].polygons[0].rings.size(), 1u);
        ++full;
    }
    EXPECT_EQ(full, 9u * 4u + 5u * 4u - 1u);
}

TEST(Thiessen, CollinearPointsAndOnePoint) {
    std::vector<Point3> pts{{0, 0, 1}, {2, 0, 2}, {5, 0, 3}};
    Case c;
    c.sites = pts;
    c.delaunay.vertices = pts;  // collinear: no triangle
    const std::vector<Polyline> outer{ring({{-1, -1}, {6, -1}, {6, 1}, {-1, 1}})};
    const Tin region = clip_region_of_rings(outer, {});
    const ThiessenResult r = thiessen_cells(c.sites, c.delaunay, region);
    ASSERT_EQ(r.cells.size(), 3u);
    EXPECT_NEAR(r.cells[0].area, 2.0 * 2.0, 1e-12);  // x in [-1, 1]
    EXPECT_NEAR(r.cells[1].area, 2.5 * 2.0, 1e-12);  // [1, 3.5]
    EXPECT_NEAR(r.cells[2].area, 2.5 * 2.0, 1e-12);  // [3.5, 6]
    EXPECT_THROW((void)clip_region_of_hull(c.delaunay), InputError);

    Case one;
    one.sites = {{2, 0, 7}};
    one.delaunay.vertices = one.sites;
    const ThiessenResult r1 = thiessen_cells(one.sites, one.delaunay, region);
    EXPECT_NEAR(r1.cells[0].area, 14.0, 1e-12);
}

}  // namespace
}  // namespace dtm
