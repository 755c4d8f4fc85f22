// SPDX-License-Identifier: MIT
// [monotone] R20-R26: every constraint present, a valid triangulation of the hull (or of the
// bounding rectangle), regularisation and chain weights checked by the method itself (it throws
// otherwise), k - 3 diagonals per monotone polygon; degenerate inputs (equal y everywhere on a
// grid, collinear runs, horizontal constraints, S-JTSK magnitudes).
#include "methods/monotone.hpp"

#include <gtest/gtest.h>

#include <set>

#include "dtm/algo/criteria.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/methods/point_sets.hpp"
#include "methods/detail/counting_predicates.hpp"
#include "methods/detail/point_set.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm::methods {
namespace {

MethodResult monotone(const std::vector<Point3>& pts,
                      const std::vector<Segment>& segments = {},
                      const std::string& domain = "hull") {
    MethodOptions options;
    options.params["domain"] = domain;
    return run_monotone(MethodInput{pts, segments}, options, Progress{});
}

bool has_edge(const Tin& tin, VertexIndex a, VertexIndex b) {
    for (const Triangle& t : tin.triangles) {
        for (int s = 0; s < 3; ++s) {
            const VertexIndex p = t.v[(s + 1) % 3];
            const VertexIndex q = t.v[(s + 2) % 3];
            if ((p == a && q == b) || (p == b && q == a)) return true;
        }
    }
    return false;
}

void expect_triangulation_of_hull(const MethodResult& r, std::size_t n) {
    ASSERT_TRUE(verify_topology(r.tin).ok()) << verify_topology(r.tin).text();
    EXPECT_EQ(r.tin.vertices.size(), n);
    detail::CountingPredicates pred;
    const std::size_t h = detail::hull_boundary(r.tin.vertices, pred).size();
    EXPECT_EQ(r.tin.triangles.size(), 2 * n - 2 - h);
    EXPECT_EQ(r.counters.extra.at("monotone_polygons") + r.counters.extra.at("diagonals"),
              r.tin.triangles.size());  // a k-gon gives k - 2 triangles from k - 3 diagonals
    EXPECT_GT(r.counters.extra.at("chains"), 0u);
}

TEST(Monotone, RandomPointsWithConstraints) {
    std::vector<Point3> pts = dtm::test::random_points(800, 3);
    std::vector<Segment> segments;
    // A zig-zag breakline and a horizontal one (equal y: the tilted order decides).
    const std::vector<Point3> line{{50, 500, 0}, {300, 620, 0}, {500, 400, 0}, {950, 600, 0}};
    for (const Point3& q : line) pts.push_back(q);
    for (VertexIndex i = 800; i + 1 < 804; ++i) segments.emplace_back(i, i + 1);
    pts.push_back({100, 200, 0});
    pts.push_back({900, 200, 0});
    segments.emplace_back(804, 805);
    const MethodResult r = monotone(pts, segments);
    expect_triangulation_of_hull(r, pts.size());
    for (const auto& [a, b] : segments) EXPECT_TRUE(has_edge(r.tin, a, b)) << a << "-" << b;
    EXPECT_EQ(r.tin.constraints.size(), segments.size());
    EXPECT_GT(r.counters.extra.at("regularisation_pass1"), 0u);
    EXPECT_GT(r.counters.extra.at("regularisation_pass2"), 0u);
}

TEST(Monotone, GridsCollinearRunsAndSjtsk) {
    for (const Distribution d : {Distribution::grid, Distribution::collinear, Distribution::circle,
                                 Distribution::arc, Distribution::cluster}) {
        PointSetOptions o;
        o.x0 = dtm::test::sjtsk_e;
        o.y0 = dtm::test::sjtsk_n;
        o.quantum = d == Distribution::circle ? 0.0 : 0.001;
        const std::vector<Point3> pts = generate_points(d, 600, 5, o);
        detail::CountingPredicates pred;
        const MethodInput in{pts, {}};
        const std::size_t distinct = detail::prepare_input(in, "t", pred).points.size();
        SCOPED_TRACE(std::string(distribution_name(d)));
        expect_triangulation_of_hull(monotone(pts), distinct);
    }
}

TEST(Monotone, ManyConstraintsFromADelaunayTriangulation) {
    // Every third Delaunay edge as a constraint: many non-crossing segments, on degenerate sets.
    for (const Distribution d :
         {Distribution::uniform, Distribution::grid, Distribution::collinear}) {
        const std::vector<Point3> pts = generate_points(d, 700, 2);
        detail::CountingPredicates pred;
        const auto prepared = detail::prepare_input(MethodInput{pts, {}}, "t", pred);
        TerrainInput terrain;
        terrain.points = prepared.points;
        const Tin dt = triangulate(terrain).tin;
        std::vector<Segment> segments;
        std::size_t k = 0;
        for (const Triangle& t : dt.triangles) {
            for (int s = 0; s < 3; ++s) {
                if (t.n[s] != no_triangle && (k++ % 3) == 0) {
                    segments.emplace_back(t.v[(s + 1) % 3], t.v[(s + 2) % 3]);
                }
            }
        }
        const MethodResult r = monotone(prepared.points, segments);
        SCOPED_TRACE(std::string(distribution_name(d)));
        expect_triangulation_of_hull(r, prepared.points.size());
        for (const auto& [a, b] : segments) ASSERT_TRUE(has_edge(r.tin, a, b));
    }
}

TEST(Monotone, RectangleDomainAddsTheCorners) {
    const std::vector<Point3> pts = dtm::test::random_points(300, 8, 0, 0, 100);
    const MethodResult r = monotone(pts, {{0, 1}}, "rectangle");
    ASSERT_TRUE(verify_topology(r.tin).ok()) << verify_topology(r.tin).text();
    EXPECT_EQ(r.tin.vertices.size(), 304u);
    EXPECT_EQ(r.counters.extra.at("corners_added"), 4u);
    // The hull is the rectangle: its corners and the extreme points on its sides.
    detail::CountingPredicates pred;
    EXPECT_EQ(detail::hull_boundary(r.tin.vertices, pred).size(), 8u);
    EXPECT_EQ(r.tin.triangles.size(), 2u * 304 - 2 - 8);
    EXPECT_TRUE(has_edge(r.tin, 0, 1));
    // The area is the rectangle's.
    Box2 box;
    for (const Point3& q : pts) box.add(q);
    EXPECT_NEAR(tin_area(r.tin), (box.xmax - box.xmin) * (box.ymax - box.ymin), 1e-6);
}

TEST(Monotone, RejectsCrossingConstraintsAndUnknownDomain) {
    const std::vector<Point3> pts{{0, 0, 0}, {2, 2, 0}, {0, 2, 0}, {2, 0, 0}};
    EXPECT_THROW((void)monotone(pts, {{0, 1}, {2, 3}}), InputError);
    EXPECT_THROW((void)monotone(pts, {}, "disc"), UsageError);
}

TEST(Monotone, WorseQualityThanTheCdt) {
    // No criterion is applied: the stack method leaves long thin triangles the CDT avoids.
    const std::vector<Point3> pts = dtm::test::random_points(500, 12);
    const MethodResult r = monotone(pts);
    EXPECT_GT(count_improvable_edges(r.tin, Criterion::maxmin_angle), 0u);
}

}  // namespace
}  // namespace dtm::methods
