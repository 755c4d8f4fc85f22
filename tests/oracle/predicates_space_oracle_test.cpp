// SPDX-License-Identifier: MIT
// dtm::geom::orient3d against CGAL's exact orientation of Point_3 (Epick), and
// dtm::geom::orient3d_lifted against CGAL's orientation of the points lifted to the paraboloid
// with exact rational lifts x^2 + y^2 (Cartesian<Exact_rational>): random, nearly coplanar /
// cocircular (a few ulps off), S-JTSK millimetres and extreme magnitudes.
#include <CGAL/Cartesian.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "dtm/geom/predicates.hpp"

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Rational = CGAL::Exact_rational;
using Exact = CGAL::Cartesian<Rational>;

constexpr double x0 = -750000.0;
constexpr double y0 = -1050000.0;

double nudge(double v, int k) {
    const double to =
        k > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::abs(k); ++i) v = std::nextafter(v, to);
    return v;
}

/// CGAL's orientation is positive when d is on the positive side of (a, b, c), i.e. when
/// (a, b, c, d) is a positively oriented tetrahedron; Shewchuk's orient3d (ours) is positive
/// when d is below counter-clockwise a, b, c. The two conventions are opposite.
int cgal_orient3d(const dtm::Point3& a,
                  const dtm::Point3& b,
                  const dtm::Point3& c,
                  const dtm::Point3& d) {
    using P = Epick::Point_3;
    return -static_cast<int>(
        CGAL::orientation(P(a.x, a.y, a.z), P(b.x, b.y, b.z), P(c.x, c.y, c.z), P(d.x, d.y, d.z)));
}

int cgal_lifted(const dtm::Point2& a,
                const dtm::Point2& b,
                const dtm::Point2& c,
                const dtm::Point2& d) {
    auto lift = [](const dtm::Point2& p) {
        const Rational x(p.x);
        const Rational y(p.y);
        return Exact::Point_3(x, y, x * x + y * y);
    };
    return -static_cast<int>(CGAL::orientation(lift(a), lift(b), lift(c), lift(d)));
}

TEST(PredicatesSpaceOracle, Orient3dAgreesWithCgal) {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> ulps(-4, 4);
    int zeros = 0;
    for (int i = 0; i < 200000; ++i) {
        dtm::Point3 p[4];
        for (dtm::Point3& q : p) q = {u(rng), u(rng), u(rng)};
        switch (i % 4) {
            case 1: {  // p3 on the segment p0-p1 (rounded), a few ulps off
                const double t = 0.5 + 0.5 * u(rng);
                p[3] = {p[0].x + t * (p[1].x - p[0].x), p[0].y + t * (p[1].y - p[0].y),
                        nudge(p[0].z + t * (p[1].z - p[0].z), ulps(rng))};
                break;
            }
            case 2:  // S-JTSK millimetres on an exact plane, then nudged
                for (dtm::Point3& q : p) {
                    const double a = std::round(500 * q.x) * 0.125;
                    const double b = std::round(500 * q.y) * 0.125;
                    q = {x0 + a, y0 + b, nudge(300 + 2 * a - b, ulps(rng) / 2)};
                }
                break;
            case 3: {
                const double s = (i % 8 == 3) ? 0x1p+300 : 0x1p-300;
                for (dtm::Point3& q : p) q = {q.x * s, q.y * s, q.z * s};
                break;
            }
            default:
                break;
        }
        const int ours = dtm::geom::orient3d(p[0], p[1], p[2], p[3]);
        ASSERT_EQ(ours, cgal_orient3d(p[0], p[1], p[2], p[3])) << i;
        zeros += ours == 0;
    }
    EXPECT_GT(zeros, 100);
}

TEST(PredicatesSpaceOracle, LiftedOrientationAgreesWithCgalOnExactLifts) {
    std::mt19937_64 rng(22);
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    std::uniform_int_distribution<int> ulps(-3, 3);
    std::uniform_int_distribution<int> lattice(-40, 40);
    int zeros = 0;
    for (int i = 0; i < 50000; ++i) {
        dtm::Point2 p[4];
        for (dtm::Point2& q : p) q = {u(rng), u(rng)};
        if (i % 3 == 1) {  // integer lattice squares: cocircular, then nudged
            const double a = lattice(rng), b = lattice(rng), s = 1 + std::abs(lattice(rng));
            p[0] = {x0 + a, y0 + b};
            p[1] = {x0 + a + s, y0 + b};
            p[2] = {x0 + a + s, y0 + b + s};
            p[3] = {x0 + a, nudge(y0 + b + s, ulps(rng))};
        } else if (i % 3 == 2) {
            for (dtm::Point2& q : p) {
                q = {std::round((x0 + q.x) * 1000) / 1000, std::round((y0 + q.y) * 1000) / 1000};
            }
        }
        const int ours = dtm::geom::orient3d_lifted(p[0], p[1], p[2], p[3]);
        ASSERT_EQ(ours, cgal_lifted(p[0], p[1], p[2], p[3])) << i;
        zeros += ours == 0;
    }
    EXPECT_GT(zeros, 1000);
}

}  // namespace
