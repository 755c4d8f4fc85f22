// SPDX-License-Identifier: MIT
// Optimality criteria: the worked example of thesis 000 §2.3 (10 triangulations of 6 points, 20
// quality vectors, the max-min and min-max orders with erratum 1 resolved: T5), the quadrilateral
// decisions against an independent law-of-cosines computation, and the local-optimality check.
#include "dtm/algo/criteria.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/geom/predicates.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm {
namespace {

const std::vector<Point3> kHosch{{5, 9, 0},   {2, 5, 0},   {4, 2, 0},
                                 {7, 1.5, 0}, {8.5, 4, 0}, {5, 8, 0}};

/// T1..T10 of the digest (1-based corner numbers).
const std::array<std::array<int, 5>, 10> kHoschTriangulations{{
    {126, 145, 146, 236, 346},
    {123, 136, 145, 146, 346},
    {123, 136, 156, 346, 456},
    {126, 145, 146, 234, 246},
    {126, 156, 236, 346, 456},
    {123, 136, 156, 345, 356},
    {126, 156, 234, 246, 456},
    {126, 156, 234, 245, 256},
    {126, 156, 235, 256, 345},
    {126, 156, 236, 345, 356},
}};

/// The digest's vectors (radians, 2 decimals): max-min ascending, min-max descending.
const std::array<std::array<double, 5>, 10> kMaxMin{{
    {0.04, 0.14, 0.35, 0.46, 0.62},
    {0.02, 0.04, 0.35, 0.46, 0.50},
    {0.02, 0.11, 0.42, 0.46, 0.50},
    {0.04, 0.14, 0.35, 0.37, 0.66},
    {0.11, 0.14, 0.42, 0.46, 0.62},
    {0.02, 0.11, 0.50, 0.58, 0.88},
    {0.11, 0.14, 0.37, 0.42, 0.66},
    {0.11, 0.14, 0.37, 0.46, 0.70},
    {0.11, 0.14, 0.57, 0.58, 0.70},
    {0.11, 0.14, 0.58, 0.62, 0.88},
}};
const std::array<std::array<double, 5>, 10> kMinMax{{
    {2.84, 2.36, 1.99, 1.77, 1.57},
    {2.98, 2.84, 1.99, 1.91, 1.57},
    {2.98, 2.42, 1.91, 1.88, 1.57},
    {2.84, 2.36, 2.32, 1.99, 1.40},
    {2.42, 2.36, 1.88, 1.77, 1.57},
    {2.98, 2.42, 1.95, 1.91, 1.27},
    {2.42, 2.36, 2.32, 1.88, 1.40},
    {2.42, 2.36, 2.32, 1.50, 1.50},
    {2.42, 2.36, 1.95, 1.74, 1.50},
    {2.42, 2.36, 1.95, 1.77, 1.27},
}};

Tin hosch_tin(int k) {
    Tin tin;
    tin.vertices = kHosch;
    for (const int code : kHoschTriangulations[k]) {
        Triangle t;
        t.v = {static_cast<VertexIndex>(code / 100 - 1),
               static_cast<VertexIndex>(code / 10 % 10 - 1),
               static_cast<VertexIndex>(code % 10 - 1)};
        if (geom::orient2d(kHosch[t.v[0]], kHosch[t.v[1]], kHosch[t.v[2]]) < 0)
            std::swap(t.v[1], t.v[2]);
        tin.triangles.push_back(t);
    }
    link_neighbours(tin);
    return tin;
}

double round2(double v) { return std::round(v * 100.0) / 100.0; }

TEST(Criteria, NamesRoundTrip) {
    EXPECT_EQ(all_criteria().size(), 11u);
    for (const Criterion c : all_criteria()) {
        EXPECT_EQ(parse_criterion(criterion_name(c)), c);
    }
    EXPECT_FALSE(parse_criterion("max-min-angle").has_value());
    EXPECT_EQ(criterion_kind(Criterion::maxmin_height), CriterionKind::triangle_max_min);
    EXPECT_TRUE(is_data_dependent(Criterion::normal_jump));
}

TEST(Criteria, HoschVectorsMatchTheThesis) {  // R13
    for (int k = 0; k < 10; ++k) {
        const Tin tin = hosch_tin(k);
        const auto maxmin = quality_vector(tin, Criterion::maxmin_angle);
        const auto minmax = quality_vector(tin, Criterion::minmax_angle);
        ASSERT_EQ(maxmin.size(), 5u);
        for (int i = 0; i < 5; ++i) {
            EXPECT_DOUBLE_EQ(round2(maxmin[i]), kMaxMin[k][i]) << "T" << k + 1 << " max-min " << i;
            EXPECT_DOUBLE_EQ(round2(minmax[i]), kMinMax[k][i]) << "T" << k + 1 << " min-max " << i;
        }
    }
}

TEST(Criteria, HoschOrdersAndOptima) {  // R12, R13, R14
    std::vector<std::vector<double>> maxmin;
    std::vector<std::vector<double>> minmax;
    for (int k = 0; k < 10; ++k) {
        maxmin.push_back(quality_vector(hosch_tin(k), Criterion::maxmin_angle));
        minmax.push_back(quality_vector(hosch_tin(k), Criterion::minmax_angle));
    }
    // Thesis: a(T2) < a(T3) < a(T6) < a(T4) < a(T1) < a(T7) < a(T8) < a(T5) < a(T9) < a(T10).
    const std::array<int, 10> up{2, 3, 6, 4, 1, 7, 8, 5, 9, 10};
    for (int i = 0; i + 1 < 10; ++i) {
        EXPECT_EQ(
            compare_quality(maxmin[up[i + 1] - 1], maxmin[up[i] - 1], Criterion::maxmin_angle), 1)
            << "T" << up[i + 1] << " should beat T" << up[i];
    }
    // Min-max, best first: T5 > T9 > T10 > T8 > T7 > T1 > T4 > T3 > T6 > T2. T5, not T9 (erratum).
    const std::array<int, 10> down{5, 9, 10, 8, 7, 1, 4, 3, 6, 2};
    for (int i = 0; i + 1 < 10; ++i) {
        EXPECT_EQ(
            compare_quality(minmax[down[i] - 1], minmax[down[i + 1] - 1], Criterion::minmax_angle),
            1)
            << "T" << down[i] << " should beat T" << down[i + 1];
    }
    // T10 is the Delaunay triangulation: locally optimal under max-min angle, and the only one.
    for (int k = 0; k < 10; ++k) {
        EXPECT_EQ(count_improvable_edges(hosch_tin(k), Criterion::maxmin_angle) == 0, k == 9) << k;
    }
}

// --- the quadrilateral decision against an independent computation ---------------------------

double law_of_cosines_angle(const Point3& p, const Point3& q, const Point3& r) {  // at p
    const double a = std::hypot(q.x - r.x, q.y - r.y);
    const double b = std::hypot(p.x - r.x, p.y - r.y);
    const double c = std::hypot(p.x - q.x, p.y - q.y);
    return std::acos(std::clamp((b * b + c * c - a * a) / (2 * b * c), -1.0, 1.0));
}

/// The criterion's value of a triangle by textbook formulas (Heron's area, R = abc/4S, r = S/s).
double reference_value(Criterion c, const Point3& p, const Point3& q, const Point3& r) {
    const double a = std::hypot(q.x - r.x, q.y - r.y);
    const double b = std::hypot(p.x - r.x, p.y - r.y);
    const double cc = std::hypot(p.x - q.x, p.y - q.y);
    const double s = (a + b + cc) / 2;
    const double area = std::sqrt(std::max(0.0, s * (s - a) * (s - b) * (s - cc)));
    const std::array<double, 3> angles{law_of_cosines_angle(p, q, r), law_of_cosines_angle(q, r, p),
                                       law_of_cosines_angle(r, p, q)};
    switch (c) {
        case Criterion::maxmin_angle:
            return *std::min_element(angles.begin(), angles.end());
        case Criterion::minmax_angle:
            return *std::max_element(angles.begin(), angles.end());
        case Criterion::maxmin_circumradius:
        case Criterion::minmax_circumradius:
            return a * b * cc / (4 * area);
        case Criterion::maxmin_area:
            return area;
        case Criterion::maxmin_height:
            return 2 * area / std::max({a, b, cc});
        case Criterion::maxmin_inradius:
            return area / s;
        default:
            return 0;
    }
}

TEST(Criteria, QuadDecisionsMatchTextbookFormulas) {  // R10
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    int decided = 0;
    for (int trial = 0; trial < 10000; ++trial) {
        std::array<Point3, 4> q;
        for (Point3& p : q) p = {u(rng), u(rng), 0.0};
        // Keep strictly convex counter-clockwise quadrilaterals only.
        bool convex = true;
        for (int i = 0; i < 4; ++i) {
            convex = convex && geom::orient2d(q[i], q[(i + 1) % 4], q[(i + 2) % 4]) > 0;
        }
        if (!convex) continue;
        for (const Criterion c : all_criteria()) {
            const CriterionKind kind = criterion_kind(c);
            if (kind != CriterionKind::triangle_max_min &&
                kind != CriterionKind::triangle_min_max && kind != CriterionKind::edge_length) {
                continue;
            }
            const int got = compare_quad_diagonals(c, q[0], q[1], q[2], q[3]);
            int want = 0;
            if (kind == CriterionKind::edge_length) {
                const double ac = std::hypot(q[2].x - q[0].x, q[2].y - q[0].y);
                const double bd = std::hypot(q[3].x - q[1].x, q[3].y - q[1].y);
                want = bd < ac ? 1 : -1;
            } else {
                const double ac1 = reference_value(c, q[0], q[1], q[2]);
                const double ac2 = reference_value(c, q[0], q[2], q[3]);
                const double bd1 = reference_value(c, q[0], q[1], q[3]);
                const double bd2 = reference_value(c, q[1], q[2], q[3]);
                const bool maxmin = kind == CriterionKind::triangle_max_min;
                const double ac = maxmin ? std::min(ac1, ac2) : std::max(ac1, ac2);
                const double bd = maxmin ? std::min(bd1, bd2) : std::max(bd1, bd2);
                if (std::abs(ac - bd) < 1e-9 * (std::abs(ac) + std::abs(bd))) continue;  // near tie
                want = (bd > ac) == maxmin ? 1 : -1;
            }
            EXPECT_EQ(got, want) << criterion_name(c) << " trial " << trial;
            ++decided;
        }
    }
    EXPECT_GT(decided, 6000);
}

TEST(Criteria, MaxMinAngleIsTheIncircleTestAndCocircularIsATie) {
    // A square: both diagonals equally good under every symmetric criterion.
    const Point3 a{0, 0, 0}, b{1, 0, 0}, c{1, 1, 0}, d{0, 1, 0};
    EXPECT_EQ(compare_quad_diagonals(Criterion::maxmin_angle, a, b, c, d), 0);
    EXPECT_EQ(compare_quad_diagonals(Criterion::shortest_diagonal, a, b, c, d), 0);
    // A kite long along x: the short diagonal bd is the Delaunay one.
    const Point3 k0{0, 0, 0}, k1{5, -1, 0}, k2{10, 0, 0}, k3{5, 1, 0};
    EXPECT_EQ(compare_quad_diagonals(Criterion::maxmin_angle, k0, k1, k2, k3), 1);
    EXPECT_EQ(compare_quad_diagonals(Criterion::shortest_diagonal, k0, k1, k2, k3), 1);
    EXPECT_EQ(compare_quad_diagonals(Criterion::maxmin_angle, k1, k2, k3, k0), -1);
}

TEST(Criteria, DataDependentCostsAreSymmetricAndZeroOnAPlane) {
    const Point3 a{0, 0, 1}, b{4, 0, 2}, c{2, 3, 5}, d{2, -3, 0};
    for (const Criterion crit : {Criterion::normals_angle, Criterion::normal_jump}) {
        EXPECT_DOUBLE_EQ(edge_cost(crit, a, b, c, d), edge_cost(crit, b, a, d, c));
        EXPECT_GT(edge_cost(crit, a, b, c, d), 0.0);
        auto plane = [](double x, double y) { return Point3{x, y, 3 + 0.5 * x - 0.25 * y}; };
        EXPECT_NEAR(edge_cost(crit, plane(0, 0), plane(4, 0), plane(2, 3), plane(2, -3)), 0.0,
                    1e-12);
    }
    // A roof ridge along x (z = -|y|): normals 2 * atan(1) apart, slope jump 2.
    const Point3 r0{0, 0, 0}, r1{4, 0, 0}, r2{2, 1, -1}, r3{2, -1, -1};
    EXPECT_NEAR(edge_cost(Criterion::normals_angle, r0, r1, r2, r3), std::numbers::pi / 2, 1e-12);
    EXPECT_NEAR(edge_cost(Criterion::normal_jump, r0, r1, r2, r3), 2.0, 1e-12);
}

TEST(Criteria, DelaunayTinIsLocallyMaxMinOptimal) {  // R11
    TerrainInput input;
    input.points = test::random_points(500, 3);
    const Tin tin = triangulate(input).tin;
    EXPECT_EQ(count_improvable_edges(tin, Criterion::maxmin_angle), 0u);
    EXPECT_EQ(count_improvable_edges(tin, Criterion::delaunay), 0u);
    // The Delaunay TIN is rarely min-max optimal (Nielson: ~10 % of triangles differ).
    EXPECT_GT(count_improvable_edges(tin, Criterion::minmax_angle), 0u);
}

}  // namespace
}  // namespace dtm
