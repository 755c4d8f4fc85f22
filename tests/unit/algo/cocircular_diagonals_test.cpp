// SPDX-License-Identifier: MIT
// Data-dependent diagonals in the cocircular ties of a lattice: the cubic surface is built on a
// TIN that is still Delaunay, has the same vertices and constraints, and takes the diagonal along
// a valley where the triangulator's tie-break took the other one; every vertex is interpolated
// exactly.
#include "dtm/algo/cocircular_diagonals.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dtm/algo/interpolation.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/geom/predicates.hpp"
#include "support/surface_fixtures.hpp"

namespace {

/// A valley along x - y = 0 on the 9 x 9 lattice of integer points: constant height along the
/// diagonals x - y = const, so the right diagonal of every lattice square is the one through
/// (i, j) and (i + 1, j + 1).
dtm::Tin valley_lattice() {
    dtm::TerrainInput input;
    for (int j = 0; j < 9; ++j) {
        for (int i = 0; i < 9; ++i) {
            const double d = i - j;
            input.points.push_back({100.0 + i, 200.0 + j, 50.0 + 4.0 * std::tanh(0.4 * d * d)});
        }
    }
    return dtm::triangulate(input).tin;
}

/// Counts the lattice squares cut by the diagonal along the valley and by the other one.
std::pair<int, int> diagonals(const dtm::Tin& tin) {
    int along = 0, across = 0;
    for (const dtm::Triangle& t : tin.triangles) {
        for (std::size_t e = 0; e < 3; ++e) {
            const dtm::Point3& a = tin.vertices[t.v[(e + 1) % 3]];
            const dtm::Point3& b = tin.vertices[t.v[(e + 2) % 3]];
            const double dx = b.x - a.x, dy = b.y - a.y;
            if (std::abs(dx) == 1.0 && std::abs(dy) == 1.0) {
                ++(dx == dy ? along : across);
            }
        }
    }
    return {along / 2, across / 2};  // each interior edge is seen from both triangles
}

TEST(CocircularDiagonals, CubicSurfaceTakesTheValleyDiagonals) {
    const dtm::Tin tin = valley_lattice();
    ASSERT_EQ(tin.triangles.size(), 128U);
    const auto [along0, across0] = diagonals(tin);
    ASSERT_GT(across0, 0) << "the tie-break alone already follows the valley: no test";

    const dtm::TinInterpolant cubic = dtm::TinInterpolant::prepare(tin, dtm::Interpolation::cubic);
    const dtm::Tin& surface = cubic.surface(tin);
    ASSERT_NE(&surface, &tin);
    const auto [along, across] = diagonals(surface);
    EXPECT_EQ(along, 64);
    EXPECT_EQ(across, 0);

    // Still a Delaunay TIN of the same vertices: every interior edge passes incircle <= 0.
    EXPECT_EQ(surface.vertices.size(), tin.vertices.size());
    EXPECT_EQ(surface.triangles.size(), tin.triangles.size());
    for (const dtm::Triangle& t : surface.triangles) {
        for (std::size_t e = 0; e < 3; ++e) {
            if (t.n[e] == dtm::no_triangle) continue;
            const dtm::Triangle& u = surface.triangles[t.n[e]];
            std::size_t back = 0;
            while (u.n[back] != static_cast<dtm::TriangleIndex>(&t - surface.triangles.data())) {
                ++back;
            }
            EXPECT_LE(dtm::geom::incircle(surface.vertices[t.v[0]], surface.vertices[t.v[1]],
                                          surface.vertices[t.v[2]], surface.vertices[u.v[back]]),
                      0);
        }
    }

    // Every vertex exactly, evaluated in every surface triangle that has it; and the cubic is
    // nearer the truth at the square centres than the linear surface of the given TIN.
    dtm::TinEvaluator eval(tin, cubic);
    ASSERT_EQ(&eval.tin(), &surface);
    for (dtm::TriangleIndex t = 0; t < surface.triangles.size(); ++t) {
        for (const dtm::VertexIndex v : surface.triangles[t].v) {
            const dtm::Point3& p = surface.vertices[v];
            ASSERT_EQ(eval.value(t, p.x, p.y), p.z);
        }
    }
    const dtm::TinInterpolant linear;
    dtm::TinEvaluator flat(tin, linear);
    double cubic_error = 0.0, linear_error = 0.0;
    dtm::TriangleIndex h1 = 0, h2 = 0;
    for (int j = 1; j < 7; ++j) {
        for (int i = 1; i < 7; ++i) {
            const double x = 100.5 + i, y = 200.5 + j, d = i - j;
            const double truth = 50.0 + 4.0 * std::tanh(0.4 * d * d);
            cubic_error += std::abs(eval.value_at(x, y, h1) - truth);
            linear_error += std::abs(flat.value_at(x, y, h2) - truth);
        }
    }
    EXPECT_LT(cubic_error, 0.5 * linear_error);
}

TEST(CocircularDiagonals, RandomPointsKeepTheirTin) {
    const auto f = [](double x, double y) { return 0.1 * x * y; };
    const dtm::Tin tin = dtm::triangulate(dtm::test::sampled_terrain(f, 200, 3)).tin;
    EXPECT_FALSE(dtm::has_improvable_cocircular_edge(tin));
    const dtm::TinInterpolant cubic = dtm::TinInterpolant::prepare(tin, dtm::Interpolation::cubic);
    EXPECT_EQ(&cubic.surface(tin), &tin);
}

}  // namespace
