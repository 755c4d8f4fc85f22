// SPDX-License-Identifier: MIT
// [lifting]: equal to the production kernel in general position (several seeds, S-JTSK
// millimetres), valid on the degenerate sets (a circle: every lift coplanar; a grid: many
// coplanar quadruples; collinear hull runs: vertical facets).
#include <gtest/gtest.h>

#include "methods_fixtures.hpp"

namespace dtm::methods {
namespace {

TEST(Lifting, EqualsTheProductionKernelInGeneralPosition) {
    const auto pts = test::points(Distribution::uniform, 4000, 1);
    for (const std::uint64_t seed : {1u, 7u})
        test::expect_delaunay_like_dc("lifting", pts, {}, seed);
    test::expect_delaunay_like_dc("lifting",
                                  test::points(Distribution::uniform, 3000, 2, test::sjtsk_mm()));
    test::expect_delaunay_like_dc("lifting", test::points(Distribution::gauss, 3000, 3));
}

TEST(Lifting, DegenerateSetsGiveValidDelaunayTriangulations) {
    for (const Distribution d : {Distribution::grid, Distribution::circle, Distribution::collinear,
                                 Distribution::duplicates, Distribution::arc}) {
        const auto pts = test::points(d, 1500, 4);
        const MethodResult r = test::run_method("lifting", pts);
        EXPECT_TRUE(test::is_delaunay_triangulation(r.tin, pts)) << distribution_name(d);
    }
    const auto circle = test::points(Distribution::circle, 300, 5);
    EXPECT_EQ(test::run_method("lifting", circle).counters.extra.at("cocircular"), 1u);
    // A circle plus its centre: the lifts are no longer coplanar.
    auto wheel = circle;
    wheel.push_back({500, 500, 0});
    EXPECT_TRUE(test::is_delaunay_triangulation(test::run_method("lifting", wheel).tin, wheel));
}

}  // namespace
}  // namespace dtm::methods
