// SPDX-License-Identifier: MIT
// [randomized-dag]: equal to the production kernel in general position for several seeds
// and at S-JTSK magnitudes, valid Delaunay on the degenerate sets, the counts of the history,
// and the lecture's finite super-triangle losing a hull edge the symbolic one keeps.
#include <gtest/gtest.h>

#include "dtm/core/error.hpp"
#include "methods_fixtures.hpp"

namespace dtm::methods {
namespace {

TEST(RandomizedDag, EqualsTheProductionKernelInGeneralPosition) {
    const auto pts = test::points(Distribution::uniform, 3000, 1);
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
        test::expect_delaunay_like_dc("randomized-dag", pts, {}, seed);
    }
    test::expect_delaunay_like_dc("randomized-dag",
                                  test::points(Distribution::uniform, 2000, 2, test::sjtsk_mm()));
    test::expect_delaunay_like_dc("randomized-dag", test::points(Distribution::cluster, 2000, 3));
    // The plain random order (the lecture's) as well as the default BRIO rounds.
    test::expect_delaunay_like_dc("randomized-dag", pts, {{"order", "random"}}, 4);
    test::expect_delaunay_like_dc("randomized-dag", pts, {{"order", "brio"}}, 4);
}

TEST(RandomizedDag, DegenerateSetsGiveValidDelaunayTriangulations) {
    for (const Distribution d : {Distribution::grid, Distribution::circle, Distribution::collinear,
                                 Distribution::duplicates, Distribution::arc}) {
        const auto pts = test::points(d, 1000, 4);
        for (const char* order : {"brio", "random"}) {
            const MethodResult r = test::run_method("randomized-dag", pts, {{"order", order}});
            EXPECT_TRUE(test::is_delaunay_triangulation(r.tin, pts))
                << distribution_name(d) << " " << order;
        }
    }
}

TEST(RandomizedDag, CountsItsHistory) {
    const auto pts = test::points(Distribution::uniform, 5000, 5);
    const MethodResult r = test::run_method("randomized-dag", pts);
    // Expected at most 9n + 1 triangles made (de Berg et al. Lemma 9.11); walk steps are the
    // history nodes visited, O(log n) per point.
    EXPECT_LT(r.counters.extra.at("dag_nodes"), 9 * pts.size() + 1);
    EXPECT_GT(r.counters.flips, 2 * pts.size());
    EXPECT_LT(r.counters.walk_steps, 40 * pts.size());
    EXPECT_LT(r.counters.peak_bytes, 200 * pts.size());
}

TEST(RandomizedDag, TheLecturesFiniteSuperTriangleLosesAHullEdge) {
    // A hull edge a-b from (0, 0) to (1000, 0) with a point 1 mm above its middle: the circle
    // through a, b and the finite corner p-1 (100 km away) bulges 1.25 m above a-b, holds the
    // point, so a-b is flipped away towards the corner and vanishes with it. The symbolic
    // corners keep it.
    std::vector<Point3> pts{{0, 0, 0},     {1000, 0, 0},  {500, 0.001, 0},
                            {500, 500, 0}, {200, 300, 0}, {800, 250, 0}};
    const MethodResult finite =
        test::run_method("randomized-dag", pts, {{"super-triangle", "finite"}});
    EXPECT_FALSE(test::is_delaunay_triangulation(finite.tin, pts));
    const MethodResult symbolic = test::run_method("randomized-dag", pts);
    EXPECT_TRUE(test::is_delaunay_triangulation(symbolic.tin, pts));
    EXPECT_TRUE(test::same_triangles(symbolic.tin, test::reference_tin(pts)));
}

TEST(RandomizedDag, RefusesCollinearInputAndUnknownParameters) {
    const std::vector<Point3> line{{0, 0, 0}, {1, 2, 0}, {2, 4, 0}};
    EXPECT_THROW((void)test::run_method("randomized-dag", line), InputError);
    EXPECT_THROW((void)test::run_method("randomized-dag", test::points(Distribution::uniform, 9),
                                        {{"super-triangle", "huge"}}),
                 UsageError);
}

}  // namespace
}  // namespace dtm::methods
