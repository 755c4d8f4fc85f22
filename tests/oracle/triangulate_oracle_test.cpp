// SPDX-License-Identifier: MIT
// dtm's triangulation against CGAL's (test-only oracle): on inputs in general position the
// constrained Delaunay triangulation is unique, so the triangle sets must be equal.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <random>

#include "dtm/algo/triangulate.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag>;
using Dt = CGAL::Delaunay_triangulation_2<K>;

template <class T>
std::set<test::XyTriangle> cgal_triangle_set(const T& t) {
    std::set<test::XyTriangle> out;
    for (auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
        test::XyTriangle tri;
        for (int i = 0; i < 3; ++i) tri[i] = {f->vertex(i)->point().x(), f->vertex(i)->point().y()};
        int k = 0;
        for (int i = 1; i < 3; ++i)
            if (tri[i] < tri[k]) k = i;
        out.insert({tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]});
    }
    return out;
}

std::vector<K::Point_2> cgal_points(const std::vector<Point3>& pts) {
    std::vector<K::Point_2> out;
    for (const Point3& p : pts) out.emplace_back(p.x, p.y);
    return out;
}

class OracleSeeds : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(OracleSeeds, DelaunayEqualsCgalOnRandomPoints) {
    TerrainInput input;
    input.points = test::random_points(20000, GetParam(), test::sjtsk_e, test::sjtsk_n);
    const auto pts = cgal_points(input.points);
    Dt dt(pts.begin(), pts.end());
    EXPECT_EQ(test::triangle_set(triangulate(input).tin), cgal_triangle_set(dt));
}

TEST_P(OracleSeeds, ConstrainedDelaunayEqualsCgalWithBreaklines) {
    TerrainInput input;
    input.points = test::random_points(10000, GetParam(), test::sjtsk_e, test::sjtsk_n);
    std::mt19937_64 rng(GetParam() + 100);
    std::uniform_real_distribution<double> jitter(-3.0, 3.0);
    for (int k = 0; k < 30; ++k) {  // long polylines in separate horizontal bands: no crossings
        Polyline line;
        for (double x = 2.0; x < 1000.0; x += 23.0) {
            line.points.push_back({test::sjtsk_e + x + jitter(rng),
                                   test::sjtsk_n + 15.0 + 33.0 * k + jitter(rng), 100.0});
        }
        input.breaklines.push_back(line);
    }
    Cdt cdt;
    const auto pts = cgal_points(input.points);
    cdt.insert(pts.begin(), pts.end());
    for (const Polyline& line : input.breaklines) {
        for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
            cdt.insert_constraint(K::Point_2(line.points[i].x, line.points[i].y),
                                  K::Point_2(line.points[i + 1].x, line.points[i + 1].y));
        }
    }
    const TriangulateResult r = triangulate(input);
    EXPECT_EQ(r.stats.intersections, 0u);
    EXPECT_EQ(test::triangle_set(r.tin), cgal_triangle_set(cdt));
}

INSTANTIATE_TEST_SUITE_P(Seeds, OracleSeeds, ::testing::Values(1u, 2u, 3u, 4u));

}  // namespace
}  // namespace dtm
