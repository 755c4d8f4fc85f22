// SPDX-License-Identifier: MIT
// The symbolic super-triangle's predicates are the limits of the real predicates: compared,
// for every ordered choice of arguments, with the exact predicates evaluated at corners
// S0 = (-d^2, -d), S1 = (d^4, -d^3), S2 = (d^5, d^6) for d = 2^64 (finite doubles, decided by
// the predicates' big-integer path), on dyadic points with collinear runs and cocircular
// quadruples.
#include "methods/detail/super_triangle.hpp"

#include <gtest/gtest.h>

#include <random>

#include "dtm/geom/predicates.hpp"

namespace dtm::methods::detail {
namespace {

TEST(SuperTriangle, SymbolicPredicatesAreTheLimitsOfTheRealOnes) {
    std::vector<Point3> pts{{0, 0, 0},  {1, 0, 0}, {2, 0, 0},   {0, 1, 0},
                            {1, 1, 0},  {3, 3, 0}, {-2, 5, 0},  {0.5, 7, 0},
                            {4, -1, 0}, {0, 2, 0}, {-1, -1, 0}, {2.5, 0.125, 0}};
    std::mt19937_64 rng(1);
    std::uniform_int_distribution<int> coord(-64, 64);
    for (int i = 0; i < 8; ++i) pts.push_back({coord(rng) / 8.0, coord(rng) / 8.0, 0});
    CountingPredicates pred;
    SuperTriangle sym(pts, pred, SuperTriangle::Mode::symbolic);
    const double d = 0x1p64;
    std::vector<Point2> at(pts.size() + 3);
    for (std::size_t i = 0; i < pts.size(); ++i) at[i] = {pts[i].x, pts[i].y};
    at[pts.size()] = {-d * d, -d};
    at[pts.size() + 1] = {d * d * d * d, -d * d * d};
    at[pts.size() + 2] = {d * d * d * d * d, d * d * d * d * d * d};
    const auto n = static_cast<VertexIndex>(at.size());
    std::uniform_int_distribution<VertexIndex> pick(0, n - 1);
    int checked = 0;
    int zeros = 0;
    for (int k = 0; k < 200000 && checked < 60000; ++k) {
        const VertexIndex a = pick(rng), b = pick(rng), c = pick(rng), e = pick(rng);
        if (a == b || a == c || b == c) continue;
        EXPECT_EQ(sym.orient(a, b, c), geom::orient2d(at[a], at[b], at[c])) << a << b << c;
        if (e == a || e == b || e == c) continue;
        if (a < pts.size() && b < pts.size() && c < pts.size() && e < pts.size()) continue;
        const int s = sym.incircle(a, b, c, e);
        ASSERT_EQ(s, geom::incircle(at[a], at[b], at[c], at[e]))
            << a << " " << b << " " << c << " " << e;
        zeros += s == 0;
        ++checked;
    }
    EXPECT_GT(checked, 10000);
    EXPECT_EQ(zeros, 0);  // a corner never lies on a circle
}

TEST(SuperTriangle, ItsCornersHoldEveryPointAndAreCounterClockwise) {
    const std::vector<Point3> pts{{-1e6, 3, 0}, {5, 1e7, 0}, {0, 0, 0}};
    CountingPredicates pred;
    SuperTriangle sym(pts, pred, SuperTriangle::Mode::symbolic);
    const VertexIndex s0 = sym.corner(0), s1 = sym.corner(1), s2 = sym.corner(2);
    EXPECT_EQ(sym.orient(s0, s1, s2), 1);
    EXPECT_EQ(sym.orient(s1, s0, s2), -1);
    for (VertexIndex v = 0; v < 3; ++v) {
        EXPECT_EQ(sym.orient(s0, s1, v), 1);
        EXPECT_EQ(sym.orient(s1, s2, v), 1);
        EXPECT_EQ(sym.orient(s2, s0, v), 1);
    }
    SuperTriangle fin(pts, pred, SuperTriangle::Mode::finite);
    for (VertexIndex v = 0; v < 3; ++v) {
        EXPECT_EQ(fin.orient(fin.corner(0), fin.corner(1), v), 1);
        EXPECT_EQ(fin.orient(fin.corner(1), fin.corner(2), v), 1);
        EXPECT_EQ(fin.orient(fin.corner(2), fin.corner(0), v), 1);
    }
}

}  // namespace
}  // namespace dtm::methods::detail
