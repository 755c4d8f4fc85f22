// SPDX-License-Identifier: MIT
// The cubic surface against scipy's CloughTocher2DInterpolator (test-only oracle, run through
// /usr/bin/python3; skipped when scipy is not installed: apt-get install python3-scipy).
// The gradient estimates are the same minimum-norm network except for dtm's weight 1/2 on the
// border edges, so dtm's must equal the oracle's direct solve of that weighted network on
// scipy's triangulation (and differ from scipy's own near the hull); the elements differ in their
// cross-boundary condition (dtm keeps the normal derivative linear along each edge), so values
// agree closely but not exactly, and dtm's must be at least as accurate.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

#include "dtm/algo/interpolation.hpp"
#include "dtm/algo/triangulate.hpp"
#include "support/surface_fixtures.hpp"
#include "support/test_support.hpp"

namespace {

std::vector<std::vector<double>> read_csv(const std::filesystem::path& path) {
    std::vector<std::vector<double>> rows;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::stringstream s(line);
        std::string item;
        while (std::getline(s, item, ',')) row.push_back(std::stod(item));
        rows.push_back(row);
    }
    return rows;
}

bool have_scipy() {
    return std::system("/usr/bin/python3 -c 'import scipy.interpolate' >/dev/null 2>&1") == 0;
}

TEST(CloughTocherScipy, SameNetworkWithWeightedBorderAndAtLeastAsAccurate) {
    if (!have_scipy()) {
        GTEST_SKIP() << "scipy not installed (apt-get install python3-scipy)";
    }
    const auto truth = [](double x, double y) {
        return 300.0 + 15.0 * std::sin(x / 17.0) * std::cos(y / 23.0) + 0.02 * x * y / 10.0;
    };
    const dtm::TerrainInput input = dtm::test::sampled_terrain(truth, 1500, 31);
    const dtm::Tin tin = dtm::triangulate(input).tin;
    ASSERT_EQ(tin.vertices.size(), input.points.size());
    dtm::test::ScratchDir dir;
    {
        std::ofstream points(dir / "points.csv");
        points.precision(17);
        for (const auto& p : tin.vertices) points << p.x << ',' << p.y << ',' << p.z << '\n';
    }
    std::vector<std::pair<double, double>> queries;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(1.0, 99.0);
    {
        std::ofstream out(dir / "queries.csv");
        out.precision(17);
        for (int k = 0; k < 5000; ++k) {
            queries.emplace_back(u(rng), u(rng));
            out << queries.back().first << ',' << queries.back().second << '\n';
        }
    }
    const std::filesystem::path script =
        std::filesystem::path(DTM_TEST_DATA_DIR) / ".." / "support" / "scipy_clough_tocher.py";
    const std::string command =
        "/usr/bin/python3 '" + script.string() + "' '" + (dir / "points.csv").string() + "' '" +
        (dir / "queries.csv").string() + "' '" + (dir / "grad.csv").string() + "' '" +
        (dir / "values.csv").string() + "'";
    ASSERT_EQ(std::system(command.c_str()), 0);
    const auto grad = read_csv(dir / "grad.csv");
    const auto values = read_csv(dir / "values.csv");
    ASSERT_EQ(grad.size(), tin.vertices.size());
    ASSERT_EQ(values.size(), queries.size());

    // dtm's network is scipy's with the border edges weighted 1/2 (gradients.cpp): equal to the
    // oracle's direct solve of that system on the same (scipy's) triangulation, and not equal
    // to scipy's own gradients near the hull.
    const dtm::TinGradients mine = dtm::estimate_gradients(tin, {.tolerance = 1e-13});
    double worst_grad = 0.0, off_scipy = 0.0;
    ASSERT_EQ(mine.gradient.size(), tin.vertices.size());  // no breaklines: one sector each
    for (std::size_t s = 0; s < mine.gradient.size(); ++s) {
        const auto& expected = grad[mine.sector_vertex[s]];
        ASSERT_EQ(expected.size(), 4U);
        worst_grad = std::max({worst_grad, std::abs(mine.gradient[s].dx - expected[2]),
                               std::abs(mine.gradient[s].dy - expected[3])});
        off_scipy = std::max({off_scipy, std::abs(mine.gradient[s].dx - expected[0]),
                              std::abs(mine.gradient[s].dy - expected[1])});
    }
    EXPECT_LT(worst_grad, 1e-8);
    EXPECT_GT(off_scipy, 1e-4) << "the border weight has no effect";

    const dtm::TinInterpolant interpolant =
        dtm::TinInterpolant::prepare(tin, dtm::Interpolation::cubic);
    dtm::TinEvaluator eval(tin, interpolant);
    double se_dtm = 0.0, se_scipy = 0.0, se_linear = 0.0, diff = 0.0;
    dtm::TriangleIndex hint = 0;
    for (std::size_t k = 0; k < queries.size(); ++k) {
        const auto [x, y] = queries[k];
        const double z = eval.value_at(x, y, hint), t = truth(x, y);
        se_dtm += (z - t) * (z - t);
        se_scipy += (values[k][0] - t) * (values[k][0] - t);
        se_linear += (values[k][1] - t) * (values[k][1] - t);
        diff = std::max(diff, std::abs(z - values[k][0]));
    }
    const double n = static_cast<double>(queries.size());
    const double rmse_dtm = std::sqrt(se_dtm / n), rmse_scipy = std::sqrt(se_scipy / n);
    EXPECT_LT(diff, 0.1) << "largest difference from scipy (z range about 40)";
    EXPECT_LE(rmse_dtm, rmse_scipy) << "dtm " << rmse_dtm << " scipy " << rmse_scipy;
    EXPECT_LT(rmse_dtm, 0.5 * std::sqrt(se_linear / n));
    std::printf("RMSE: dtm cubic %.5f, scipy CT %.5f, linear %.5f; max |dtm - scipy| %.4f\n",
                rmse_dtm, rmse_scipy, std::sqrt(se_linear / n), diff);
}

}  // namespace
