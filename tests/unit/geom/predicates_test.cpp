// SPDX-License-Identifier: MIT
// Exact predicates: known signs reasoned by hand, symmetries, S-JTSK magnitudes, tilted grids,
// extreme magnitudes, and agreement of the adaptive path with an independent big-integer
// evaluation (geom/detail/bigint.hpp). The CGAL comparison lives in tests/oracle.
#include "dtm/geom/predicates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "dtm/core/point.hpp"
#include "geom/detail/bigint.hpp"
#include "geom/detail/expansion.hpp"

namespace {

using dtm::Point2;
using dtm::geom::incircle;
using dtm::geom::orient2d;
using dtm::geom::detail::incircle_bigint;
using dtm::geom::detail::orient2d_bigint;

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double x0 = -750000.0;  // S-JTSK-like origin
constexpr double y0 = -1050000.0;

double up(double v) { return std::nextafter(v, inf); }
double down(double v) { return std::nextafter(v, -inf); }

/// Grid for exact translations: multiples of 2^-20 below 2^11 plus a shift of magnitude
/// below 2^33 need at most 53 bits.
constexpr double grid = 0x1p-20;
constexpr double sx = 0x1p+32;
constexpr double sy = -0x1p+31 - 0x1p+30;
double quantize(double v) { return std::round(v / grid) * grid; }

int orient_p(Point2 a, Point2 b, Point2 c) { return orient2d(a, b, c); }
int incircle_p(Point2 a, Point2 b, Point2 c, Point2 d) { return incircle(a, b, c, d); }

TEST(Orient2d, SignsOfSimpleTurns) {
    EXPECT_EQ(orient2d(0.0, 0.0, 1.0, 0.0, 0.0, 1.0), 1);
    EXPECT_EQ(orient2d(0.0, 0.0, 0.0, 1.0, 1.0, 0.0), -1);
    EXPECT_EQ(orient2d(0.0, 0.0, 1.0, 1.0, 2.0, 2.0), 0);
    EXPECT_EQ(orient_p({0, 0}, {1, 0}, {0, 1}), 1);
}

TEST(Orient2d, ExactlyRepresentableCollinearPointsGiveZero) {
    // a, a + d, a + 2d with binary-fraction coordinates: every value is exact.
    for (const double dx : {0.125, 0.375, 3.0, -17.25}) {
        for (const double dy : {0.5, -0.0625, 1024.0}) {
            EXPECT_EQ(orient2d(x0, y0, x0 + dx, y0 + dy, x0 + 2 * dx, y0 + 2 * dy), 0);
            EXPECT_EQ(orient2d(x0 + 2 * dx, y0 + 2 * dy, x0, y0, x0 + dx, y0 + dy), 0);
        }
    }
    EXPECT_EQ(orient2d(1e15, 1e15, 2e15, 2e15, 3e15, 3e15), 0);
}

TEST(Orient2d, OneUlpOffTheLineGivesTheSideOfThePerturbation) {
    // Line direction (1, 1); moving c up puts it left of a->b (+1), down right of it (-1).
    EXPECT_EQ(orient2d(x0, y0, x0 + 1, y0 + 1, x0 + 2, up(y0 + 2)), 1);
    EXPECT_EQ(orient2d(x0, y0, x0 + 1, y0 + 1, x0 + 2, down(y0 + 2)), -1);
    EXPECT_EQ(orient2d(x0, y0, x0 + 1, y0 + 1, up(x0 + 2), y0 + 2), -1);
    EXPECT_EQ(orient2d(0.0, 0.0, 1.0, 1.0, 1e300, up(1e300)), 1);
    EXPECT_EQ(orient2d(0.0, 0.0, 3.0, 7.0, 3e10, up(7e10)), 1);
}

TEST(Orient2d, ShewchukNearDiagonalGridMatchesTheUlpOffsets) {
    // a = (0.5 + i ulp, 0.5 + j ulp), b = (12, 12), c = (24, 24): a is left of b->c exactly
    // when it lies above y = x, i.e. when j > i. Naive evaluation gets many of these wrong.
    const double ulp = std::nextafter(0.5, 1.0) - 0.5;
    for (int i = 0; i < 64; ++i) {
        for (int j = 0; j < 64; ++j) {
            const double ax = 0.5 + i * ulp;
            const double ay = 0.5 + j * ulp;
            const int expected = (j > i) - (j < i);
            ASSERT_EQ(orient2d(ax, ay, 12.0, 12.0, 24.0, 24.0), expected) << i << ' ' << j;
            ASSERT_EQ(orient2d(12.0, 12.0, 24.0, 24.0, ax, ay), expected) << i << ' ' << j;
        }
    }
}

TEST(Orient2d, SwapFlipsRotationKeepsExactTranslationKeeps) {
    std::mt19937_64 rng(42);
    std::uniform_int_distribution<int> small(-4, 4);
    std::uniform_real_distribution<double> coord(-1000.0, 1000.0);
    for (int k = 0; k < 20000; ++k) {
        // Nearly collinear: c on the line a-b, rounded, then nudged a few ulps.
        const Point2 a{coord(rng), coord(rng)};
        const Point2 b{coord(rng), coord(rng)};
        const double t = coord(rng) / 300.0;
        Point2 c{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        for (int s = small(rng); s != 0; s += s > 0 ? -1 : 1) {
            c.y = s > 0 ? up(c.y) : down(c.y);
        }
        const int o = orient_p(a, b, c);
        ASSERT_EQ(o, orient2d_bigint(a.x, a.y, b.x, b.y, c.x, c.y));
        ASSERT_EQ(orient_p(b, a, c), -o);
        ASSERT_EQ(orient_p(a, c, b), -o);
        ASSERT_EQ(orient_p(b, c, a), o);
        ASSERT_EQ(orient_p(c, a, b), o);
        // Translation: on a 2^-20 grid below 2^11, adding +-2^32 stays exact (53 bits).
        const Point2 qa{quantize(a.x), quantize(a.y)};
        const Point2 qb{quantize(b.x), quantize(b.y)};
        const Point2 qc{quantize(c.x), quantize(c.y) + small(rng) * grid};
        const int q = orient_p(qa, qb, qc);
        ASSERT_EQ(orient2d(qa.x + sx, qa.y + sy, qb.x + sx, qb.y + sy, qc.x + sx, qc.y + sy), q);
    }
}

TEST(Orient2d, SjtskMillimetreGridAgreesWithBigIntegerEvaluation) {
    // Millimetre steps are not binary fractions, so "collinear" grid points are only nearly
    // collinear: the big-integer evaluation is the independent reference.
    int zeros = 0;
    int nonzeros = 0;
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 40; ++j) {
            const double ax = x0 + 0.001 * i;
            const double ay = y0 + 0.001 * j;
            const double bx = x0 + 0.001 * (i + 7);
            const double by = y0 + 0.001 * (j + 3);
            const double cx = x0 + 0.001 * (i + 14);
            const double cy = y0 + 0.001 * (j + 6);
            const int o = orient2d(ax, ay, bx, by, cx, cy);
            ASSERT_EQ(o, orient2d_bigint(ax, ay, bx, by, cx, cy)) << i << ' ' << j;
            (o == 0 ? zeros : nonzeros) += 1;
        }
    }
    EXPECT_GT(nonzeros, 0);  // rounding makes many of them non-collinear
}

TEST(Orient2d, TiltedIntegerGridRowsAreCollinearAndCellsTurnLeft) {
    // p(i, j) = O + i u + j v with u = (3, 4) / 8, v = (-4, 3) / 8: all exact at S-JTSK size.
    auto p = [](int i, int j) {
        return Point2{x0 + (3.0 * i - 4.0 * j) / 8.0, y0 + (4.0 * i + 3.0 * j) / 8.0};
    };
    for (int i = -5; i < 5; ++i) {
        for (int j = -5; j < 5; ++j) {
            ASSERT_EQ(orient_p(p(i, j), p(i + 1, j), p(i + 3, j)), 0);
            ASSERT_EQ(orient_p(p(i, j), p(i, j + 2), p(i, j - 5)), 0);
            ASSERT_EQ(orient_p(p(i, j), p(i + 1, j + 1), p(i + 4, j + 4)), 0);
            ASSERT_EQ(orient_p(p(i, j), p(i + 1, j), p(i, j + 1)), 1);
            ASSERT_EQ(orient_p(p(i, j), p(i, j + 1), p(i + 1, j)), -1);
            ASSERT_EQ(orient_p(p(i, j), p(i + 2, j + 1), p(i + 4, j + 3)), 1);
        }
    }
}

TEST(Orient2d, ExtremeMagnitudesAreExact) {
    const double big = std::ldexp(1.0, 900);
    EXPECT_EQ(orient2d(big, big, 2 * big, 2 * big, 3 * big, 3 * big), 0);
    EXPECT_EQ(orient2d(big, big, 2 * big, 2 * big, 3 * big, up(3 * big)), 1);
    EXPECT_EQ(orient2d(-big, big, big, -big, 0.0, 0.0), 0);
    // Products underflow to zero in plain floating point; the true determinant is -2^-1252.
    const double t = std::ldexp(1.0, -600);
    EXPECT_EQ(orient2d(0.0, 0.0, t, t, up(t), t), -1);
    EXPECT_EQ(orient2d(0.0, 0.0, t, t, t, up(t)), 1);
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(orient2d(0.0, 0.0, tiny, tiny, 2 * tiny, 2 * tiny), 0);
    EXPECT_EQ(orient2d(0.0, 0.0, tiny, tiny, 2 * tiny, 3 * tiny), 1);
    const double max = std::numeric_limits<double>::max();
    EXPECT_EQ(orient2d(-max, -max, max, max, 0.0, 0.0), 0);
    EXPECT_EQ(orient2d(-max, -max, max, max, 0.0, tiny), 1);
    EXPECT_EQ(orient2d(-max, -max, max, max, tiny, 0.0), -1);
}

TEST(Orient2d, MixedMagnitudesAgreeWithBigIntegerEvaluation) {
    // Coordinates of very different sizes make the differences round, so near-degenerate
    // cases need the tails' products (stage D). First a case found that way.
    EXPECT_EQ(orient2d(0x1p+17, 0x1.8p+18, 0x1p+17, -0x1p+16, 0x1.0000000000002p+235, -0x1.4p+327),
              orient2d_bigint(0x1p+17, 0x1.8p+18, 0x1p+17, -0x1p+16, 0x1.0000000000002p+235,
                              -0x1.4p+327));
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<int> eighths(-8, 8);
    std::uniform_int_distribution<int> mag(-150, 240);
    std::uniform_int_distribution<int> ulps(-2, 2);
    for (int k = 0; k < 100000; ++k) {
        const int common = mag(rng);
        double v[6];
        for (double& x : v) {
            x = std::ldexp(eighths(rng) / 8.0, k % 3 == 0 ? common : mag(rng));
        }
        for (int s = ulps(rng); s != 0; s += s > 0 ? -1 : 1) {
            v[4] = s > 0 ? up(v[4]) : down(v[4]);
        }
        ASSERT_EQ(orient2d(v[0], v[1], v[2], v[3], v[4], v[5]),
                  orient2d_bigint(v[0], v[1], v[2], v[3], v[4], v[5]))
            << std::hexfloat << v[0] << ' ' << v[1] << ' ' << v[2] << ' ' << v[3] << ' ' << v[4]
            << ' ' << v[5];
    }
}

TEST(Incircle, MixedMagnitudesAgreeWithBigIntegerEvaluation) {
    std::mt19937_64 rng(12);
    std::uniform_int_distribution<int> eighths(-8, 8);
    std::uniform_int_distribution<int> mag(-60, 120);
    std::uniform_int_distribution<int> ulps(-2, 2);
    for (int k = 0; k < 50000; ++k) {
        const int common = mag(rng);
        double v[8];
        for (double& x : v) {
            x = std::ldexp(eighths(rng) / 8.0, k % 3 == 0 ? common : mag(rng));
        }
        for (int s = ulps(rng); s != 0; s += s > 0 ? -1 : 1) {
            v[6] = s > 0 ? up(v[6]) : down(v[6]);
        }
        ASSERT_EQ(incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]),
                  incircle_bigint(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]))
            << std::hexfloat << v[0] << ' ' << v[1] << ' ' << v[2] << ' ' << v[3] << ' ' << v[4]
            << ' ' << v[5] << ' ' << v[6] << ' ' << v[7];
    }
}

TEST(Incircle, UnitCircleCases) {
    EXPECT_EQ(incircle(1.0, 0.0, 0.0, 1.0, -1.0, 0.0, 0.0, 0.0), 1);
    EXPECT_EQ(incircle(1.0, 0.0, 0.0, 1.0, -1.0, 0.0, 2.0, 2.0), -1);
    EXPECT_EQ(incircle(1.0, 0.0, 0.0, 1.0, -1.0, 0.0, 0.0, -1.0), 0);
    // Clockwise a, b, c flips the sign.
    EXPECT_EQ(incircle(0.0, 1.0, 1.0, 0.0, -1.0, 0.0, 0.0, 0.0), -1);
}

TEST(Incircle, PythagoreanCocircularPointsAndOneUlpMoves) {
    // (5,0), (3,4), (-4,3), (0,-5) lie on the circle of radius 5, shifted to S-JTSK size.
    const double cx = x0;
    const double cy = y0;
    EXPECT_EQ(incircle(cx + 5, cy, cx + 3, cy + 4, cx - 4, cy + 3, cx, cy - 5), 0);
    EXPECT_EQ(incircle(cx + 5, cy, cx + 3, cy + 4, cx - 4, cy + 3, cx, down(cy - 5)), -1);
    EXPECT_EQ(incircle(cx + 5, cy, cx + 3, cy + 4, cx - 4, cy + 3, cx, up(cy - 5)), 1);
    EXPECT_EQ(incircle(cx + 5, cy, cx + 3, cy + 4, cx - 4, cy + 3, down(cx - 3), cy - 4), -1);
    EXPECT_EQ(incircle(cx + 5, cy, cx + 3, cy + 4, cx - 4, cy + 3, up(cx - 3), cy - 4), 1);
    EXPECT_EQ(incircle(cx + 3, cy + 4, cx - 4, cy + 3, cx, cy - 5, cx + 5, cy), 0);
}

TEST(Incircle, SymmetriesOnNearlyCocircularPoints) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<int> small(-3, 3);
    for (int k = 0; k < 20000; ++k) {
        const double r = 0.5 + 100.0 * unit(rng);
        const double ox = 200.0 * unit(rng) - 100.0;
        const double oy = 200.0 * unit(rng) - 100.0;
        Point2 q[4];
        for (auto& pt : q) {
            const double t = angle(rng);
            pt = {ox + r * std::cos(t), oy + r * std::sin(t)};
        }
        for (int s = small(rng); s != 0; s += s > 0 ? -1 : 1) {
            q[3].x = s > 0 ? up(q[3].x) : down(q[3].x);
        }
        const auto [a, b, c, d] = q;
        const int v = incircle_p(a, b, c, d);
        ASSERT_EQ(v, incircle_bigint(a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y));
        ASSERT_EQ(incircle_p(b, a, c, d), -v);
        ASSERT_EQ(incircle_p(b, c, a, d), v);
        ASSERT_EQ(incircle_p(a, c, b, d), -v);
        // The sign of the 4x4 determinant is antisymmetric in all four points.
        ASSERT_EQ(incircle_p(d, b, c, a), -v);
        Point2 t[4];
        for (int m = 0; m < 4; ++m) {
            t[m] = {quantize(q[m].x), quantize(q[m].y)};
        }
        t[3].y += small(rng) * grid;
        const int w = incircle_p(t[0], t[1], t[2], t[3]);
        ASSERT_EQ(incircle(t[0].x + sx, t[0].y + sy, t[1].x + sx, t[1].y + sy, t[2].x + sx,
                           t[2].y + sy, t[3].x + sx, t[3].y + sy),
                  w);
    }
}

TEST(Incircle, TiltedGridCellCornersAreCocircular) {
    auto p = [](int i, int j) {
        return Point2{x0 + (3.0 * i - 4.0 * j) / 8.0, y0 + (4.0 * i + 3.0 * j) / 8.0};
    };
    for (int i = -4; i < 4; ++i) {
        for (int j = -4; j < 4; ++j) {
            // Corners of any grid rectangle are cocircular; (a, b, c) turn left.
            ASSERT_EQ(incircle_p(p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)), 0);
            ASSERT_EQ(incircle_p(p(i, j), p(i + 2, j), p(i + 2, j + 3), p(i, j + 3)), 0);
            ASSERT_EQ(incircle_p(p(i + 2, j + 3), p(i, j + 3), p(i, j), p(i + 2, j)), 0);
            ASSERT_EQ(incircle_p(p(i, j), p(i + 2, j), p(i + 2, j + 2), p(i + 1, j + 1)), 1);
            ASSERT_EQ(incircle_p(p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i + 3, j)), -1);
            ASSERT_EQ(incircle_p(p(i, j), p(i + 1, j + 1), p(i + 1, j), p(i + 3, j)), 1);
        }
    }
}

TEST(Incircle, SjtskMillimetreGridAgreesWithBigIntegerEvaluation) {
    for (int i = 0; i < 30; ++i) {
        for (int j = 0; j < 30; ++j) {
            const double ax = x0 + 0.001 * i;
            const double ay = y0 + 0.001 * j;
            const double bx = x0 + 0.001 * (i + 5);
            const double by = y0 + 0.001 * j;
            const double cx = x0 + 0.001 * (i + 5);
            const double cy = y0 + 0.001 * (j + 5);
            const double dx = x0 + 0.001 * i;
            const double dy = y0 + 0.001 * (j + 5);
            ASSERT_EQ(incircle(ax, ay, bx, by, cx, cy, dx, dy),
                      incircle_bigint(ax, ay, bx, by, cx, cy, dx, dy))
                << i << ' ' << j;
        }
    }
}

TEST(Incircle, ExtremeMagnitudesAreExact) {
    const double big = std::ldexp(1.0, 600);
    EXPECT_EQ(incircle(big, 0.0, 0.0, big, -big, 0.0, 0.0, -big), 0);
    EXPECT_EQ(incircle(big, 0.0, 0.0, big, -big, 0.0, 0.0, up(-big)), 1);
    const double t = std::ldexp(1.0, -500);
    EXPECT_EQ(incircle(t, 0.0, 0.0, t, -t, 0.0, 0.0, -t), 0);
    EXPECT_EQ(incircle(t, 0.0, 0.0, t, -t, 0.0, 0.0, down(-t)), -1);
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(incircle(tiny, 0.0, 0.0, tiny, -tiny, 0.0, 0.0, -tiny), 0);
    EXPECT_EQ(incircle(4 * tiny, 0.0, 0.0, 4 * tiny, -4 * tiny, 0.0, 0.0, 0.0), 1);
    const double max = std::numeric_limits<double>::max();
    EXPECT_EQ(incircle(max, 0.0, 0.0, max, -max, 0.0, 0.0, -max), 0);
    EXPECT_EQ(incircle(max, 0.0, 0.0, max, -max, 0.0, 1.0, 1.0), 1);
}

TEST(Incircle, StageDExpansionsAgreeWithBigIntegersWhenDifferencesAreInexact) {
    // Points straddling the origin with very different magnitudes: coordinate differences
    // round, so stage D (full expansions with tails) must be right on its own.
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> scale(-30, 30);
    for (int k = 0; k < 5000; ++k) {
        double v[8];
        for (double& x : v) {
            x = std::ldexp(unit(rng), scale(rng));
        }
        ASSERT_EQ(dtm::geom::detail::incircle_exact(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]),
                  incircle_bigint(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
    }
}

}  // namespace

namespace {

/// Near-degenerate and mixed-magnitude cases that reach stages B-D, against big integers.
void check_adaptive_stages_against_bigint() {
    std::mt19937_64 rng(21);
    std::uniform_int_distribution<int> eighths(-8, 8);
    std::uniform_int_distribution<int> mag(-60, 120);
    std::uniform_int_distribution<int> ulps(-2, 2);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 30000; ++k) {
        const int common = mag(rng);
        double v[8];
        for (double& x : v) {
            x = std::ldexp(eighths(rng) / 8.0, k % 3 == 0 ? common : mag(rng));
        }
        for (int s = ulps(rng); s != 0; s += s > 0 ? -1 : 1) {
            v[6] = s > 0 ? up(v[6]) : down(v[6]);
        }
        ASSERT_EQ(orient2d(v[0], v[1], v[2], v[3], v[6], v[7]),
                  orient2d_bigint(v[0], v[1], v[2], v[3], v[6], v[7]));
        ASSERT_EQ(incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]),
                  incircle_bigint(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
    }
    for (int k = 0; k < 20000; ++k) {
        // Nearly cocircular at S-JTSK size: exact differences, inexact products.
        const double r = 1.0 + 50.0 * unit(rng);
        double v[8];
        for (int m = 0; m < 4; ++m) {
            const double t = 6.283185307179586 * unit(rng);
            v[2 * m] = x0 + r * std::cos(t);
            v[2 * m + 1] = y0 + r * std::sin(t);
        }
        ASSERT_EQ(incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]),
                  incircle_bigint(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
    }
    // Binary-fraction lattice: exactly cocircular cells (incircle's short route).
    for (int i = 0; i < 20; ++i) {
        const double ax = x0 + i * 0.375;
        const double ay = y0 + i * 0.5;
        ASSERT_EQ(incircle(ax, ay, ax + 1.5, ay, ax + 1.5, ay + 2.25, ax, ay + 2.25), 0);
        ASSERT_EQ(incircle(ax, ay, ax + 1.5, ay, ax + 1.5, ay + 2.25, ax + 0.75, ay + 1.0), 1);
        ASSERT_EQ(incircle(ax, ay, ax + 1.5, ay, ax + 1.5, ay + 2.25, ax - 0.25, ay), -1);
        ASSERT_EQ(orient2d(ax, ay, ax + 1.5, ay + 2.25, ax + 3.0, ay + 4.5), 0);
    }
}

TEST(AdaptiveStages, PortableTwoProductIsExact) {
    ASSERT_TRUE(dtm::geom::detail::use_fma_in_adaptive_stages(false));
    check_adaptive_stages_against_bigint();
    dtm::geom::detail::use_fma_in_adaptive_stages(true);  // restore the default where possible
}

TEST(AdaptiveStages, FusedMultiplyAddTwoProductIsExact) {
    if (!dtm::geom::detail::use_fma_in_adaptive_stages(true)) {
        GTEST_SKIP() << "this CPU has no FMA instruction";
    }
    check_adaptive_stages_against_bigint();
}

}  // namespace
