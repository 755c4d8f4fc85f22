// SPDX-License-Identifier: MIT
// dtm::geom::orient2d / incircle against CGAL's exact predicates (Epick `orientation` and
// `side_of_oriented_circle`, which are exact through interval filters and an exact fallback).
// Millions of cases: random, one-ulp-perturbed collinear / cocircular, tilted grids,
// S-JTSK magnitudes with millimetre spacing, and extreme magnitudes.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "dtm/geom/predicates.hpp"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P = K::Point_2;

constexpr double x0 = -750000.0;
constexpr double y0 = -1050000.0;

int cgal_orient(double ax, double ay, double bx, double by, double cx, double cy) {
    return static_cast<int>(CGAL::orientation(P(ax, ay), P(bx, by), P(cx, cy)));
}

int cgal_incircle(
    double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    return static_cast<int>(
        CGAL::side_of_oriented_circle(P(ax, ay), P(bx, by), P(cx, cy), P(dx, dy)));
}

/// Moves v by k ulps (k may be negative).
double nudge(double v, int k) {
    const double to =
        k > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::abs(k); ++i) {
        v = std::nextafter(v, to);
    }
    return v;
}

struct Counts {
    std::int64_t cases = 0;
    std::int64_t zeros = 0;
};

void check_orient(const double* v, Counts& n) {
    const int ours = dtm::geom::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]);
    const int ref = cgal_orient(v[0], v[1], v[2], v[3], v[4], v[5]);
    ASSERT_EQ(ours, ref) << std::hexfloat << v[0] << ' ' << v[1] << ' ' << v[2] << ' ' << v[3]
                         << ' ' << v[4] << ' ' << v[5];
    ++n.cases;
    n.zeros += ours == 0;
}

void check_incircle(const double* v, Counts& n) {
    const int ours = dtm::geom::incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    const int ref = cgal_incircle(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
    ASSERT_EQ(ours, ref) << std::hexfloat << v[0] << ' ' << v[1] << ' ' << v[2] << ' ' << v[3]
                         << ' ' << v[4] << ' ' << v[5] << ' ' << v[6] << ' ' << v[7];
    ++n.cases;
    n.zeros += ours == 0;
}

TEST(PredicatesOracle, RandomPointsAgreeWithCgal) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1000.0, 1000.0);
    Counts o;
    Counts c;
    for (int k = 0; k < 1000000; ++k) {
        double v[8];
        for (double& x : v) {
            x = u(rng);
        }
        check_orient(v, o);
        check_incircle(v, c);
        if (testing::Test::HasFatalFailure()) {
            return;
        }
    }
}

TEST(PredicatesOracle, NearlyCollinearPointsAgreeWithCgal) {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> ulps(-3, 3);
    std::uniform_int_distribution<int> mag(-20, 25);
    Counts o;
    for (int k = 0; k < 400000; ++k) {
        // Alternate S-JTSK offsets with points around the origin (where differences round).
        const bool sjtsk = k % 2 == 0;
        const double s = std::ldexp(1.0, mag(rng));
        const double ox = sjtsk ? x0 : 0.0;
        const double oy = sjtsk ? y0 : 0.0;
        const double ax = ox + s * u(rng);
        const double ay = oy + s * u(rng);
        const double bx = ox + s * u(rng);
        const double by = oy + s * u(rng);
        const double t = 4.0 * u(rng);
        const double v[6] = {ax,
                             ay,
                             bx,
                             by,
                             nudge(ax + t * (bx - ax), ulps(rng)),
                             nudge(ay + t * (by - ay), ulps(rng))};
        check_orient(v, o);
        if (testing::Test::HasFatalFailure()) {
            return;
        }
    }
    EXPECT_GT(o.zeros, 0);
}

TEST(PredicatesOracle, NearlyCocircularPointsAgreeWithCgal) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::uniform_int_distribution<int> ulps(-2, 2);
    std::uniform_int_distribution<int> mag(-10, 12);
    Counts c;
    for (int k = 0; k < 400000; ++k) {
        const bool sjtsk = k % 2 == 0;
        const double r = std::ldexp(0.5 + u(rng), mag(rng));
        const double ox = (sjtsk ? x0 : 0.0) + r * (u(rng) - 0.5);
        const double oy = (sjtsk ? y0 : 0.0) + r * (u(rng) - 0.5);
        double v[8];
        for (int i = 0; i < 4; ++i) {
            const double t = 6.283185307179586 * u(rng);
            v[2 * i] = nudge(ox + r * std::cos(t), ulps(rng));
            v[2 * i + 1] = nudge(oy + r * std::sin(t), ulps(rng));
        }
        check_incircle(v, c);
        if (testing::Test::HasFatalFailure()) {
            return;
        }
    }
}

TEST(PredicatesOracle, TiltedAndMillimetreGridsAgreeWithCgal) {
    // Grid p(i, j) = O + i u + j v. Tilted by 3-4-5 at exact eighths, and at S-JTSK size with
    // millimetre steps (not exact in binary, so "degenerate" cases are only nearly so).
    struct Grid {
        double ux, uy, vx, vy;
    };
    const Grid grids[] = {{3.0 / 8, 4.0 / 8, -4.0 / 8, 3.0 / 8},
                          {0.001, 0.0, 0.0, 0.001},
                          {0.003, 0.004, -0.004, 0.003},
                          {0.1, 0.1, -0.1, 0.1}};
    constexpr int n = 12;
    Counts o;
    Counts c;
    std::mt19937_64 rng(4);
    std::uniform_int_distribution<int> idx(0, n - 1);
    for (const Grid& g : grids) {
        auto px = [&](int i, int j) { return x0 + (i * g.ux + j * g.vx); };
        auto py = [&](int i, int j) { return y0 + (i * g.uy + j * g.vy); };
        for (int k = 0; k < 150000; ++k) {
            int ij[8];
            for (int& x : ij) {
                x = idx(rng);
            }
            double v[8];
            for (int m = 0; m < 4; ++m) {
                v[2 * m] = px(ij[2 * m], ij[2 * m + 1]);
                v[2 * m + 1] = py(ij[2 * m], ij[2 * m + 1]);
            }
            check_orient(v, o);
            check_incircle(v, c);
            if (testing::Test::HasFatalFailure()) {
                return;
            }
        }
    }
    EXPECT_GT(o.zeros, 0);
    EXPECT_GT(c.zeros, 0);
}

TEST(PredicatesOracle, ExtremeMagnitudesAgreeWithCgal) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> mag(-1074, 1023);
    std::uniform_int_distribution<int> ulps(-2, 2);
    std::uniform_int_distribution<int> pick(0, 2);
    Counts o;
    Counts c;
    for (int k = 0; k < 20000; ++k) {
        // One common scale (so cases are often nearly degenerate) or independent scales.
        const int common = mag(rng);
        double v[8];
        for (double& x : v) {
            const int e = pick(rng) == 0 ? mag(rng) : common;
            x = std::ldexp(std::round(u(rng) * 8.0) / 8.0, e);
        }
        v[4] = nudge(v[4], ulps(rng));
        check_orient(v, o);
        check_incircle(v, c);
        if (testing::Test::HasFatalFailure()) {
            return;
        }
    }
    EXPECT_GT(o.zeros, 0);
}

}  // namespace
