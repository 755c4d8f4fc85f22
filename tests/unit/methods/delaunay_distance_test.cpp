// SPDX-License-Identifier: MIT
// [delaunay-distance]: equal to the production kernel in general position, valid Delaunay on
// grids (every square cocircular: the tie rule must keep fronts consistent), circles (one
// cocircular face), collinear runs and duplicates; the third-point rule on its own.
#include <gtest/gtest.h>

#include "methods/detail/third_point.hpp"
#include "methods_fixtures.hpp"

namespace dtm::methods {
namespace {

TEST(DelaunayDistance, EqualsTheProductionKernelInGeneralPosition) {
    test::expect_delaunay_like_dc("delaunay-distance",
                                  test::points(Distribution::uniform, 1500, 1));
    test::expect_delaunay_like_dc("delaunay-distance",
                                  test::points(Distribution::uniform, 1000, 2, test::sjtsk_mm()));
    test::expect_delaunay_like_dc("delaunay-distance", test::points(Distribution::cluster, 800, 3),
                                  {}, 5);
}

TEST(DelaunayDistance, DegenerateSetsGiveValidDelaunayTriangulations) {
    for (const Distribution d : {Distribution::grid, Distribution::circle, Distribution::collinear,
                                 Distribution::duplicates, Distribution::arc}) {
        for (const std::uint64_t seed : {1u, 2u}) {
            const auto pts = test::points(d, 700, 4);
            const MethodResult r = test::run_method("delaunay-distance", pts, {}, seed);
            EXPECT_TRUE(test::is_delaunay_triangulation(r.tin, pts)) << distribution_name(d);
        }
    }
}

TEST(ThirdPoint, PicksTheEmptyCircleAndTriangulatesCocircularFacesAsFans) {
    // A regular octagon-like cocircular face: the unit square's corners and the points
    // (+-5, 0), (0, +-5) scaled... use the integer circle x^2 + y^2 = 25.
    const std::vector<Point3> p{{5, 0, 0},   {4, 3, 0},  {3, 4, 0},  {0, 5, 0}, {-3, 4, 0},
                                {-4, -3, 0}, {0, -5, 0}, {4, -3, 0}, {1, 1, 0}, {20, 20, 0}};
    detail::CountingPredicates pred;
    detail::ThirdPoint third(p, pred);
    // Edge (0,-5) -> (4,-3): every other circle point is on the circle, (1,1) inside.
    third.reset(6, 7);
    for (VertexIndex q = 0; q < 10; ++q) third.offer(q);
    EXPECT_EQ(third.choose(), 8u);  // (1, 1) is strictly inside: the empty circle is smaller
    // Without (1, 1): the face is the whole circle; its smallest vertex (-4, -3) = 5 gets the
    // fan, and the edge 6 -> 7 (neither is 5) closes the triangle (6, 7, 5).
    third.reset(6, 7);
    for (const VertexIndex q : {0u, 1u, 2u, 3u, 4u, 5u, 9u}) third.offer(q);
    EXPECT_EQ(third.choose(), 5u);
    // The edge 5 -> 6 starts at the fan's apex: the face's vertex after 6 is 7.
    third.reset(5, 6);
    for (const VertexIndex q : {0u, 1u, 2u, 3u, 4u, 7u, 9u}) third.offer(q);
    EXPECT_EQ(third.choose(), 7u);
    // The edge 4 -> 5 ends at the apex: the vertex before 4 is 3.
    third.reset(4, 5);
    for (const VertexIndex q : {0u, 1u, 2u, 3u, 6u, 7u, 9u}) third.offer(q);
    EXPECT_EQ(third.choose(), 3u);
    // Nothing left of an edge: a hull edge.
    third.reset(7, 6);
    for (const VertexIndex q : {0u, 1u, 2u, 3u, 4u, 5u}) third.offer(q);
    EXPECT_FALSE(third.found());
}

}  // namespace
}  // namespace dtm::methods
