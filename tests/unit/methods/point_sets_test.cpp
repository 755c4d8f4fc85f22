// SPDX-License-Identifier: MIT
// The lab's point sets: deterministic, in the square, with the degeneracies they promise; and
// the shared validator of the methods tests accepts the production kernel's TINs of every set
// and rejects a broken one.
#include "dtm/methods/point_sets.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "dtm/geom/predicates.hpp"
#include "methods_fixtures.hpp"

namespace dtm::methods {
namespace {

using test::is_delaunay_triangulation;

TEST(PointSets, NamesRoundTrip) {
    EXPECT_EQ(all_distributions().size(), 8u);
    EXPECT_EQ(lab_distributions().size(), 4u);
    for (const Distribution d : all_distributions()) {
        EXPECT_EQ(parse_distribution(distribution_name(d)), d);
    }
    EXPECT_FALSE(parse_distribution("nonsense").has_value());
}

TEST(PointSets, DeterministicInSeedAndInsideTheSquare) {
    const PointSetOptions o{100.0, 200.0, 50.0, 0.0};
    for (const Distribution d : all_distributions()) {
        const auto a = generate_points(d, 500, 7, o);
        const auto b = generate_points(d, 500, 7, o);
        const auto c = generate_points(d, 500, 8, o);
        ASSERT_EQ(a.size(), 500u) << distribution_name(d);
        EXPECT_EQ(a, b) << distribution_name(d);
        EXPECT_NE(a, c) << distribution_name(d);
        for (const Point3& p : a) {
            EXPECT_TRUE(p.x >= 100.0 && p.x < 150.0 && p.y >= 200.0 && p.y < 250.0)
                << distribution_name(d) << " " << p.x << " " << p.y;
        }
    }
}

TEST(PointSets, FirstValuesArePinned) {
    // Bit-for-bit stability across platforms and releases: a changed generator changes the
    // lab's published figures, so it must be deliberate.
    const auto p = generate_points(Distribution::uniform, 2, 1);
    EXPECT_EQ(p[0].x, 0x1.4a71c24d334p+7);
    EXPECT_EQ(p[0].y, 0x1.edbc0e3569557p+9);
    EXPECT_EQ(p[1].x, 0x1.20d06eb64321ap+9);
    EXPECT_EQ(p[1].y, 0x1.1e5dade521d7p+8);
    const auto g = generate_points(Distribution::gauss, 1, 1);
    EXPECT_EQ(g[0].x, 0x1.6226d3bde4144p+8);
    EXPECT_EQ(g[0].y, 0x1.27c6505882f67p+9);
}

TEST(PointSets, QuantumRoundsToMillimetres) {
    const auto pts = generate_points(Distribution::uniform, 200, 3, test::sjtsk_mm());
    for (const Point3& p : pts) {
        EXPECT_EQ(p.x, std::round(p.x / 0.001) * 0.001);
        EXPECT_LT(p.x, -749000.0);
        EXPECT_GE(p.y, -1050000.0);
    }
}

TEST(PointSets, CircleIsExactlyCocircular) {
    EXPECT_EQ(max_circle_points(), 6804u);
    for (const PointSetOptions& o : {PointSetOptions{}, test::sjtsk_mm()}) {
        const auto pts = generate_points(Distribution::circle, max_circle_points(), 2, o);
        std::set<std::pair<double, double>> distinct;
        for (const Point3& p : pts) distinct.insert({p.x, p.y});
        EXPECT_EQ(distinct.size(), pts.size());
        for (std::size_t i = 3; i < pts.size(); i += 7) {
            EXPECT_EQ(geom::incircle(pts[0], pts[1], pts[2], pts[i]), 0) << i;
        }
    }
    EXPECT_THROW((void)generate_points(Distribution::circle, max_circle_points() + 1, 1),
                 std::invalid_argument);
}

TEST(PointSets, GridIsCocircularCollinearHasRunsDuplicatesRepeat) {
    const auto grid = generate_points(Distribution::grid, 100, 1);
    std::set<std::pair<double, double>> g;
    for (const Point3& p : grid) g.insert({p.x, p.y});
    EXPECT_EQ(g.size(), 100u);
    // Four corners of one lattice square are cocircular.
    std::vector<double> xs;
    for (const auto& [x, y] : g) xs.push_back(x);
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    ASSERT_GE(xs.size(), 2u);
    const double s = xs[1] - xs[0];
    EXPECT_EQ(geom::incircle(Point2{0, 0}, Point2{s, 0}, Point2{s, s}, Point2{0, s}), 0);

    const auto col = generate_points(Distribution::collinear, 400, 1);
    // A quarter of the points on each of the horizontal lines at least: many collinear runs.
    std::map<double, int> rows;
    for (const Point3& p : col) ++rows[p.y];
    int longest = 0;
    for (const auto& [y, count] : rows) longest = std::max(longest, count);
    EXPECT_GE(longest, 20);
    bool all = true;
    for (std::size_t i = 2; i < col.size(); ++i)
        all = all && geom::orient2d(col[0], col[1], col[i]) == 0;
    EXPECT_FALSE(all);

    const auto dup = generate_points(Distribution::duplicates, 300, 1);
    EXPECT_LT(test::distinct_points(dup).size(), 250u);
}

TEST(PointSets, ProductionKernelTinsPassTheSharedValidator) {
    for (const Distribution d : all_distributions()) {
        const auto pts = generate_points(d, 300, 5);
        const Tin tin = test::reference_tin(pts);
        EXPECT_TRUE(is_delaunay_triangulation(tin, pts)) << distribution_name(d);
    }
    const auto sj = generate_points(Distribution::uniform, 300, 5, test::sjtsk_mm());
    EXPECT_TRUE(is_delaunay_triangulation(test::reference_tin(sj), sj));
}

TEST(PointSets, TheValidatorRejectsBrokenTins) {
    const auto pts = generate_points(Distribution::uniform, 100, 9);
    const Tin tin = test::reference_tin(pts);
    ASSERT_TRUE(is_delaunay_triangulation(tin, pts));
    EXPECT_FALSE(is_delaunay_triangulation(test::without_first_triangle(tin), pts));
    // One shared edge unlinked on both sides: still manifold, but a missing link.
    Tin unlinked = tin;
    TriangleIndex t = 0;
    int side = 0;
    while (unlinked.triangles[t].n[static_cast<std::size_t>(side)] == no_triangle) {
        if (++side == 3) {
            side = 0;
            ++t;
        }
    }
    const TriangleIndex other = unlinked.triangles[t].n[static_cast<std::size_t>(side)];
    unlinked.triangles[t].n[static_cast<std::size_t>(side)] = no_triangle;
    for (TriangleIndex& m : unlinked.triangles[other].n) {
        if (m == t) m = no_triangle;
    }
    EXPECT_FALSE(is_delaunay_triangulation(unlinked, pts));
    Tin missing_vertex = tin;
    missing_vertex.vertices.pop_back();
    EXPECT_FALSE(is_delaunay_triangulation(missing_vertex, pts));
}

}  // namespace
}  // namespace dtm::methods
