// SPDX-License-Identifier: MIT
// The Clough-Tocher element: quadratic precision with exact gradients, interpolation of the
// corner data, C1 across its inner edges and across the edge shared with a neighbour.
#include "dtm/algo/clough_tocher.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using dtm::CloughTocherPatch;
using dtm::CornerDerivatives;
using dtm::Point3;

struct Quadratic {
    double c, gx, gy, xx, xy, yy;
    [[nodiscard]] double f(double x, double y) const {
        return c + gx * x + gy * y + xx * x * x + xy * x * y + yy * y * y;
    }
    [[nodiscard]] std::array<double, 2> grad(double x, double y) const {
        return {gx + 2 * xx * x + xy * y, gy + xy * x + 2 * yy * y};
    }
};

CornerDerivatives exact_derivatives(const std::array<Point3, 3>& v, const Quadratic& q) {
    CornerDerivatives d{};
    for (std::size_t i = 0; i < 3; ++i) {
        const auto g = q.grad(v[i].x, v[i].y);
        for (std::size_t s = 0; s < 2; ++s) {
            const Point3& w = v[(i + 1 + s) % 3];
            d[i][s] = g[0] * (w.x - v[i].x) + g[1] * (w.y - v[i].y);
        }
    }
    return d;
}

std::array<Point3, 3> with_heights(std::array<Point3, 3> v, const Quadratic& q) {
    for (Point3& p : v) {
        p.z = q.f(p.x, p.y);
    }
    return v;
}

double patch_at(const CloughTocherPatch& p, double u, double v, const std::array<Point3, 3>& t) {
    const double w = 1.0 - u - v;
    return p.value(w * t[0].x + u * t[1].x + v * t[2].x, w * t[0].y + u * t[1].y + v * t[2].y);
}

TEST(CloughTocher, ReproducesQuadraticsFromExactGradients) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> c(-1.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        const Quadratic q{c(rng) * 100, c(rng), c(rng), c(rng) * 0.1, c(rng) * 0.1, c(rng) * 0.1};
        std::array<Point3, 3> v{Point3{c(rng) * 5, c(rng) * 5, 0},
                                Point3{20 + c(rng) * 5, c(rng) * 5, 0},
                                Point3{c(rng) * 5, 20 + c(rng) * 5, 0}};
        v = with_heights(v, q);
        const CloughTocherPatch patch(v, exact_derivatives(v, q));
        for (int k = 0; k < 40; ++k) {
            const double u = std::abs(c(rng)), w = std::abs(c(rng)) * (1 - u);
            const double x = (1 - u - w) * v[0].x + u * v[1].x + w * v[2].x;
            const double y = (1 - u - w) * v[0].y + u * v[1].y + w * v[2].y;
            ASSERT_NEAR(patch.value(x, y), q.f(x, y), 1e-9 * (1 + std::abs(q.f(x, y))));
        }
    }
}

TEST(CloughTocher, DoesNotReproduceEveryCubic) {
    // The reduced element has quadratic precision only: a cubic term must show (the test of the
    // test: the quadratic check above would also pass a plain linear interpolant otherwise
    // failing here).
    const std::array<Point3, 3> v{Point3{0, 0, 0}, Point3{10, 0, 0}, Point3{0, 10, 0}};
    const auto f = [](double x, double y) { return x * x * y; };
    std::array<Point3, 3> w = v;
    for (Point3& p : w) p.z = f(p.x, p.y);
    CornerDerivatives d{};
    for (std::size_t i = 0; i < 3; ++i) {
        const double gx = 2 * w[i].x * w[i].y, gy = w[i].x * w[i].x;
        for (std::size_t s = 0; s < 2; ++s) {
            const Point3& q = w[(i + 1 + s) % 3];
            d[i][s] = gx * (q.x - w[i].x) + gy * (q.y - w[i].y);
        }
    }
    const CloughTocherPatch patch(w, d);
    EXPECT_GT(std::abs(patch.value(3.0, 3.0) - f(3.0, 3.0)), 1e-3);
}

TEST(CloughTocher, InterpolatesCornersAndIsTheEdgeCubicOnEdges) {
    const std::array<Point3, 3> v{Point3{-750000.5, -1050000.25, 300},
                                  Point3{-749990.0, -1049998.0, 302.5},
                                  Point3{-749996.0, -1049989.0, 299.0}};
    const CornerDerivatives d{{{1.5, -0.5}, {0.25, 2.0}, {-1.0, 0.75}}};
    const CloughTocherPatch patch(v, d);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(patch.value(v[static_cast<std::size_t>(i)].x, v[static_cast<std::size_t>(i)].y),
                    v[static_cast<std::size_t>(i)].z, 1e-9);
        EXPECT_EQ(patch.edge_value(i, (i + 1) % 3, 0.0), v[static_cast<std::size_t>(i)].z);
    }
    // On edge 0 -> 1 the patch is the cubic of the edge's own data (heights and D01, D10).
    for (const double t : {0.1, 0.37, 0.5, 0.81}) {
        const double x = v[0].x + t * (v[1].x - v[0].x), y = v[0].y + t * (v[1].y - v[0].y);
        const double h00 = 2 * t * t * t - 3 * t * t + 1, h10 = t * t * t - 2 * t * t + t;
        const double h01 = -2 * t * t * t + 3 * t * t, h11 = t * t * t - t * t;
        const double hermite = h00 * v[0].z + h10 * d[0][0] + h01 * v[1].z - h11 * d[1][1];
        EXPECT_NEAR(patch.value(x, y), hermite, 1e-8);
        EXPECT_NEAR(patch.edge_value(0, 1, t), hermite, 1e-9);
        EXPECT_NEAR(patch.edge_value(1, 0, 1 - t), hermite, 1e-9);
    }
    const auto [lo, hi] = patch.bounds();
    for (double u = 0; u <= 1.0; u += 0.05) {
        for (double w = 0; u + w <= 1.0; w += 0.05) {
            const double z = patch_at(patch, u, w, v);
            EXPECT_GE(z, lo - 1e-9);
            EXPECT_LE(z, hi + 1e-9);
        }
    }
}

/// Finite-difference gradient of the patch at barycentric (u, v).
std::array<double, 2> fd(const CloughTocherPatch& p, double x, double y) {
    const double h = 1e-5;
    return {(p.value(x + h, y) - p.value(x - h, y)) / (2 * h),
            (p.value(x, y + h) - p.value(x, y - h)) / (2 * h)};
}

TEST(CloughTocher, IsC1AcrossItsInnerEdges) {
    const std::array<Point3, 3> v{Point3{0, 0, 10}, Point3{12, 1, 14}, Point3{3, 9, 7}};
    const CornerDerivatives d{{{2.0, -1.5}, {0.5, 3.0}, {-2.0, 1.0}}};
    const CloughTocherPatch patch(v, d);
    const double cx = (v[0].x + v[1].x + v[2].x) / 3, cy = (v[0].y + v[1].y + v[2].y) / 3;
    for (std::size_t i = 0; i < 3; ++i) {
        for (const double t : {0.2, 0.5, 0.8}) {
            // a point on the inner edge v_i -> centroid, and the edge's normal
            const double x = v[i].x + t * (cx - v[i].x), y = v[i].y + t * (cy - v[i].y);
            double nx = -(cy - v[i].y), ny = cx - v[i].x;
            const double len = std::hypot(nx, ny);
            nx *= 1e-3 / len;
            ny *= 1e-3 / len;
            const auto g1 = fd(patch, x + nx, y + ny);
            const auto g2 = fd(patch, x - nx, y - ny);
            // the kink a C0-only join would show is O(1); a C1 join differs by O(h) only
            EXPECT_NEAR(g1[0], g2[0], 5e-3) << i << " " << t;
            EXPECT_NEAR(g1[1], g2[1], 5e-3) << i << " " << t;
        }
    }
}

TEST(CloughTocher, NeighboursSharingEdgeDataJoinC1) {
    // Two triangles sharing edge a-b, the corner derivatives from one gradient per vertex.
    const Point3 a{0, 0, 5}, b{10, 2, 8}, c{4, 9, 6}, e{6, -8, 3};
    const std::array<std::array<double, 2>, 4> grad{
        {{0.3, -0.2}, {-0.1, 0.4}, {0.5, 0.1}, {0.2, 0.2}}};
    const auto derivs = [&](const std::array<Point3, 3>& t, const std::array<int, 3>& id) {
        CornerDerivatives d{};
        for (std::size_t i = 0; i < 3; ++i) {
            for (std::size_t s = 0; s < 2; ++s) {
                const Point3& w = t[(i + 1 + s) % 3];
                const auto& g = grad[static_cast<std::size_t>(id[i])];
                d[i][s] = g[0] * (w.x - t[i].x) + g[1] * (w.y - t[i].y);
            }
        }
        return d;
    };
    const std::array<Point3, 3> t1{a, b, c}, t2{b, a, e};
    const CloughTocherPatch p1(t1, derivs(t1, {0, 1, 2})), p2(t2, derivs(t2, {1, 0, 3}));
    for (const double t : {0.15, 0.5, 0.9}) {
        const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
        EXPECT_NEAR(p1.value(x, y), p2.value(x, y), 1e-9);
        const double nx = -(b.y - a.y) * 1e-4, ny = (b.x - a.x) * 1e-4;  // into t1
        const auto g1 = fd(p1, x + nx, y + ny);
        const auto g2 = fd(p2, x - nx, y - ny);
        EXPECT_NEAR(g1[0], g2[0], 1e-3) << t;
        EXPECT_NEAR(g1[1], g2[1], 1e-3) << t;
    }
}

}  // namespace
