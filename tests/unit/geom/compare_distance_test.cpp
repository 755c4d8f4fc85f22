// SPDX-License-Identifier: MIT
// geom::compare_distance: exact ties on grids and at S-JTSK magnitudes, one-ulp differences the
// floating-point filter cannot see, antisymmetry, and extreme magnitudes (big-integer path).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dtm/core/point.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::geom {
namespace {

TEST(CompareDistance, ExactTiesAndOrder) {
    const Point2 o{0, 0}, a{3, 4}, b{5, 0}, c{4, 3}, d{1, 1};
    EXPECT_EQ(compare_distance(o, a, o, b), 0);
    EXPECT_EQ(compare_distance(o, a, c, o), 0);
    EXPECT_EQ(compare_distance(o, d, o, a), -1);
    EXPECT_EQ(compare_distance(o, a, o, d), 1);
    // S-JTSK magnitudes: the same 5 m on two rotated vectors.
    const Point2 p{-750123.25, -1050321.5};
    EXPECT_EQ(compare_distance(p, Point2{p.x + 3, p.y + 4}, p, Point2{p.x - 5, p.y}), 0);
}

TEST(CompareDistance, OneUlpApart) {
    const double x = 1e6;
    const Point2 o{0, 0};
    const Point2 a{x, 0};
    const Point2 b{std::nextafter(x, 2 * x), 0};
    EXPECT_EQ(compare_distance(o, a, o, b), -1);
    EXPECT_EQ(compare_distance(o, b, o, a), 1);
    // Differences whose squares round to the same double: (1 + 2^-30)^2 vs 1 + 2^-29 + tiny.
    const Point2 c{1.0 + 0x1p-30, 0};
    const Point2 d{1.0, std::sqrt(0x1p-29)};
    const int s = compare_distance(o, c, o, d);
    // |oc|^2 = 1 + 2^-29 + 2^-60; |od|^2 = 1 + fl(sqrt(2^-29))^2: decided exactly either way,
    // and antisymmetric.
    EXPECT_EQ(compare_distance(o, d, o, c), -s);
}

TEST(CompareDistance, AntisymmetricOnRandomInput) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 10000; ++i) {
        const Point2 a{u(rng), u(rng)}, b{u(rng), u(rng)}, c{u(rng), u(rng)}, d{u(rng), u(rng)};
        EXPECT_EQ(compare_distance(a, b, c, d), -compare_distance(c, d, a, b));
        EXPECT_EQ(compare_distance(a, b, b, a), 0);
    }
}

TEST(CompareDistance, ExtremeMagnitudes) {
    const Point2 o{0, 0};
    EXPECT_EQ(compare_distance(o, Point2{1e300, 0}, o, Point2{0, 1e300}), 0);
    EXPECT_EQ(compare_distance(o, Point2{1e300, 1e300}, o, Point2{0, 1e300}), 1);
    EXPECT_EQ(compare_distance(o, Point2{1e-300, 0}, o, Point2{0, 2e-300}), -1);
    EXPECT_EQ(compare_distance(o, Point2{3e-310, 4e-310}, o, Point2{5e-310, 0}), 0);
}

}  // namespace
}  // namespace dtm::geom
