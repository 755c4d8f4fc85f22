// SPDX-License-Identifier: MIT
// [uniform-grid] and the vertex list: equal to the production kernel in general position,
// valid Delaunay on the degenerate sets, the thesis' four queries with its own answers
// (§3.10.7, Figs. 19/20), its 20-vertex example (Fig. 23: 50 edges, 31 triangles, hull
// 20-19-9-8-17-15-12; R30), the streamed lists equal to the result's, the Fig. 33 trap
// (R5), TOL merging (R45).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "dtm/methods/vertex_list.hpp"
#include "methods_fixtures.hpp"

namespace dtm::methods {
namespace {

using T = VertexTriangle;

TEST(UniformGrid, EqualsTheProductionKernelInGeneralPosition) {
    test::expect_delaunay_like_dc("uniform-grid", test::points(Distribution::uniform, 5000, 1));
    test::expect_delaunay_like_dc("uniform-grid",
                                  test::points(Distribution::uniform, 3000, 2, test::sjtsk_mm()));
    test::expect_delaunay_like_dc("uniform-grid", test::points(Distribution::cluster, 3000, 3));
    test::expect_delaunay_like_dc("uniform-grid", test::points(Distribution::arc, 3000, 4));
    test::expect_delaunay_like_dc("uniform-grid", test::points(Distribution::gauss, 3000, 5));
}

TEST(UniformGrid, DegenerateSetsGiveValidDelaunayTriangulations) {
    for (const Distribution d : {Distribution::grid, Distribution::circle, Distribution::collinear,
                                 Distribution::duplicates}) {
        // One face of n cocircular points costs O(n) per triangle: keep the circle small.
        const auto pts = test::points(d, d == Distribution::circle ? 500 : 2000, 6);
        const MethodResult r = test::run_method("uniform-grid", pts);
        EXPECT_TRUE(test::is_delaunay_triangulation(r.tin, pts)) << distribution_name(d);
    }
}

TEST(VertexList, AnswersTheThesisQueriesWithItsAnswers) {
    // Figs. 19/20 (vertex 0 unused): interior 3 and 6, the rest on the hull.
    std::vector<std::vector<VertexIndex>> lists(9);
    lists[3] = {5, 6, 4, 1, 2};
    lists[6] = {8, 7, 4, 3, 5};
    lists[5] = {8, 6, 3, 2};
    lists[8] = {7, 6, 5};
    lists[7] = {4, 6, 8};
    lists[4] = {1, 3, 6, 7};
    lists[1] = {2, 3, 4};
    lists[2] = {5, 3, 1};
    const VertexList vl =
        make_vertex_list(lists, {false, true, true, false, true, true, false, true, true});
    EXPECT_EQ(triangles_at_vertex(vl, 3),
              (std::vector<T>{{3, 5, 6}, {3, 6, 4}, {3, 4, 1}, {3, 1, 2}, {3, 2, 5}}));
    EXPECT_EQ(triangles_at_vertex(vl, 5), (std::vector<T>{{5, 8, 6}, {5, 6, 3}, {5, 3, 2}}));
    EXPECT_EQ(triangles_on_edge(vl, 3, 6), (std::vector<T>{{3, 6, 4}, {6, 3, 5}}));
    EXPECT_EQ(triangles_on_edge(vl, 2, 1), (std::vector<T>{{1, 2, 3}}));
    EXPECT_EQ(edges_at_vertex(vl, 7),
              (std::vector<std::pair<VertexIndex, VertexIndex>>{{7, 4}, {7, 6}, {7, 8}}));
    EXPECT_EQ(neighbours_of_triangle(vl, {3, 6, 4}),
              (std::vector<T>{{6, 3, 5}, {4, 6, 7}, {3, 4, 1}}));
}

TEST(VertexList, TheThesisTwentyPointExampleIsConsistent) {
    std::vector<std::vector<VertexIndex>> l(21);
    l[1] = {2, 3, 4, 5, 6, 7};
    l[2] = {3, 1, 7};
    l[3] = {4, 1, 2, 7, 8, 9, 10};
    l[4] = {5, 1, 3, 10, 11, 12, 13, 14};
    l[5] = {6, 1, 4, 14, 15, 16};
    l[7] = {8, 3, 2, 1, 6};
    l[6] = {8, 7, 1, 5, 16};
    l[10] = {11, 4, 3, 9, 18};
    l[11] = {12, 4, 10, 18, 19, 20};
    l[14] = {15, 5, 4, 13};
    l[13] = {15, 14, 4, 12};
    l[16] = {17, 8, 6, 5, 15};
    l[18] = {19, 11, 10, 9};
    l[20] = {12, 11, 19};
    l[12] = {15, 13, 4, 11, 20};
    l[15] = {17, 16, 5, 14, 13, 12};
    l[17] = {8, 16, 15};
    l[8] = {9, 3, 7, 6, 16, 17};
    l[9] = {19, 18, 10, 3, 8};
    l[19] = {20, 11, 18, 9};
    std::vector<bool> hull(21, false);
    for (const VertexIndex v : {20u, 12u, 15u, 17u, 8u, 9u, 19u}) hull[v] = true;
    const VertexList vl = make_vertex_list(l, hull);
    std::size_t ends = 0;
    std::map<std::array<VertexIndex, 3>, int> triangles;
    for (VertexIndex v = 1; v <= 20; ++v) {
        ends += vl.neighbours(v).size();
        for (T t : triangles_at_vertex(vl, v)) {
            std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
            ++triangles[t];
        }
    }
    EXPECT_EQ(ends / 2, 50u);
    EXPECT_EQ(triangles.size(), 31u);
    for (const auto& [t, count] : triangles) EXPECT_EQ(count, 3) << t[0] << t[1] << t[2];
    EXPECT_EQ(hull_cycle(vl, 20), (std::vector<VertexIndex>{20, 19, 9, 8, 17, 15, 12}));
}

TEST(UniformGrid, StreamsEveryVertexListAsTheResultHasIt) {
    const auto pts = test::distinct_points(test::points(Distribution::uniform, 3000, 7));
    std::vector<int> seen(pts.size(), 0);
    std::size_t interior_before_hull = 0;
    bool hull_started = false;
    const VertexList streamed =
        uniform_grid_vertex_list(pts, [&](VertexIndex v, std::span<const VertexIndex>, bool h) {
            ++seen[v];
            hull_started = hull_started || h;
            if (!h && !hull_started) ++interior_before_hull;
        });
    for (const int s : seen) EXPECT_EQ(s, 1);
    const Tin tin = test::run_method("uniform-grid", pts).tin;
    const VertexList from_tin = vertex_list_of(tin);
    ASSERT_EQ(from_tin.vertex_count(), streamed.vertex_count());
    std::size_t hull = 0;
    for (VertexIndex v = 0; v < pts.size(); ++v) {
        const auto a = streamed.neighbours(v);
        auto b =
            std::vector<VertexIndex>(from_tin.neighbours(v).begin(), from_tin.neighbours(v).end());
        ASSERT_EQ(streamed.is_hull(v), from_tin.is_hull(v)) << v;
        ASSERT_EQ(a.size(), b.size()) << v;
        if (!streamed.is_hull(v)) {  // cyclic lists: same up to the starting element
            const auto it = std::find(b.begin(), b.end(), a[0]);
            ASSERT_NE(it, b.end());
            std::rotate(b.begin(), it, b.end());
        } else {
            ++hull;
        }
        EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin())) << v;
    }
    EXPECT_EQ(interior_before_hull, pts.size() - hull);
}

TEST(UniformGrid, FigureThirtyThreeShortEdgeAndFarNearlyCollinearPoint) {
    // R5: an active edge a few micrometres long on the hull and a far point almost on its
    // line; a rounded side test calls the edge a hull edge and leaves a cavity (Fig. 33b).
    std::vector<Point3> pts = test::points(Distribution::uniform, 500, 8);
    pts.push_back({-10.0, 0.0, 0});
    pts.push_back({-10.0 + 3e-6, 1e-9, 0});
    pts.push_back({1e4, 1e-9 * (1e4 + 10.0) / 3e-6 + 1e-7, 0});
    const MethodResult r = test::run_method("uniform-grid", pts);
    EXPECT_TRUE(test::is_delaunay_triangulation(r.tin, pts));
    EXPECT_TRUE(test::same_triangles(r.tin, test::reference_tin(pts)));
}

TEST(UniformGrid, ToleranceDropsNearPoints) {
    std::vector<Point3> pts = test::points(Distribution::uniform, 400, 9);
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i < 50; ++i) pts.push_back({pts[i].x + 1e-4, pts[i].y, 0});
    const MethodResult r = test::run_method("uniform-grid", pts, {{"tol", "0.001"}});
    EXPECT_EQ(r.tin.vertices.size(), n);
    EXPECT_EQ(r.counters.extra.at("duplicates"), 50u);
    EXPECT_TRUE(test::is_delaunay_triangulation(r.tin, std::span(pts).first(n)));
}

}  // namespace
}  // namespace dtm::methods
