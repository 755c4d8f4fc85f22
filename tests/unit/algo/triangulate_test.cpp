// SPDX-License-Identifier: MIT
// The constrained Delaunay triangulation: exact Delaunay property, breaklines, crossings,
// duplicates, degeneracies, domain, determinism.
#include "dtm/algo/triangulate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm {
namespace {

using test::random_points;
using test::triangle_set;

void expect_valid(const TriangulateResult& r, const TerrainInput& input) {
    const CheckReport topology = verify_topology(r.tin);
    EXPECT_TRUE(topology.ok()) << topology.text();
    const CheckReport delaunay = verify_constrained_delaunay(r.tin);
    EXPECT_TRUE(delaunay.ok()) << delaunay.text();
    const CheckReport constraints = verify_constraints(r.tin, input);
    EXPECT_TRUE(constraints.ok()) << constraints.text();
}

/// Number of triangles of a full triangulation of n points with h on the hull: 2n - 2 - h.
std::size_t hull_vertex_count(const Tin& tin) {
    std::set<VertexIndex> hull;
    for (const Triangle& t : tin.triangles) {
        for (int i = 0; i < 3; ++i) {
            if (t.n[i] == no_triangle) {
                hull.insert(t.v[(i + 1) % 3]);
                hull.insert(t.v[(i + 2) % 3]);
            }
        }
    }
    return hull.size();
}

TEST(Triangulate, RandomPointsGiveAFullExactDelaunayTriangulation) {
    TerrainInput input;
    input.points = random_points(20000, 1, test::sjtsk_e, test::sjtsk_n);
    const TriangulateResult r = triangulate(input);
    expect_valid(r, input);
    ASSERT_EQ(r.tin.vertices.size(), input.points.size());
    EXPECT_EQ(r.tin.triangles.size(), 2 * r.tin.vertices.size() - 2 - hull_vertex_count(r.tin));
    EXPECT_EQ(r.stats.duplicates_merged, 0u);
}

TEST(Triangulate, OutputVerticesAreBitIdenticalToTheInput) {
    TerrainInput input;
    input.points = random_points(1000, 2, test::sjtsk_e, test::sjtsk_n);
    const TriangulateResult r = triangulate(input);
    for (std::size_t i = 0; i < input.points.size(); ++i) {
        ASSERT_EQ(r.tin.vertices[r.input_to_vertex[i]], input.points[i]) << "point " << i;
    }
}

TEST(Triangulate, TiltedGridsAtSjtskMagnitudeAreValidAndExactlyDelaunay) {
    for (const double angle : {0.0, 0.3, 0.7853981633974483, 1.1}) {
        TerrainInput input;
        input.points = test::tilted_grid(60, 45, 0.001, angle, test::sjtsk_e, test::sjtsk_n);
        const TriangulateResult r = triangulate(input);
        SCOPED_TRACE("angle " + std::to_string(angle));
        expect_valid(r, input);
        EXPECT_EQ(r.tin.triangles.size(), 2 * r.tin.vertices.size() - 2 - hull_vertex_count(r.tin));
    }
}

TEST(Triangulate, SameTrianglesWhateverTheInputOrder) {
    TerrainInput a;
    a.points = test::tilted_grid(30, 30, 1.0, 0.0, 0.0, 0.0);  // cocircular: many valid answers
    TerrainInput b = a;
    std::mt19937 rng(7);
    std::shuffle(b.points.begin(), b.points.end(), rng);
    EXPECT_EQ(triangle_set(triangulate(a).tin), triangle_set(triangulate(b).tin));
}

TEST(Triangulate, SameTrianglesForEveryTileAndThreadCount) {
    TerrainInput input;
    input.points = random_points(30000, 3);
    const auto grid = test::tilted_grid(40, 40, 7.0, 0.0, 100.0, 100.0);
    input.points.insert(input.points.end(), grid.begin(), grid.end());
    input.breaklines.push_back({{{10, 10, 5}, {990, 950, 7}, {20, 980, 9}}, false, "b1"});
    TriangulateOptions sequential;
    sequential.tiles = 1;
    sequential.threads = 1;
    const Tin reference = triangulate(input, sequential).tin;
    for (const std::size_t tiles : {2u, 7u, 64u}) {
        for (const unsigned threads : {1u, 2u}) {
            TriangulateOptions o;
            o.tiles = tiles;
            o.threads = threads;
            const Tin tin = triangulate(input, o).tin;
            EXPECT_EQ(tin.triangles.size(), reference.triangles.size());
            EXPECT_TRUE(std::equal(
                tin.triangles.begin(), tin.triangles.end(), reference.triangles.begin(),
                reference.triangles.end(),
                [](const Triangle& x, const Triangle& y) { return x.v == y.v && x.n == y.n; }))
                << "tiles " << tiles << " threads " << threads;
        }
    }
}

TEST(Triangulate, DuplicatesAreMergedWithTheChosenHeightRuleAndListed) {
    TerrainInput input;
    input.points = {{0, 0, 1}, {10, 0, 2}, {0, 10, 3}, {10, 0, 6}, {10, 0, 4}, {10, 10, 0}};
    for (const auto& [rule, z] :
         std::vector<std::pair<DuplicateRule, double>>{{DuplicateRule::first, 2.0},
                                                       {DuplicateRule::mean, 4.0},
                                                       {DuplicateRule::min, 2.0},
                                                       {DuplicateRule::max, 6.0}}) {
        TriangulateOptions o;
        o.duplicates = rule;
        const TriangulateResult r = triangulate(input, o);
        EXPECT_EQ(r.stats.duplicates_merged, 2u);
        ASSERT_EQ(r.merges.size(), 2u);
        EXPECT_EQ(r.merges[0].kept_input, 1u);
        EXPECT_EQ(r.merges[0].merged_input, 3u);
        EXPECT_EQ(r.tin.vertices.size(), 4u);
        EXPECT_DOUBLE_EQ(r.tin.vertices[r.input_to_vertex[4]].z, z);
    }
}

TEST(Triangulate, ManyDuplicatesMergeIntoTheirFirstOccurrenceWithOneOrTwoThreads) {
    // Large enough for the parallel hash table; every 7th point repeats an earlier one (and
    // some repeat a repeat), in shuffled order, with -0.0 standing for 0.0.
    TerrainInput input;
    input.points = random_points(150000, 11);
    input.points.push_back({0.0, 0.0, 1.0});
    std::mt19937 rng(5);
    const std::size_t originals = input.points.size();
    for (std::size_t i = 0; i < originals / 7; ++i) {
        Point3 p = input.points[rng() % input.points.size()];
        p.z += 1.0;
        input.points.push_back(p);
    }
    input.points.push_back({-0.0, 0.0, 2.0});
    std::map<std::pair<double, double>, std::size_t> first;
    for (std::size_t i = 0; i < input.points.size(); ++i) {
        const double x = input.points[i].x == 0.0 ? 0.0 : input.points[i].x;
        first.emplace(std::make_pair(x, input.points[i].y), i);
    }
    for (const unsigned threads : {1u, 2u}) {
        TriangulateOptions o;
        o.threads = threads;
        const TriangulateResult r = triangulate(input, o);
        EXPECT_EQ(r.tin.vertices.size(), first.size()) << threads << " threads";
        ASSERT_EQ(r.stats.duplicates_merged, input.points.size() - first.size());
        for (const DuplicateMerge& m : r.merges) {
            const Point3& p = input.points[m.merged_input];
            const double x = p.x == 0.0 ? 0.0 : p.x;
            ASSERT_EQ(m.kept_input, first.at({x, p.y})) << "merged input " << m.merged_input;
            ASSERT_EQ(r.input_to_vertex[m.merged_input], r.input_to_vertex[m.kept_input]);
        }
    }
}

TEST(Triangulate, SnapMergesPointsCloserThanTheDistance) {
    TerrainInput input;
    input.points = {{0, 0, 1}, {10, 0, 2}, {0, 10, 3}, {10.004, 0.003, 8}, {10, 10, 0}, {5, 5, 1}};
    TriangulateOptions o;
    o.snap_distance = 0.01;
    const TriangulateResult r = triangulate(input, o);
    EXPECT_EQ(r.stats.duplicates_merged, 1u);
    EXPECT_EQ(r.input_to_vertex[3], r.input_to_vertex[1]);
    EXPECT_EQ(r.tin.vertices.size(), 5u);
}

TEST(Triangulate, FewerThanThreeDistinctPointsIsAnInputError) {
    TerrainInput input;
    input.points = {{0, 0, 1}, {1, 1, 1}, {1, 1, 2}};
    EXPECT_THROW((void)triangulate(input), InputError);
}

TEST(Triangulate, AllCollinearPointsIsAnInputError) {
    TerrainInput input;
    for (int i = 0; i < 100; ++i)
        input.points.push_back({test::sjtsk_e + i * 0.1, test::sjtsk_n + i * 0.2, 1});
    try {
        (void)triangulate(input);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos) << e.what();
    }
}

TEST(Triangulate, BreaklinesBecomeConstrainedEdgesAndTheRestStaysDelaunay) {
    TerrainInput input;
    input.points = random_points(5000, 4);
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(50.0, 950.0);
    for (int k = 0; k < 40; ++k) {  // horizontal zig-zags in separate bands never cross
        Polyline line;
        const double y = 20.0 + 24.0 * k;
        for (double x = 5.0; x < 1000.0; x += 37.0)
            line.points.push_back({x, y + 10.0 * std::sin(x), 100});
        input.breaklines.push_back(line);
    }
    const TriangulateResult r = triangulate(input);
    expect_valid(r, input);
    EXPECT_EQ(r.stats.intersections, 0u);
    EXPECT_GE(r.tin.constraints.size(), 40u * 26u);  // 26 segments per line, more if split
}

TEST(Triangulate, BreaklineThroughAnExistingVertexIsSplitThere) {
    TerrainInput input;
    input.points = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0},
                    {5, 5, 7}, {2, 8, 0},  {8, 2, 0}};
    input.breaklines.push_back({{{0, 0, 0}, {10, 10, 0}}, false, ""});
    const TriangulateResult r = triangulate(input);
    expect_valid(r, input);
    EXPECT_EQ(r.tin.constraints.size(), 2u);
}

TEST(Triangulate, OverlappingCollinearBreaklinesAreMerged) {
    TerrainInput input;
    input.points = random_points(200, 6);
    input.breaklines.push_back({{{100, 500, 1}, {700, 500, 1}}, false, ""});
    input.breaklines.push_back({{{400, 500, 1}, {900, 500, 1}}, false, ""});
    const TriangulateResult r = triangulate(input);
    expect_valid(r, input);
    EXPECT_EQ(r.stats.intersections, 0u);
    EXPECT_EQ(r.tin.constraints.size(), 3u);  // 100-400, 400-700, 700-900
}

TEST(Triangulate, CrossingBreaklinesAreSplitWithInterpolatedHeightsAndConflictsReported) {
    TerrainInput input;
    input.points = random_points(500, 8);
    input.breaklines.push_back({{{100, 100, 10}, {900, 900, 20}}, false, ""});
    input.breaklines.push_back({{{100, 900, 15}, {900, 100, 15}}, false, ""});  // agrees at 15
    input.breaklines.push_back({{{100, 300, 50}, {900, 300, 50}}, false, ""});  // 50 vs 12.5
    const TriangulateResult r = triangulate(input);
    expect_valid(r, input);
    EXPECT_EQ(r.stats.intersections, 3u);
    ASSERT_EQ(r.stats.conflicts, 2u);  // third line against the two diagonals
    for (const ConstraintConflict& c : r.conflicts) EXPECT_DOUBLE_EQ(c.at.y, 300.0);
    bool found_centre = false;
    for (const Point3& v : r.tin.vertices) {
        if (v.x == 500.0 && v.y == 500.0) {
            found_centre = true;
            EXPECT_DOUBLE_EQ(v.z, 15.0);
        }
    }
    EXPECT_TRUE(found_centre);
}

TEST(Triangulate, ManyRandomCrossingBreaklinesStayValid) {
    TerrainInput input;
    input.points = random_points(3000, 9, test::sjtsk_e, test::sjtsk_n);
    std::mt19937_64 rng(10);
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    for (int k = 0; k < 60; ++k) {
        input.breaklines.push_back({{{test::sjtsk_e + u(rng), test::sjtsk_n + u(rng), 1},
                                     {test::sjtsk_e + u(rng), test::sjtsk_n + u(rng), 2}},
                                    false,
                                    ""});
    }
    const TriangulateResult r = triangulate(input);
    expect_valid(r, input);
    EXPECT_GT(r.stats.intersections, 100u);
}

// Long breaklines through dense points: some pass around a vertex and cross its whole star, so
// an edge of that vertex has both its triangles in the cavity without being crossed (it lies on
// the cavity's boundary twice); the new triangles must be linked across it.
TEST(Triangulate, LongBreaklinesAroundWholeStarsStayValid) {
    for (const std::uint32_t seed : {21u, 22u, 23u}) {
        TerrainInput input;
        input.points = random_points(4000, seed);
        for (int k = 0; k < 20; ++k) {
            const double y = 50.0 + 45.0 * k + 0.37 * static_cast<double>(seed);
            input.breaklines.push_back({{{20, y, 1}, {980, y + 3.0, 2}}, false, ""});
        }
        for (const unsigned threads : {1u, 2u}) {
            TriangulateOptions options;
            options.threads = threads;
            const TriangulateResult r = triangulate(input, options);
            SCOPED_TRACE("seed " + std::to_string(seed) + ", threads " + std::to_string(threads));
            expect_valid(r, input);
        }
    }
}

TEST(Triangulate, BoundaryAndHoleRingsLimitTheSurface) {
    TerrainInput input;
    input.points = random_points(4000, 11);
    input.boundaries.push_back(
        {{{100, 100, 0}, {900, 100, 0}, {900, 900, 0}, {100, 900, 0}}, true, ""});
    input.holes.push_back(
        {{{400, 400, 0}, {600, 400, 0}, {600, 600, 0}, {400, 600, 0}, {400, 400, 0}}, false, ""});
    const TriangulateResult r = triangulate(input);
    expect_valid(r, input);
    EXPECT_NEAR(tin_area(r.tin), 800.0 * 800.0 - 200.0 * 200.0, 1e-6);
}

TEST(Triangulate, HoleSeedRemovesTheEnclosedRegion) {
    TerrainInput input;
    input.points = random_points(2000, 12);
    input.breaklines.push_back(
        {{{300, 300, 0}, {700, 300, 0}, {700, 700, 0}, {300, 700, 0}}, true, ""});
    input.hole_seeds.push_back({500, 500});
    const TriangulateResult r = triangulate(input);
    expect_valid(r, input);
    TerrainInput hull_only;
    hull_only.points = input.points;
    EXPECT_NEAR(tin_area(r.tin), tin_area(triangulate(hull_only).tin) - 400.0 * 400.0, 1e-6);
}

TEST(Triangulate, OpenBoundaryIsAnInputError) {
    TerrainInput input;
    input.points = random_points(100, 13);
    input.boundaries.push_back(
        {{{100, 100, 0}, {900, 100, 0}, {900, 900, 0}}, false, "fence.shp:1"});
    try {
        (void)triangulate(input);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("fence.shp:1"), std::string::npos) << e.what();
    }
}

TEST(Triangulate, MaxEdgeTrimsLongBorderTrianglesOnly) {
    TerrainInput input;
    input.points = test::tilted_grid(20, 20, 1.0, 0.0, 0.0, 0.0);
    input.points.push_back({50.0, 10.0, 0.0});  // far outlier: long skinny hull triangles
    TriangulateOptions o;
    o.max_edge = 3.0;
    const TriangulateResult r = triangulate(input, o);
    expect_valid(r, input);
    EXPECT_NEAR(tin_area(r.tin), 19.0 * 19.0, 1e-9);
    EXPECT_GT(r.stats.removed_triangles, 0u);
}

TEST(Triangulate, SoftBreaklinesTakeTheirHeightFromTheSurface) {
    TerrainInput input;
    input.points = test::tilted_grid(11, 11, 10.0, 0.0, 0.0, 0.0);
    input.soft_breaklines.push_back({{{5, 5, 0}, {95, 45, 0}}, false, ""});
    const TriangulateResult r = triangulate(input);
    expect_valid(r, input);
    for (const Point3& v : r.tin.vertices) {
        EXPECT_NEAR(v.z, test::terrain_z(v.x, v.y), 1e-9);  // the plane is reproduced exactly
    }
}

}  // namespace
}  // namespace dtm
