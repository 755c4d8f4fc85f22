// SPDX-License-Identifier: MIT
// The insertion orders (detail/spatial_order.hpp): the Hilbert order sorted by the curve's
// index, ties by vertex (checked against a plain sort of the same keys); the BRIO order is a
// permutation whose rounds
// (n/2^j .. n/2^(j-1)) are the same sets as in the random permutation it is cut from, each
// round in Hilbert order (consecutive points near each other); the renumbering in insertion
// order and back is the identity on the points and maps triangles back to input numbers.
#include "methods/detail/spatial_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dtm/methods/point_sets.hpp"

namespace dtm::methods::detail {
namespace {

double mean_step(const std::vector<Point3>& pts,
                 const std::vector<VertexIndex>& order,
                 std::size_t begin,
                 std::size_t end) {
    double sum = 0.0;
    for (std::size_t k = begin + 1; k < end; ++k) {
        const Point3& a = pts[order[k - 1]];
        const Point3& b = pts[order[k]];
        sum += std::hypot(a.x - b.x, a.y - b.y);
    }
    return sum / static_cast<double>(end - begin - 1);
}

TEST(SpatialOrder, HilbertOrderKeepsTiesByVertex) {
    // 10 000 points on 100 positions (the radix path) and 1000 on 10 (the comparison path):
    // equal positions have equal Hilbert indices, so each position's points come together,
    // ascending by vertex.
    for (const std::size_t n : {10000u, 1000u}) {
        const auto base = generate_points(Distribution::uniform, n / 100, 6);
        std::vector<Point3> pts;
        for (std::size_t i = 0; i < n; ++i) pts.push_back(base[(i * 37) % base.size()]);
        const auto order = hilbert_order(pts);
        ASSERT_EQ(order.size(), n);
        std::size_t groups = 1;
        for (std::size_t k = 1; k < n; ++k) {
            const Point3& a = pts[order[k - 1]];
            const Point3& b = pts[order[k]];
            if (a.x == b.x && a.y == b.y) {
                EXPECT_LT(order[k - 1], order[k]);
            } else {
                ++groups;
            }
        }
        EXPECT_EQ(groups, base.size());
        auto sorted = order;
        std::sort(sorted.begin(), sorted.end());
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i);
    }
}

TEST(SpatialOrder, BrioIsAPermutationOfRandomRoundsEachInHilbertOrder) {
    for (const std::size_t n : {1u, 2u, 3u, 64u, 65u, 1000u, 20011u}) {
        const auto pts = generate_points(Distribution::uniform, n, 3);
        const auto brio = brio_order(pts, 5);
        const auto random = random_order(pts.size(), 5);
        ASSERT_EQ(brio.size(), pts.size());
        auto sorted = brio;
        std::sort(sorted.begin(), sorted.end());
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i) << n;
        // Rounds [n >> j, n >> (j - 1)) while the range is above 64 points, then the rest.
        std::size_t end = n;
        while (end > 0) {
            const std::size_t begin = end > 64 ? end / 2 : 0;
            auto a = std::vector<VertexIndex>(brio.begin() + static_cast<std::ptrdiff_t>(begin),
                                              brio.begin() + static_cast<std::ptrdiff_t>(end));
            auto b = std::vector<VertexIndex>(random.begin() + static_cast<std::ptrdiff_t>(begin),
                                              random.begin() + static_cast<std::ptrdiff_t>(end));
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            EXPECT_EQ(a, b) << n << " round at " << begin;
            if (end - begin > 500) {
                // Hilbert order: steps between consecutive points far shorter than random ones.
                EXPECT_LT(mean_step(pts, brio, begin, end),
                          0.25 * mean_step(pts, random, begin, end));
            }
            end = begin;
        }
    }
    const auto pts = generate_points(Distribution::uniform, 500, 3);
    EXPECT_EQ(brio_order(pts, 9), brio_order(pts, 9));
    EXPECT_NE(brio_order(pts, 9), brio_order(pts, 10));
}

TEST(SpatialOrder, RenumberingInInsertionOrderAndBack) {
    const auto pts = generate_points(Distribution::uniform, 300, 4);
    const auto order = brio_order(pts, 2);
    auto sorted = pts;
    to_insertion_order(sorted, order);
    ASSERT_EQ(sorted.size(), pts.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        EXPECT_EQ(sorted[k].x, pts[order[k]].x);
        EXPECT_EQ(sorted[k].y, pts[order[k]].y);
        EXPECT_EQ(sorted[k].z, pts[order[k]].z);
    }
    std::vector<Triangle> tris(2);
    tris[0].v = {0, 1, 2};
    tris[1].v = {299, 17, 5};
    auto back = sorted;
    to_input_numbering(tris, back, order);
    ASSERT_EQ(back.size(), pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        EXPECT_EQ(back[i].x, pts[i].x);
        EXPECT_EQ(back[i].y, pts[i].y);
        EXPECT_EQ(back[i].z, pts[i].z);
    }
    EXPECT_EQ(tris[0].v, (std::array<VertexIndex, 3>{order[0], order[1], order[2]}));
    EXPECT_EQ(tris[1].v, (std::array<VertexIndex, 3>{order[299], order[17], order[5]}));
}

}  // namespace
}  // namespace dtm::methods::detail
