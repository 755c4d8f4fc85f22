// SPDX-License-Identifier: MIT
// [greedy-naive], [greedy-gilbert], [greedy]: the same edge set (R18, and the fast variant against
// both) on uniform, clustered and collinear-rich inputs and on grids full of equal lengths; fixed
// edges kept (R17); the result a valid triangulation of the hull with 3n - 3 - h edges; the
// segment tree T(4, 15) of the thesis (R19); the greedy triangulation locally shortest-diagonal
// optimal; its length against the Delaunay one.
#include "methods/greedy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "dtm/algo/criteria.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "methods/greedy_gilbert.hpp"
#include "methods/greedy_naive.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm::methods {
namespace {

using EdgeSet = std::set<std::pair<VertexIndex, VertexIndex>>;

EdgeSet edge_set(const Tin& tin) {
    EdgeSet out;
    for (const Triangle& t : tin.triangles) {
        for (int s = 0; s < 3; ++s) {
            const VertexIndex a = t.v[(s + 1) % 3];
            const VertexIndex b = t.v[(s + 2) % 3];
            out.emplace(std::min(a, b), std::max(a, b));
        }
    }
    return out;
}

struct Three {
    MethodResult naive, gilbert, fast;
};

Three run_all(const std::vector<Point3>& points, const std::vector<Segment>& segments = {}) {
    const MethodInput in{points, segments};
    return {run_greedy_naive(in, {}, {}), run_greedy_gilbert(in, {}, {}), run_greedy(in, {}, {})};
}

void expect_same(const Three& r, const char* what) {
    const EdgeSet naive = edge_set(r.naive.tin);
    EXPECT_EQ(edge_set(r.gilbert.tin), naive) << what;
    EXPECT_EQ(edge_set(r.fast.tin), naive) << what;
    for (const MethodResult* m : {&r.naive, &r.gilbert, &r.fast}) {
        EXPECT_TRUE(verify_topology(m->tin).ok()) << what << ": " << verify_topology(m->tin).text();
        // Locally optimal under the shortest diagonal: a shorter diagonal would have come first.
        EXPECT_EQ(count_improvable_edges(m->tin, Criterion::shortest_diagonal), 0u) << what;
    }
}

std::vector<Point3> clustered(std::size_t n, std::uint32_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    std::vector<Point3> centres(5);
    for (Point3& c : centres) c = {u(rng), u(rng), 0};
    std::vector<Point3> pts;
    for (std::size_t i = 0; i < n; ++i) {
        const Point3& c = centres[i % 5];
        pts.push_back({c.x + 2.0 * g(rng), c.y + 2.0 * g(rng), 0});
    }
    return pts;
}

TEST(Greedy, VariantsAgreeOnUniformPoints) {
    for (std::uint32_t seed = 1; seed <= 2; ++seed) {
        expect_same(run_all(test::random_points(300, seed)), "uniform");
    }
}

TEST(Greedy, VariantsAgreeOnClusters) { expect_same(run_all(clustered(400, 7)), "clusters"); }

TEST(Greedy, VariantsAgreeOnGridsWithEqualLengths) {
    // Every unit edge ties with hundreds of others: the index tie-break decides.
    std::vector<Point3> grid;
    for (int j = 0; j < 14; ++j) {
        for (int i = 0; i < 15; ++i) grid.push_back({double(i), double(j), 0});
    }
    const Three r = run_all(grid);
    expect_same(r, "grid");
    // Tilted and at S-JTSK magnitudes (rounded coordinates: near-ties for the exact comparison).
    expect_same(run_all(test::tilted_grid(12, 11, 2.5, 0.4, test::sjtsk_e, test::sjtsk_n)),
                "tilted grid");
}

TEST(Greedy, CollinearHullPointsAndRepeatedPoints) {
    std::vector<Point3> pts = test::random_points(150, 9, 0, 0, 100);
    for (int i = 0; i <= 10; ++i) {
        pts.push_back({10.0 * i, 0, 0});    // a collinear hull side
        pts.push_back({10.0 * i, 100, 0});  // and another
        pts.push_back({50, 10.0 * i, 0});   // collinear interior points
    }
    pts.push_back(pts[3]);  // a duplicate
    const Three r = run_all(pts);
    expect_same(r, "collinear");
    EXPECT_EQ(r.fast.counters.extra.at("duplicates"), 3u);  // (50, 0) and (50, 100) twice too
}

TEST(Greedy, FixedEdgesStay) {  // R17
    std::vector<Point3> pts = test::random_points(250, 4);
    // Long fixed edges, which the greedy loop would never choose by itself.
    for (const Point3& q : {Point3{100, 500, 0}, Point3{900, 520, 0}, Point3{500, 100, 0},
                            Point3{520, 300, 0}, Point3{200, 900, 0}, Point3{800, 880, 0}}) {
        pts.push_back(q);
    }
    std::vector<Segment> segments{{250, 251}, {252, 253}, {254, 255}};
    const Three r = run_all(pts, segments);
    const EdgeSet e = edge_set(r.naive.tin);
    for (const auto& [a, b] : segments) EXPECT_TRUE(e.count({std::min(a, b), std::max(a, b)}));
    expect_same(r, "fixed");
    EXPECT_EQ(r.fast.tin.constraints.size(), 3u);
}

TEST(Greedy, ManyFixedEdgesFromADelaunayTriangulation) {
    const std::vector<Point3> pts = test::random_points(200, 6);
    TerrainInput terrain;
    terrain.points = pts;
    const Tin dt = triangulate(terrain).tin;
    std::vector<Segment> segments;
    std::size_t k = 0;
    for (const Triangle& t : dt.triangles) {
        for (int s = 0; s < 3; ++s) {
            if (t.n[s] != no_triangle && (k++ % 4) == 0) {
                segments.emplace_back(t.v[(s + 1) % 3], t.v[(s + 2) % 3]);
            }
        }
    }
    const Three r = run_all(pts, segments);
    expect_same(r, "many fixed");
    const EdgeSet e = edge_set(r.fast.tin);
    for (const auto& [a, b] : segments) EXPECT_TRUE(e.count({std::min(a, b), std::max(a, b)}));
}

TEST(Greedy, CrossingFixedEdgesAreRefused) {
    const std::vector<Point3> pts{{0, 0, 0}, {2, 2, 0}, {0, 2, 0}, {2, 0, 0}, {5, 5, 0}};
    EXPECT_THROW((void)run_greedy(MethodInput{pts, std::vector<Segment>{{0, 1}, {2, 3}}}, {}, {}),
                 InputError);
    EXPECT_THROW((void)run_greedy_naive(MethodInput{{pts.data(), 2}, {}}, {}, {}), InputError);
}

TEST(Greedy, EdgeCountAndLengthAgainstDelaunay) {
    const std::vector<Point3> pts = test::random_points(1000, 11);
    const MethodResult r = run_greedy(MethodInput{pts, {}}, {}, {});
    EXPECT_TRUE(verify_topology(r.tin).ok());
    // The greedy triangulation approximates the minimum-weight one: shorter than Delaunay.
    const auto at = [&](const std::string& key) {
        const auto k = r.stats_json.find("\"" + key + "\": ");
        return std::stod(r.stats_json.substr(k + key.size() + 4));
    };
    EXPECT_LT(at("total_length"), at("delaunay_total_length"));
    EXPECT_GT(at("length_ratio"), 0.9);
}

TEST(Greedy, SegmentTreeOfTheThesis) {  // R19: T(4, 15)
    const SegmentTreeShape t(4, 15);
    EXPECT_EQ(t.size(), 2u * 11 - 1);  // 11 elementary intervals
    EXPECT_EQ(t.depth(), 4);           // ceil(log2(15 - 4))
    EXPECT_EQ(t.begin[0], 4u);
    EXPECT_EQ(t.end[0], 15u);
    EXPECT_EQ(t.end[t.left[0]], 9u);  // floor((4 + 15) / 2)
    EXPECT_EQ(t.begin[t.right[0]], 9u);
    std::size_t leaves = 0;
    for (std::size_t v = 0; v < t.size(); ++v) {
        if (t.left[v] == SegmentTreeShape::none) {
            ++leaves;
            EXPECT_EQ(t.end[v] - t.begin[v], 1u);
        }
    }
    EXPECT_EQ(leaves, 11u);
}

}  // namespace
}  // namespace dtm::methods
