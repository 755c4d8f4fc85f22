// SPDX-License-Identifier: MIT
// orient3d, orient3d_lifted and compare_distances: hand-checked signs, antisymmetry, exact
// zeros on grids, one-ulp perturbations at S-JTSK magnitudes, extreme magnitudes, and
// agreement with independent big-integer evaluations written here (orient3d as the 4x4
// determinant with a column of ones; the lifted predicate on the untranslated lifts
// x^2 + y^2). The CGAL comparison lives in tests/oracle.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "dtm/core/point.hpp"
#include "dtm/geom/predicates.hpp"
#include "geom/detail/bigint.hpp"

namespace {

using dtm::Point2;
using dtm::Point3;
using dtm::geom::compare_distances;
using dtm::geom::orient3d;
using dtm::geom::orient3d_lifted;
namespace d = dtm::geom::detail;

constexpr double x0 = -750000.0;
constexpr double y0 = -1050000.0;

d::BigInt mul(const d::BigInt& a, const d::BigInt& b) {
    d::BigInt r;
    d::bigint_mul(a, b, r);
    return r;
}
d::BigInt add(const d::BigInt& a, const d::BigInt& b) {
    d::BigInt r;
    d::bigint_add(a, b, r);
    return r;
}
d::BigInt sub(const d::BigInt& a, const d::BigInt& b) {
    d::BigInt r;
    d::bigint_sub(a, b, r);
    return r;
}

/// det of a 3x3 big-integer matrix by cofactors.
d::BigInt det3(const std::array<std::array<d::BigInt, 3>, 3>& m) {
    const d::BigInt t0 = mul(m[0][0], sub(mul(m[1][1], m[2][2]), mul(m[1][2], m[2][1])));
    const d::BigInt t1 = mul(m[0][1], sub(mul(m[1][0], m[2][2]), mul(m[1][2], m[2][0])));
    const d::BigInt t2 = mul(m[0][2], sub(mul(m[1][0], m[2][1]), mul(m[1][1], m[2][0])));
    return add(sub(t0, t1), t2);
}

/// sign det [[x y z 1]] of rows a, b, c, d (equal to det[a-d; b-d; c-d]), expanded along the
/// column of ones: -M(a) + M(b) - M(c) + M(d) with M the 3x3 minors of the other rows.
int orient3d_reference(const std::array<std::array<d::BigInt, 3>, 4>& rows) {
    d::BigInt total;
    for (int skip = 0; skip < 4; ++skip) {
        std::array<std::array<d::BigInt, 3>, 3> m;
        int r = 0;
        for (int i = 0; i < 4; ++i) {
            if (i != skip) m[static_cast<std::size_t>(r++)] = rows[static_cast<std::size_t>(i)];
        }
        const d::BigInt minor = det3(m);
        // cofactor of row `skip`, column 4: (-1)^(skip + 4) with 1-based row skip + 1.
        total = (skip % 2 == 0) ? sub(total, minor) : add(total, minor);
    }
    return total.sign;
}

int orient3d_bigint(const Point3& a, const Point3& b, const Point3& c, const Point3& p) {
    const double v[12] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, p.x, p.y, p.z};
    const int base = d::common_exponent(v, 12);
    std::array<std::array<d::BigInt, 3>, 4> rows;
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 3; ++k) {
            rows[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] =
                d::bigint_from_double(v[3 * i + k], base);
        }
    }
    return orient3d_reference(rows);
}

/// The lifted determinant on the untranslated lifts x^2 + y^2, all on one power of two: the
/// lifts' scale is base^2, so x and y are multiplied by 2^-base once more (a positive factor
/// per column, which keeps the sign).
int orient3d_lifted_bigint(Point2 a, Point2 b, Point2 c, Point2 p) {
    const double v[8] = {a.x, a.y, b.x, b.y, c.x, c.y, p.x, p.y};
    const int base = d::common_exponent(v, 8);
    std::array<std::array<d::BigInt, 3>, 4> rows;
    for (int i = 0; i < 4; ++i) {
        const d::BigInt x = d::bigint_from_double(v[2 * i], base);
        const d::BigInt y = d::bigint_from_double(v[2 * i + 1], base);
        rows[static_cast<std::size_t>(i)] = {x, y, add(mul(x, x), mul(y, y))};
    }
    return orient3d_reference(rows);
}

int distances_bigint(Point2 a, Point2 b, Point2 c, Point2 p) {
    const double v[8] = {a.x, a.y, b.x, b.y, c.x, c.y, p.x, p.y};
    const int base = d::common_exponent(v, 8);
    auto sq = [&](double u, double w) {
        const d::BigInt t = sub(d::bigint_from_double(u, base), d::bigint_from_double(w, base));
        return mul(t, t);
    };
    return sub(add(sq(a.x, b.x), sq(a.y, b.y)), add(sq(c.x, p.x), sq(c.y, p.y))).sign;
}

double nudge(double v, int k) {
    const double to =
        k > 0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    for (int i = 0; i < std::abs(k); ++i) v = std::nextafter(v, to);
    return v;
}

TEST(Orient3d, SignsOfSimpleConfigurations) {
    const Point3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    EXPECT_EQ(orient3d(a, b, c, Point3{0.2, 0.2, -1}), 1);  // below a ccw triangle
    EXPECT_EQ(orient3d(a, b, c, Point3{0.2, 0.2, 1}), -1);
    EXPECT_EQ(orient3d(a, b, c, Point3{5, 7, 0}), 0);
    EXPECT_EQ(orient3d(b, a, c, Point3{0.2, 0.2, -1}), -1);
}

TEST(Orient3d, AntisymmetricAndExactOnTiltedLatticePlanes) {
    // Points of the plane z = 3x - 5y + 7 on a binary lattice at S-JTSK offsets: exactly
    // coplanar, and a one-ulp change in z takes them off it.
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int> k(-4000, 4000);
    for (int i = 0; i < 2000; ++i) {
        Point3 p[4];
        for (Point3& q : p) {
            const double u = k(rng) * 0.125;
            const double w = k(rng) * 0.125;
            q = {x0 + u, y0 + w, 3 * u - 5 * w + 7};
        }
        EXPECT_EQ(orient3d(p[0], p[1], p[2], p[3]), 0);
        Point3 up = p[3];
        up.z = nudge(up.z, 1);
        const int o = orient3d(p[0], p[1], p[2], up);
        EXPECT_EQ(o, orient3d_bigint(p[0], p[1], p[2], up));
        EXPECT_EQ(orient3d(p[1], p[0], p[2], up), -o);
        EXPECT_EQ(orient3d(p[1], p[2], p[0], up), o);
    }
}

TEST(Orient3d, AgreesWithBigIntegersOnRandomNearlyCoplanarAndExtremeInput) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> ulps(-3, 3);
    int zeros = 0;
    for (int i = 0; i < 20000; ++i) {
        Point3 p[4];
        const int family = i % 4;
        for (Point3& q : p) q = {u(rng), u(rng), u(rng)};
        if (family == 1) {
            // p[3] on the plane of the others (rounded), then a few ulps off.
            const double s = u(rng), t = u(rng);
            for (int k = 0; k < 3; ++k) {
                const double* a = &p[0].x;
                const double* b = &p[1].x;
                const double* c = &p[2].x;
                (&p[3].x)[k] = nudge(a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]), ulps(rng));
            }
        } else if (family == 2) {
            for (Point3& q : p) q = {x0 + 1000 * q.x, y0 + 1000 * q.y, 300 + 50 * q.z};
            p[3].z = nudge(p[0].z, ulps(rng));
            p[3].x = p[0].x + 0.5 * (p[1].x - p[0].x);
            p[3].y = p[0].y + 0.5 * (p[1].y - p[0].y);
            p[3].z = nudge(p[0].z + 0.5 * (p[1].z - p[0].z), ulps(rng));
        } else if (family == 3) {
            const double scale = (i % 8 == 3) ? 0x1p+600 : 0x1p-600;
            for (Point3& q : p) q = {q.x * scale, q.y * scale, q.z * scale};
            p[3] = {nudge(p[0].x, ulps(rng)), p[1].y, nudge(p[2].z, ulps(rng))};
        }
        const int o = orient3d(p[0], p[1], p[2], p[3]);
        ASSERT_EQ(o, orient3d_bigint(p[0], p[1], p[2], p[3]))
            << std::hexfloat << p[0].x << ' ' << p[0].y << ' ' << p[0].z << " / " << p[3].x;
        zeros += o == 0;
    }
    EXPECT_GT(zeros, 0);
}

TEST(Orient3dLifted, IsTheOrientationOfTheExactLifts) {
    // Untranslated lifts in big integers against the predicate, on random, cocircular
    // (lattice circle points), one-ulp-perturbed and S-JTSK millimetre input.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    std::uniform_int_distribution<int> ulps(-2, 2);
    int zeros = 0;
    for (int i = 0; i < 20000; ++i) {
        Point2 p[4];
        for (Point2& q : p) q = {u(rng), u(rng)};
        switch (i % 4) {
            case 1:  // the unit-square corners of an integer lattice, shifted
                p[0] = {x0 + 3, y0 + 4};
                p[1] = {x0 + 8, y0 + 4};
                p[2] = {x0 + 8, y0 + 9};
                p[3] = {x0 + 3, nudge(y0 + 9, ulps(rng))};
                break;
            case 2:  // (+-3, +-4) and (+-5, 0) on the circle of radius 5 at a millimetre origin
                p[0] = {x0 + 3, y0 + 4};
                p[1] = {x0 - 5, y0};
                p[2] = {x0 + 3, y0 - 4};
                p[3] = {nudge(x0 + 5, ulps(rng)), y0};
                break;
            case 3:
                for (Point2& q : p) {
                    q = {std::round((x0 + q.x) * 1000) / 1000,
                         std::round((y0 + q.y) * 1000) / 1000};
                }
                break;
            default:
                break;
        }
        const int o = orient3d_lifted(p[0], p[1], p[2], p[3]);
        ASSERT_EQ(o, orient3d_lifted_bigint(p[0], p[1], p[2], p[3])) << i;
        zeros += o == 0;
    }
    EXPECT_GT(zeros, 100);
    // Orientation of the lifts of a ccw triangle and a point inside its circumcircle: below.
    EXPECT_EQ(orient3d_lifted(Point2{0, 0}, Point2{1, 0}, Point2{0, 1}, Point2{0.3, 0.3}), 1);
    EXPECT_EQ(orient3d_lifted(Point2{0, 0}, Point2{1, 0}, Point2{0, 1}, Point2{3, 3}), -1);
}

TEST(CompareDistances, ExactOnTiesAndNearTies) {
    EXPECT_EQ(compare_distances(Point2{0, 0}, Point2{3, 4}, Point2{1, 1}, Point2{6, 1}), 0);
    EXPECT_EQ(compare_distances(Point2{0, 0}, Point2{1, 0}, Point2{0, 0}, Point2{0, 2}), -1);
    EXPECT_EQ(compare_distances(Point2{0, 0}, Point2{0, 3}, Point2{0, 0}, Point2{2, 2}), 1);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> ulps(-3, 3);
    int zeros = 0;
    for (int i = 0; i < 20000; ++i) {
        Point2 p[4];
        for (Point2& q : p) q = {u(rng), u(rng)};
        const int family = i % 4;
        if (family == 1) {  // equal lengths by symmetry, then a few ulps off
            p[2] = {p[0].y, p[0].x};
            p[3] = {p[1].y, nudge(p[1].x, ulps(rng))};
        } else if (family == 2) {  // S-JTSK millimetres
            for (Point2& q : p) q = {std::round((x0 + 1000 * q.x) * 1000) / 1000, y0 + 1000 * q.y};
            p[2] = {p[0].x + (p[1].y - p[0].y), p[0].y - (p[1].x - p[0].x)};
            p[3] = {nudge(p[0].x, ulps(rng)), p[0].y};
        } else if (family == 3) {
            const double scale = (i % 8 == 3) ? 0x1p+700 : 0x1p-700;
            for (Point2& q : p) q = {q.x * scale, q.y * scale};
            p[2] = {-p[0].x, -p[0].y};
            p[3] = {nudge(-p[1].x, ulps(rng)), -p[1].y};
        }
        const int o = compare_distances(p[0], p[1], p[2], p[3]);
        ASSERT_EQ(o, distances_bigint(p[0], p[1], p[2], p[3])) << i;
        zeros += o == 0;
    }
    EXPECT_GT(zeros, 100);
}

}  // namespace
