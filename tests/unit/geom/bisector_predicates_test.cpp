// SPDX-License-Identifier: MIT
// The exact bisector predicates against 128-bit integer evaluation, on inputs built to be
// degenerate or nearly so, and at extreme magnitudes (scaling by powers of two keeps the sign).
#include "dtm/geom/bisector_predicates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace dtm::geom {
namespace {

__extension__ typedef __int128 I;

int sign(I v) { return (v > 0) - (v < 0); }

I power_difference(I px, I py, I gx, I gy, I hx, I hy) {
    return (px - gx) * (px - gx) + (py - gy) * (py - gy) - (px - hx) * (px - hx) -
           (py - hy) * (py - hy);
}

TEST(BisectorPredicates, DotSignIsExact) {
    std::mt19937_64 rng(2);
    std::uniform_int_distribution<long long> u(-(1LL << 40), 1LL << 40);
    for (int i = 0; i < 100000; ++i) {
        const long long ax = u(rng), ay = u(rng), bx = u(rng), by = u(rng);
        long long cx = u(rng), cy = u(rng), dx = u(rng), dy = u(rng);
        if (i % 2 == 0) {  // perpendicular: d - c a multiple of rot90(b - a)
            dx = cx - (by - ay) / 4;
            dy = cy + (bx - ax) / 4;
        }
        const I expected = I(bx - ax) * (dx - cx) + I(by - ay) * (dy - cy);
        ASSERT_EQ(dot_sign(double(ax), double(ay), double(bx), double(by), double(cx), double(cy),
                           double(dx), double(dy)),
                  sign(expected))
            << i;
    }
}

TEST(BisectorPredicates, CrossingOrderIsExact) {
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<long long> u(-(1LL << 18), 1LL << 18);
    int tested = 0;
    for (int i = 0; i < 100000 && tested < 30000; ++i) {
        const Point2 a{double(u(rng)), double(u(rng))}, b{double(u(rng)), double(u(rng))};
        const Point2 g{double(u(rng)), double(u(rng))}, h{double(u(rng)), double(u(rng))};
        Point2 k{double(u(rng)), double(u(rng))};
        const auto f = [](const Point2& x, const Point2& p, const Point2& q) {
            return power_difference(I(x.x), I(x.y), I(p.x), I(p.y), I(q.x), I(q.y));
        };
        const I ha = f(a, g, h), hb = f(b, g, h);
        if (sign(ha) == 0 || sign(ha) == sign(hb)) continue;
        if (i % 3 == 0) {
            // k the mirror of g in line a-b's crossing direction: often exactly on the bisector
            // of g and k at the crossing when the configuration is symmetric.
            k = {2 * h.x - g.x, 2 * h.y - g.y};
        }
        ++tested;
        const I ka = f(a, g, k), kb = f(b, g, k);
        const int expected = sign(ha * kb - ka * hb) * sign(ha);
        ASSERT_EQ(crossing_order(a, b, g, h, k), expected) << i;
        // Scaling every coordinate by a power of two keeps the sign (big-integer path too).
        if (i % 10 != 0) continue;
        for (const int e : {-400, -60, 300, 600}) {
            const auto s = [e](const Point2& p) {
                return Point2{std::ldexp(p.x, e), std::ldexp(p.y, e)};
            };
            ASSERT_EQ(crossing_order(s(a), s(b), s(g), s(h), s(k)), expected) << i << " " << e;
        }
    }
    EXPECT_GT(tested, 20000);
}

}  // namespace
}  // namespace dtm::geom
