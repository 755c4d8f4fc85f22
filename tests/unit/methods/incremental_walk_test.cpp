// SPDX-License-Identifier: MIT
// [incremental-walk]: equal to the production kernel in general position for every insertion
// order and at S-JTSK magnitudes, valid Delaunay on the degenerate sets, the winged-edge
// structure consistent after every insertion (R28), walks short in Hilbert order and of
// about sqrt(n) steps in random order (R41).
#include <gtest/gtest.h>

#include <cmath>

#include "dtm/core/error.hpp"
#include "methods/detail/spatial_order.hpp"
#include "methods/detail/winged_edge.hpp"
#include "methods_fixtures.hpp"

namespace dtm::methods {
namespace {

TEST(IncrementalWalk, EqualsTheProductionKernelInGeneralPosition) {
    const auto pts = test::points(Distribution::uniform, 3000, 1);
    for (const char* order : {"hilbert", "random", "input"}) {
        test::expect_delaunay_like_dc("incremental-walk", pts, {{"order", order}});
    }
    test::expect_delaunay_like_dc("incremental-walk",
                                  test::points(Distribution::uniform, 2000, 2, test::sjtsk_mm()));
    test::expect_delaunay_like_dc("incremental-walk", test::points(Distribution::gauss, 2000, 3));
}

TEST(IncrementalWalk, DegenerateSetsGiveValidDelaunayTriangulations) {
    for (const Distribution d : {Distribution::grid, Distribution::circle, Distribution::collinear,
                                 Distribution::duplicates, Distribution::arc}) {
        for (const char* order : {"hilbert", "random"}) {
            const auto pts = test::points(d, 1000, 4);
            const MethodResult r = test::run_method("incremental-walk", pts, {{"order", order}});
            EXPECT_TRUE(test::is_delaunay_triangulation(r.tin, pts))
                << distribution_name(d) << " " << order;
        }
    }
}

TEST(IncrementalWalk, TheWingedEdgeStructureStaysConsistent) {
    for (const Distribution d :
         {Distribution::uniform, Distribution::grid, Distribution::collinear}) {
        const auto pts = test::distinct_points(test::points(d, 300, 6));
        detail::CountingPredicates pred;
        detail::WingedEdgeDelaunay we(pts, pred);
        ASSERT_EQ(we.check(), "");
        for (const VertexIndex v : detail::random_order(pts.size(), 3)) {
            (void)we.insert(v);
            ASSERT_EQ(we.check(), "") << distribution_name(d) << " after " << v;
        }
        EXPECT_EQ(we.edges().size(), 3 * pts.size() + 3);
        EXPECT_EQ(we.triangles().size(), 2 * pts.size() + 1);
    }
}

TEST(IncrementalWalk, WalksAreShortInHilbertOrderAndGrowAsRootNInRandomOrder) {
    std::vector<double> random_steps;
    for (const std::size_t n : {1000u, 4000u, 16000u}) {
        const auto pts = test::points(Distribution::uniform, n, 7);
        const MethodResult h = test::run_method("incremental-walk", pts);
        EXPECT_LT(static_cast<double>(h.counters.walk_steps) / static_cast<double>(n), 4.0) << n;
        const MethodResult r = test::run_method("incremental-walk", pts, {{"order", "random"}});
        random_steps.push_back(static_cast<double>(r.counters.walk_steps) / static_cast<double>(n));
    }
    // Four times the points, about twice the steps (between 1.6 and 2.4 times).
    for (std::size_t i = 1; i < random_steps.size(); ++i) {
        const double ratio = random_steps[i] / random_steps[i - 1];
        EXPECT_GT(ratio, 1.6) << i;
        EXPECT_LT(ratio, 2.4) << i;
    }
}

TEST(IncrementalWalk, RefusesCollinearInput) {
    const std::vector<Point3> line{{0, 0, 0}, {1, 2, 0}, {2, 4, 0}, {3, 6, 0}};
    EXPECT_THROW((void)test::run_method("incremental-walk", line), InputError);
}

}  // namespace
}  // namespace dtm::methods
