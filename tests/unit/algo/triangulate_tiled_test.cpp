// SPDX-License-Identifier: MIT
// Parallel tiles: the TIN is identical for every tile and thread count, on the cases that stress
// the seams (points on cut lines, collinear runs, duplicates, breaklines along and across seams,
// boundary and holes cut by seams, more tiles than points). Each case is compared with the
// sequential kernel (one tile, one thread), and checked for validity.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <random>
#include <string>

#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm {
namespace {

struct SeamCase {
    std::string name;
    TerrainInput input;
};

/// A 64 x 64 grid: every median cut (by x, then by y) runs through a row or column of points,
/// which the lexicographic split divides between the two tiles.
TerrainInput grid_on_cut_lines() {
    TerrainInput in;
    in.points = test::tilted_grid(64, 64, 1.0, 0.0, test::sjtsk_e, test::sjtsk_n);
    return in;
}

std::vector<SeamCase> seam_cases() {
    std::vector<SeamCase> cases;
    cases.push_back({"points_on_cut_lines", grid_on_cut_lines()});
    {
        TerrainInput in = grid_on_cut_lines();
        for (int i = 0; i < 200; ++i) {  // a long collinear diagonal run plus duplicates
            in.points.push_back(
                {test::sjtsk_e + 0.25 + i * 0.3, test::sjtsk_n + 0.5 + i * 0.3, 1.0});
            in.points.push_back(in.points[static_cast<std::size_t>(i) * 17]);
        }
        cases.push_back({"collinear_runs_and_duplicates_across_seams", in});
    }
    {
        TerrainInput in = grid_on_cut_lines();
        // Along the first cut (x = 31.5 lies between columns 31 and 32; column 32 is on it).
        in.breaklines.push_back({{{test::sjtsk_e + 32, test::sjtsk_n + 0, 5},
                                  {test::sjtsk_e + 32, test::sjtsk_n + 63, 9}},
                                 false,
                                 ""});
        in.breaklines.push_back({{{test::sjtsk_e + 0.5, test::sjtsk_n + 31.7, 2},
                                  {test::sjtsk_e + 62.5, test::sjtsk_n + 31.7, 2}},
                                 false,
                                 ""});
        // Many tiles, crossing each other near the seams.
        in.breaklines.push_back({{{test::sjtsk_e + 1.3, test::sjtsk_n + 2.1, 3},
                                  {test::sjtsk_e + 61.7, test::sjtsk_n + 60.2, 3},
                                  {test::sjtsk_e + 3.3, test::sjtsk_n + 58.9, 3}},
                                 false,
                                 ""});
        cases.push_back({"breaklines_along_and_across_seams", in});
    }
    {
        TerrainInput in;
        in.points = test::random_points(20000, 21);
        in.boundaries.push_back(
            {{{50, 50, 0}, {950, 80, 0}, {900, 950, 0}, {60, 900, 0}}, true, ""});
        in.holes.push_back(
            {{{480, 300, 0}, {530, 300, 0}, {530, 700, 0}, {480, 700, 0}}, true, ""});
        in.holes.push_back(
            {{{200, 495, 0}, {800, 495, 0}, {800, 505, 0}, {200, 505, 0}}, true, ""});
        cases.push_back({"boundary_and_holes_cut_by_seams", in});
    }
    {
        TerrainInput in;
        in.points = {{0, 0, 0}, {1, 0, 1}, {0, 1, 2}, {1, 1, 3}, {0.5, 0.5, 4}};
        cases.push_back({"more_tiles_than_points", in});
    }
    {
        TerrainInput in;
        std::mt19937_64 rng(5);
        std::normal_distribution<double> g(0.0, 30.0);
        for (int c = 0; c < 20; ++c) {
            const double cx = 50.0 * c;
            for (int i = 0; i < 2000; ++i)
                in.points.push_back({cx + g(rng), 0.3 * cx + g(rng), 1.0});
        }
        cases.push_back({"clustered", in});
    }
    {
        // Thousands of short breaklines on a cocircular grid, some crossing, some sharing
        // endpoints: the parallel rounds must give the sequential result exactly.
        TerrainInput in = grid_on_cut_lines();
        std::mt19937_64 rng(17);
        std::uniform_real_distribution<double> u(0.0, 63.0);
        std::uniform_real_distribution<double> d(-2.0, 2.0);
        for (int k = 0; k < 3000; ++k) {
            const double x = u(rng), y = u(rng);
            in.breaklines.push_back({{{test::sjtsk_e + x, test::sjtsk_n + y, 1.0},
                                      {test::sjtsk_e + std::clamp(x + d(rng), 0.0, 63.0),
                                       test::sjtsk_n + std::clamp(y + d(rng), 0.0, 63.0), 2.0},
                                      {test::sjtsk_e + std::clamp(x + d(rng), 0.0, 63.0),
                                       test::sjtsk_n + std::clamp(y + d(rng), 0.0, 63.0), 3.0}},
                                     false,
                                     ""});
        }
        cases.push_back({"many_short_breaklines_on_a_grid", in});
    }
    return cases;
}

class TiledSeams : public ::testing::TestWithParam<std::size_t> {};

TEST_P(TiledSeams, EveryTileCountGivesTheSequentialTin) {
    const std::size_t case_index = GetParam();
    const SeamCase c = seam_cases()[case_index];
    SCOPED_TRACE(c.name);
    TriangulateOptions sequential;
    sequential.tiles = 1;
    sequential.threads = 1;
    const TriangulateResult reference = triangulate(c.input, sequential);
    ASSERT_TRUE(verify_topology(reference.tin).ok()) << verify_topology(reference.tin).text();
    ASSERT_TRUE(verify_constrained_delaunay(reference.tin).ok());
    const CheckReport constraints = verify_constraints(reference.tin, c.input);
    ASSERT_TRUE(constraints.ok()) << constraints.text();
    for (const std::size_t tiles : {1u, 2u, 7u, 64u}) {
        for (const unsigned threads : {1u, 2u}) {
            TriangulateOptions options;
            options.tiles = tiles;
            options.threads = threads;
            const Tin tin = triangulate(c.input, options).tin;
            const std::string where =
                "tiles " + std::to_string(tiles) + ", threads " + std::to_string(threads);
            ASSERT_EQ(tin.vertices, reference.tin.vertices) << where;
            ASSERT_EQ(tin.triangles.size(), reference.tin.triangles.size()) << where;
            for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
                ASSERT_EQ(tin.triangles[t].v, reference.tin.triangles[t].v)
                    << where << " triangle " << t;
                ASSERT_EQ(tin.triangles[t].n, reference.tin.triangles[t].n)
                    << where << " triangle " << t;
            }
            ASSERT_EQ(tin.constraints, reference.tin.constraints) << where;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, TiledSeams, ::testing::Range<std::size_t>(0, 7));

}  // namespace
}  // namespace dtm

namespace dtm {
namespace {

TEST(TiledProgress, ReportsFromTheParallelPhaseAndCancelsCleanly) {
    TerrainInput input;
    input.points = test::random_points(300000, 31);
    for (const unsigned threads : {1u, 2u}) {
        std::vector<double> seen;
        std::mutex mutex;
        const Progress watch([&](double fraction, std::string_view) {
            std::lock_guard lock(mutex);
            seen.push_back(fraction);
            return true;
        });
        TriangulateOptions options;
        options.threads = threads;
        (void)triangulate(input, options, watch);
        ASSERT_GE(seen.size(), 3u) << "threads " << threads;
        EXPECT_DOUBLE_EQ(seen.back(), 1.0);

        std::atomic<int> calls{0};
        const Progress stop([&](double, std::string_view) { return ++calls < 2; });
        EXPECT_THROW((void)triangulate(input, options, stop), Cancelled) << "threads " << threads;
    }
}

}  // namespace
}  // namespace dtm
