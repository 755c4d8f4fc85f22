// SPDX-License-Identifier: MIT
// Rasterising the cubic and natural-neighbour surfaces: the values of the point evaluator at
// every cell centre, the same NoData footprint as the linear DEM, vertices exact, results
// independent of threads and bands.
#include <gtest/gtest.h>

#include "dtm/algo/interpolation.hpp"
#include "dtm/algo/rasterize.hpp"
#include "dtm/algo/triangulate.hpp"
#include "support/surface_fixtures.hpp"

namespace {

using dtm::Interpolation;

dtm::Tin survey_with_breakline_and_hole() {
    const auto f = [](double x, double y) {
        return 300.0 + 4.0 * std::sin(x / 11.0) + 2.0 * std::abs(y - 40.0) * 0.2;
    };
    dtm::TerrainInput input = dtm::test::sampled_terrain(f, 900, 14, -750000.0, -1050000.0, 80.0);
    dtm::Polyline brk;
    for (double x = 5; x <= 75; x += 7)
        brk.points.push_back({-750000.0 + x, -1050000.0 + 40.0, f(x, 40)});
    input.breaklines.push_back(brk);
    dtm::Polyline hole;
    for (const auto& [x, y] : {std::pair{50.0, 50.0}, {65.0, 52.0}, {60.0, 66.0}, {52.0, 62.0}}) {
        hole.points.push_back({-750000.0 + x, -1050000.0 + y, 0.0});
    }
    hole.closed = true;
    input.holes.push_back(hole);
    return dtm::triangulate(input).tin;
}

class RasterizeSurface : public ::testing::TestWithParam<Interpolation> {};

TEST_P(RasterizeSurface, EqualsThePointEvaluatorWithTheLinearFootprint) {
    const dtm::Tin tin = survey_with_breakline_and_hole();
    const dtm::GridSpec spec = dtm::snapped_grid_spec(dtm::tin_bounds(tin), 0.9);
    const dtm::Grid linear = dtm::rasterize(tin, spec, {.nodata = -1.0F});
    const dtm::Grid grid =
        dtm::rasterize(tin, spec, {.nodata = -1.0F, .interpolation = GetParam()});
    const dtm::TinInterpolant interpolant = dtm::TinInterpolant::prepare(tin, GetParam());
    dtm::TinEvaluator eval(tin, interpolant);
    std::size_t inside = 0;
    dtm::TriangleIndex hint = 0;
    for (std::size_t r = 0; r < spec.rows; ++r) {
        for (std::size_t c = 0; c < spec.cols; ++c) {
            ASSERT_EQ(grid.at(r, c) == -1.0F, linear.at(r, c) == -1.0F) << r << "," << c;
            if (grid.at(r, c) == -1.0F) continue;
            ++inside;
            const double z = eval.value_at(spec.center_x(c), spec.center_y(r), hint);
            ASSERT_NEAR(grid.at(r, c), z, 1e-4) << r << "," << c;
        }
    }
    EXPECT_GT(inside, 5000U);
}

TEST_P(RasterizeSurface, CentresOnVerticesGetTheVertexHeight) {
    // Vertices on a 2 m lattice sampled by 1 m cells: every vertex is a cell centre.
    dtm::TerrainInput input;
    for (int j = 0; j < 12; ++j) {
        for (int i = 0; i < 12; ++i) {
            const double x = 0.5 + 2 * i + (j % 3 == 1 && i % 2 == 0 ? 1 : 0), y = 0.5 + 2 * j;
            input.points.push_back({x, y, 100 + std::sin(x) * 3 + y * 0.1});
        }
    }
    const dtm::Tin tin = dtm::triangulate(input).tin;
    const dtm::GridSpec spec{.xmin = 0.0, .ymax = 24.0, .cell = 1.0, .cols = 24, .rows = 24};
    const dtm::Grid grid = dtm::rasterize(tin, spec, {.interpolation = GetParam()});
    for (const dtm::Point3& v : tin.vertices) {
        const auto c = static_cast<std::size_t>(v.x - 0.5);
        const auto r = static_cast<std::size_t>(23.5 - v.y);
        EXPECT_EQ(grid.at(r, c), static_cast<float>(v.z));
    }
}

TEST_P(RasterizeSurface, ThreadsBandsAndAPreparedInterpolantGiveTheSameRaster) {
    const dtm::Tin tin = survey_with_breakline_and_hole();
    const dtm::GridSpec spec = dtm::snapped_grid_spec(dtm::tin_bounds(tin), 0.4);
    const dtm::Grid a =
        dtm::rasterize(tin, spec, {.band_rows = 1, .threads = 1, .interpolation = GetParam()});
    const dtm::Grid b =
        dtm::rasterize(tin, spec, {.band_rows = 9, .threads = 2, .interpolation = GetParam()});
    EXPECT_EQ(a.values, b.values);
    const dtm::TinInterpolant interpolant = dtm::TinInterpolant::prepare(tin, GetParam());
    dtm::Grid c{spec, -9999.0F, std::vector<float>(spec.cell_count(), -9999.0F)};
    struct Into final : dtm::GridSink {
        dtm::Grid& g;
        explicit Into(dtm::Grid& grid) : g(grid) {}
        void write_rows(std::size_t first, std::size_t, std::span<const float> v) override {
            std::copy(v.begin(), v.end(),
                      g.values.begin() + static_cast<std::ptrdiff_t>(first * g.spec.cols));
        }
    } sink(c);
    dtm::rasterize(tin, interpolant, spec, {}, sink);
    EXPECT_EQ(a.values, c.values);
}

INSTANTIATE_TEST_SUITE_P(Methods,
                         RasterizeSurface,
                         ::testing::Values(Interpolation::cubic, Interpolation::natural),
                         [](const auto& param_info) {
                             return std::string(dtm::interpolation_name(param_info.param));
                         });

}  // namespace
