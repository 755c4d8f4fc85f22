// SPDX-License-Identifier: MIT
// Gradient estimation (minimum-norm network, border edges weighted 1/2): exact on linear data,
// equal to a direct solve of the weighted network, close on quadratics, split
// at hard breaklines, independent of the thread count.
#include "dtm/algo/gradients.hpp"

#include <gtest/gtest.h>

#include "dtm/algo/triangulate.hpp"
#include "support/surface_fixtures.hpp"

namespace {

using dtm::Gradient;
using dtm::TinGradients;

TEST(Gradients, ExactForLinearSurfacesAtSjtskOffsets) {
    const auto f = [](double x, double y) { return 300.0 + 0.03 * x - 0.08 * y; };
    const auto input = dtm::test::sampled_terrain(f, 400, 11, -750000.0, -1050000.0);
    const dtm::Tin tin = dtm::triangulate(input).tin;
    const TinGradients g = dtm::estimate_gradients(tin);
    ASSERT_EQ(g.gradient.size(), tin.vertices.size());
    for (const Gradient& v : g.gradient) {
        EXPECT_NEAR(v.dx, 0.03, 1e-9);
        EXPECT_NEAR(v.dy, -0.08, 1e-9);
    }
    EXPECT_LT(g.iterations, 200U);
}

TEST(Gradients, CloseToTheTrueGradientOfAQuadratic) {
    const auto f = [](double x, double y) { return 0.002 * x * x - 0.001 * x * y + 0.003 * y * y; };
    const auto input = dtm::test::sampled_terrain(f, 3000, 5);
    const dtm::Tin tin = dtm::triangulate(input).tin;
    const TinGradients g = dtm::estimate_gradients(tin);
    double worst = 0.0, sum = 0.0;
    std::size_t n = 0;
    ASSERT_EQ(g.sector_vertex.size(), g.gradient.size());
    for (std::size_t s = 0; s < g.gradient.size(); ++s) {
        const auto& p = tin.vertices[g.sector_vertex[s]];
        if (p.x < 10 || p.x > 90 || p.y < 10 || p.y > 90) {
            continue;  // the network is one-sided near the hull
        }
        const double ex = 0.004 * p.x - 0.001 * p.y, ey = -0.001 * p.x + 0.006 * p.y;
        const double err = std::hypot(g.gradient[s].dx - ex, g.gradient[s].dy - ey);
        worst = std::max(worst, err);
        sum += err;
        ++n;
    }
    // gradients are about 0.5; the network's error is second order in the spacing (~2)
    EXPECT_LT(sum / static_cast<double>(n), 2e-3);
    EXPECT_LT(worst, 2e-2);
}

TEST(Gradients, ThreadCountDoesNotChangeTheResult) {
    const auto f = [](double x, double y) { return std::sin(x / 9) * std::cos(y / 7) * 10; };
    const dtm::Tin tin = dtm::triangulate(dtm::test::sampled_terrain(f, 5000, 2)).tin;
    const TinGradients a = dtm::estimate_gradients(tin, {.threads = 1});
    const TinGradients b = dtm::estimate_gradients(tin, {.threads = 2});
    ASSERT_EQ(a.gradient.size(), b.gradient.size());
    for (std::size_t i = 0; i < a.gradient.size(); ++i) {
        ASSERT_EQ(a.gradient[i].dx, b.gradient[i].dx);
        ASSERT_EQ(a.gradient[i].dy, b.gradient[i].dy);
    }
}

TEST(Gradients, HardBreaklineSplitsTheStarIntoTwoSidesWithTheirOwnGradients) {
    // A V-shaped valley z = |y - 50| with its floor as a hard breakline: each side is a plane,
    // so each side's sector gradient is that plane's gradient exactly.
    const auto f = [](double x, double y) { return 0.0 * x + std::abs(y - 50.0); };
    dtm::TerrainInput input = dtm::test::sampled_terrain(f, 600, 9);
    dtm::Polyline floor;
    for (double x = 0; x <= 100.0; x += 12.5) floor.points.push_back({x, 50.0, 0.0});
    input.breaklines.push_back(floor);
    const dtm::Tin tin = dtm::triangulate(input).tin;
    const TinGradients g = dtm::estimate_gradients(tin);
    EXPECT_GT(g.gradient.size(), tin.vertices.size());  // floor vertices have two sectors
    std::size_t floor_corners = 0;
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        double cy = 0.0;
        for (const auto v : tin.triangles[t].v) cy += tin.vertices[v].y / 3.0;
        for (std::size_t i = 0; i < 3; ++i) {
            const Gradient& gr = g.gradient[g.corner_sector[t][i]];
            EXPECT_NEAR(gr.dx, 0.0, 1e-9);
            EXPECT_NEAR(gr.dy, cy > 50.0 ? 1.0 : -1.0, 1e-9);
            floor_corners += tin.vertices[tin.triangles[t].v[i]].y == 50.0 ? 1 : 0;
        }
    }
    EXPECT_GT(floor_corners, 0U);
}

TEST(Gradients, EqualTheNetworkWithBorderEdgesWeightedHalfSolvedDirectly) {
    // The minimum of sum_e w_e E_e over the gradients (E_e: the Hermite curve's energy of
    // gradients.cpp, w_e = 1/2 on a border edge, 1 inside), solved by dense elimination.
    const auto f = [](double x, double y) { return std::sin(x / 9) * std::cos(y / 7) * 10; };
    const dtm::Tin tin = dtm::triangulate(dtm::test::sampled_terrain(f, 40, 3)).tin;
    const std::size_t n = tin.vertices.size(), m = 2 * n;
    std::vector<double> a(m * (m + 1), 0.0);  // rows of [matrix | right-hand side]
    const auto at = [&](std::size_t r, std::size_t c) -> double& { return a[r * (m + 1) + c]; };
    std::size_t border = 0;
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        const auto& tri = tin.triangles[t];
        for (std::size_t k = 0; k < 3; ++k) {  // the edge opposite corner k
            const auto other = tri.n[k];
            if (other != dtm::no_triangle && other < t) continue;  // once per edge
            const double w = other == dtm::no_triangle ? 0.5 : 1.0;
            border += other == dtm::no_triangle ? 1 : 0;
            const std::size_t p = tri.v[(k + 1) % 3], q = tri.v[(k + 2) % 3];
            const auto &vp = tin.vertices[p], &vq = tin.vertices[q];
            const double dx = vq.x - vp.x, dy = vq.y - vp.y, h = vq.z - vp.z;
            const double l2 = dx * dx + dy * dy, c = w / (l2 * std::sqrt(l2));
            const double d[2] = {dx, dy};
            for (std::size_t i = 0; i < 2; ++i) {
                for (std::size_t j = 0; j < 2; ++j) {
                    at(2 * p + i, 2 * p + j) += 8 * c * d[i] * d[j];
                    at(2 * q + i, 2 * q + j) += 8 * c * d[i] * d[j];
                    at(2 * p + i, 2 * q + j) += 4 * c * d[i] * d[j];
                    at(2 * q + i, 2 * p + j) += 4 * c * d[i] * d[j];
                }
                at(2 * p + i, m) += 12 * c * h * d[i];
                at(2 * q + i, m) += 12 * c * h * d[i];
            }
        }
    }
    ASSERT_GT(border, 3U);
    for (std::size_t col = 0; col < m; ++col) {  // Gaussian elimination, partial pivoting
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < m; ++r) {
            if (std::abs(at(r, col)) > std::abs(at(pivot, col))) pivot = r;
        }
        for (std::size_t c = 0; c <= m; ++c) std::swap(at(col, c), at(pivot, c));
        for (std::size_t r = 0; r < m; ++r) {
            if (r == col) continue;
            const double factor = at(r, col) / at(col, col);
            for (std::size_t c = col; c <= m; ++c) at(r, c) -= factor * at(col, c);
        }
    }
    const TinGradients g = dtm::estimate_gradients(tin, {.tolerance = 1e-13});
    ASSERT_EQ(g.gradient.size(), n);
    double worst = 0.0;
    for (std::size_t s = 0; s < n; ++s) {
        const std::size_t v = g.sector_vertex[s];
        worst =
            std::max({worst, std::abs(g.gradient[s].dx - at(2 * v, m) / at(2 * v, 2 * v)),
                      std::abs(g.gradient[s].dy - at(2 * v + 1, m) / at(2 * v + 1, 2 * v + 1))});
    }
    EXPECT_LT(worst, 1e-8);
}

}  // namespace
