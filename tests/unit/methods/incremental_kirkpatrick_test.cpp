// SPDX-License-Identifier: MIT
// [incremental-kirkpatrick]: equal to the production kernel in general position, valid on the
// degenerate sets; the hierarchy itself (R42): O(log n) levels, every query answered with a
// triangle containing the point, O(n) nodes, at most 11 + ... children.
#include <gtest/gtest.h>

#include <cmath>

#include "methods/detail/kirkpatrick.hpp"
#include "methods/detail/spatial_order.hpp"
#include "methods/detail/winged_edge.hpp"
#include "methods_fixtures.hpp"

namespace dtm::methods {
namespace {

TEST(IncrementalKirkpatrick, EqualsTheProductionKernelInGeneralPosition) {
    const auto pts = test::points(Distribution::uniform, 4000, 1);
    test::expect_delaunay_like_dc("incremental-kirkpatrick", pts);
    test::expect_delaunay_like_dc("incremental-kirkpatrick", pts, {}, 9);
    test::expect_delaunay_like_dc("incremental-kirkpatrick",
                                  test::points(Distribution::uniform, 3000, 2, test::sjtsk_mm()));
}

TEST(IncrementalKirkpatrick, DegenerateSetsGiveValidDelaunayTriangulations) {
    for (const Distribution d : {Distribution::grid, Distribution::circle, Distribution::collinear,
                                 Distribution::duplicates, Distribution::cluster}) {
        const auto pts = test::points(d, 3000, 4);
        const MethodResult r = test::run_method("incremental-kirkpatrick", pts);
        EXPECT_TRUE(test::is_delaunay_triangulation(r.tin, pts)) << distribution_name(d);
        // One rebuild at the start of every BRIO round but the last, from 64 points in (n >> j,
        // j >= 2).
        std::size_t rounds = 0;
        for (std::size_t b = test::distinct_points(pts).size() / 4; b >= 64; b /= 2) ++rounds;
        EXPECT_GT(r.counters.extra.at("rebuilds"), 0u) << distribution_name(d);
        EXPECT_EQ(r.counters.extra.at("rebuilds"), rounds) << distribution_name(d);
    }
}

TEST(IncrementalKirkpatrick, TheHierarchyLocatesEveryPointInLogarithmicLevels) {
    for (const Distribution d : {Distribution::uniform, Distribution::grid}) {
        const auto pts = test::distinct_points(test::points(d, 4000, 5));
        detail::CountingPredicates pred;
        detail::WingedEdgeDelaunay we(pts, pred);
        const auto order = detail::random_order(pts.size(), 2);
        const std::size_t built = pts.size() / 2;
        for (std::size_t k = 0; k < built; ++k) (void)we.insert(order[k]);
        std::vector<detail::KirkpatrickHierarchy::Corners> tris(we.triangles().size());
        for (TriangleIndex t = 0; t < tris.size(); ++t) tris[t] = we.corners(t);
        detail::KirkpatrickHierarchy h;
        h.build(tris, pts.size() + 3, we.super());
        // alpha <= 0.955 gives at most log(n) / log(1/0.955) levels; in practice far fewer.
        EXPECT_LT(static_cast<double>(h.levels()),
                  std::log(static_cast<double>(built)) / std::log(1 / 0.955));
        EXPECT_LT(static_cast<double>(h.nodes()),
                  2.0 * static_cast<double>(tris.size()) / (1 - 0.955));
        std::uint64_t steps = 0;
        for (std::size_t k = built; k < pts.size(); ++k) {
            const auto c = h.locate(order[k], we.super(), steps);
            EXPECT_GE(we.super().orient(c[0], c[1], order[k]), 0);
            EXPECT_GE(we.super().orient(c[1], c[2], order[k]), 0);
            EXPECT_GE(we.super().orient(c[2], c[0], order[k]), 0);
        }
        EXPECT_LT(static_cast<double>(steps) / static_cast<double>(pts.size() - built),
                  6.0 * std::log2(static_cast<double>(built)));
    }
}

}  // namespace
}  // namespace dtm::methods
