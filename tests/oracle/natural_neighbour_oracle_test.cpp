// SPDX-License-Identifier: MIT
// dtm's natural-neighbour (Sibson) interpolation against CGAL's natural_neighbor_coordinates_2
// (test-only oracle) on the same points: the same Delaunay triangulation, so the same values.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/natural_neighbor_coordinates_2.h>
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "dtm/algo/interpolation.hpp"
#include "dtm/algo/triangulate.hpp"

namespace dtm {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Dt = CGAL::Delaunay_triangulation_2<K>;

void compare_with_cgal(double x0, double y0, std::uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    TerrainInput input;
    std::map<std::pair<double, double>, double> heights;
    Dt dt;
    for (int i = 0; i < 800; ++i) {
        const double x = x0 + u(rng), y = y0 + u(rng);
        const double z = 50.0 + 10.0 * std::sin((x - x0) / 13.0) * std::cos((y - y0) / 9.0);
        input.points.push_back({x, y, z});
        heights[{x, y}] = z;
        dt.insert(K::Point_2(x, y));
    }
    const Tin tin = triangulate(input).tin;
    const TinInterpolant interpolant = TinInterpolant::prepare(tin, Interpolation::natural);
    TinEvaluator eval(tin, interpolant);
    std::uniform_real_distribution<double> inner(15.0, 85.0);
    TriangleIndex hint = 0;
    double worst = 0.0;
    for (int k = 0; k < 2000; ++k) {
        const double x = x0 + inner(rng), y = y0 + inner(rng);
        std::vector<std::pair<K::Point_2, K::FT>> coords;
        const auto result =
            CGAL::natural_neighbor_coordinates_2(dt, K::Point_2(x, y), std::back_inserter(coords));
        ASSERT_TRUE(result.third);
        double value = 0.0;
        for (const auto& [p, w] : coords) value += w * heights.at({p.x(), p.y()});
        value /= result.second;
        const double mine = eval.value_at(x, y, hint);
        worst = std::max(worst, std::abs(mine - value));
    }
    EXPECT_LT(worst, 1e-7) << "largest difference from CGAL";
}

TEST(NaturalNeighbourOracle, EqualsCgalInLocalCoordinates) { compare_with_cgal(0.0, 0.0, 1); }

TEST(NaturalNeighbourOracle, EqualsCgalAtSjtskOffsets) {
    compare_with_cgal(-750000.0, -1050000.0, 2);
}

}  // namespace
}  // namespace dtm
