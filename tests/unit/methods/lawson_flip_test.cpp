// SPDX-License-Identifier: MIT
// [lawson-flip]: equal to the production kernel in general position (also at S-JTSK
// magnitudes), valid Delaunay on grids, circles, collinear runs and duplicates, both flip
// orders, and the production kernel's refusals.
#include <gtest/gtest.h>

#include "dtm/core/error.hpp"
#include "methods_fixtures.hpp"

namespace dtm::methods {
namespace {

using test::expect_delaunay_like_dc;

TEST(LawsonFlip, EqualsTheProductionKernelInGeneralPosition) {
    expect_delaunay_like_dc("lawson-flip", test::points(Distribution::uniform, 2000, 1));
    expect_delaunay_like_dc("lawson-flip", test::points(Distribution::gauss, 1000, 2));
    expect_delaunay_like_dc("lawson-flip",
                            test::points(Distribution::uniform, 1500, 3, test::sjtsk_mm()));
    expect_delaunay_like_dc("lawson-flip", test::points(Distribution::uniform, 400, 4),
                            {{"order", "pass"}});
}

TEST(LawsonFlip, DegenerateSetsGiveValidDelaunayTriangulations) {
    for (const Distribution d : {Distribution::grid, Distribution::circle, Distribution::collinear,
                                 Distribution::duplicates}) {
        for (const char* order : {"stack", "pass"}) {
            const auto pts = test::points(d, 600, 5);
            const MethodResult r = test::run_method("lawson-flip", pts, {{"order", order}});
            EXPECT_TRUE(test::is_delaunay_triangulation(r.tin, pts))
                << distribution_name(d) << " " << order;
        }
    }
    const auto dup = test::points(Distribution::duplicates, 600, 5);
    const MethodResult r = test::run_method("lawson-flip", dup);
    EXPECT_EQ(r.counters.extra.at("duplicates"), dup.size() - test::distinct_points(dup).size());
}

TEST(LawsonFlip, CountsItsFlipsAndPredicates) {
    const auto pts = test::points(Distribution::uniform, 1000, 6);
    const MethodResult r = test::run_method("lawson-flip", pts);
    EXPECT_GT(r.counters.flips, 0u);
    EXPECT_GT(r.counters.incircle_calls, r.counters.flips);
    EXPECT_GT(r.counters.orient_calls, 0u);
    EXPECT_GT(r.counters.peak_bytes, 0u);
}

TEST(LawsonFlip, RefusesWhatTheProductionKernelRefuses) {
    const std::vector<Point3> line{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}, {5, 5, 1}};
    EXPECT_THROW((void)test::run_method("lawson-flip", line), InputError);
    const std::vector<Point3> two{{0, 0, 0}, {1, 1, 0}, {0, 0, 3}};
    EXPECT_THROW((void)test::run_method("lawson-flip", two), InputError);
    EXPECT_THROW((void)test::run_method("lawson-flip", test::points(Distribution::uniform, 10, 1),
                                        {{"order", "random"}}),
                 UsageError);
    EXPECT_THROW((void)test::run_method("lawson-flip", test::points(Distribution::uniform, 10, 1),
                                        {{"nonsense", "1"}}),
                 UsageError);
}

}  // namespace
}  // namespace dtm::methods
