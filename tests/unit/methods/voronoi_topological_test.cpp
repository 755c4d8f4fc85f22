// SPDX-License-Identifier: MIT
// The topology-oriented incremental Voronoi method under corrupted in-circle signs (000 §3.6,
// R36): whatever the signs, the graph it grows stays a planar graph of n regions (plus the three
// auxiliary ones and the outside of the curve), every region one simple cycle, no two regions
// sharing two edges. The classic method, trusting each sign, breaks (and says so). Also
// Sugihara and Iri's numerics: H of method 2 and the circumcentre formula (R3, R4).
#include "methods/voronoi_topological.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/geom/constructions.hpp"
#include "dtm/geom/predicates.hpp"
#include "dtm/methods/registry.hpp"
#include "dtm/methods/voronoi.hpp"
#include "methods/detail/voronoi_incremental_graph.hpp"
#include "methods/voronoi_incremental.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm::methods {
namespace {

using detail::IncrementalVoronoi;

/// Everything Sugihara and Iri promise of G_n, checked on the whole graph.
std::string graph_problems(const detail::VoronoiGraph& g, std::uint32_t faces) {
    const auto& he = g.he;
    std::vector<std::uint32_t> degree(g.vertex_count, 0);
    std::map<std::uint32_t, std::vector<std::uint32_t>> by_face;
    std::size_t live = 0;
    for (std::uint32_t h = 0; h < he.size(); ++h) {
        if (he[h].face == detail::dead_face) continue;
        ++live;
        ++degree[he[h].origin];
        by_face[he[h].face].push_back(h);
        if (he[he[h].next].origin != he[h ^ 1u].origin) return "next does not continue the edge";
        if (he[he[h].next].face != he[h].face) return "next leaves the face";
    }
    std::size_t vertices = 0;
    for (std::uint32_t d : degree) {
        if (d == 0) continue;
        ++vertices;
        if (d != 3) return "a vertex of degree " + std::to_string(d);
    }
    if (by_face.size() != faces) {
        return std::to_string(by_face.size()) + " regions, expected " + std::to_string(faces);
    }
    for (const auto& [f, list] : by_face) {
        // One simple cycle per region.
        std::set<std::uint32_t> cycle_vertices, neighbours;
        std::size_t length = 0;
        std::uint32_t h = list.front();
        do {
            if (!cycle_vertices.insert(he[h].origin).second)
                return "a region's cycle is not simple";
            if (!neighbours.insert(he[h ^ 1u].face).second) return "two regions share two edges";
            h = he[h].next;
            ++length;
        } while (h != list.front() && length <= list.size());
        if (length != list.size()) return "a region has more than one cycle";
    }
    const long long euler = static_cast<long long>(vertices) - static_cast<long long>(live / 2) +
                            static_cast<long long>(faces);
    if (euler != 2) return "V - E + F = " + std::to_string(euler);
    return {};
}

detail::VoronoiGraph grow(std::vector<Point3> pts,
                          double faults,
                          std::uint64_t seed,
                          detail::ChooseTree choose,
                          std::uint32_t& faces) {
    detail::Sites sites = detail::make_sites(pts, "test");
    detail::CountingPredicates pred;
    IncrementalVoronoi graph(sites, pred);
    graph.set_faults(faults, seed);
    std::vector<std::uint32_t> tree;
    for (std::uint32_t g : graph.insertion_order()) {
        graph.clear_labels();
        tree.clear();
        choose(graph, g, sites.xy[g], tree);
        graph.insert(g, tree);
    }
    graph.clear_labels();
    faces = sites.real + 4;
    return graph.release();
}

TEST(VoronoiTopological, CorruptedSignsStillGiveAValidPlanarGraph) {
    for (const double faults : {0.01, 0.1, 0.3, 0.5, 1.0}) {
        for (std::uint64_t seed = 1; seed <= 6; ++seed) {
            SCOPED_TRACE("faults " + std::to_string(faults) + " seed " + std::to_string(seed));
            const auto pts = test::random_points(400, static_cast<std::uint32_t>(seed));
            std::uint32_t faces = 0;
            const detail::VoronoiGraph g =
                grow(pts, faults, seed, &detail::choose_tree_topological, faces);
            EXPECT_EQ(graph_problems(g, faces), "");
        }
    }
}

TEST(VoronoiTopological, CorruptedSignsThroughTheRegistry) {
    const auto pts = test::random_points(2000, 9);
    MethodOptions options;
    options.params["faults"] = "0.2";
    options.seed = 4;
    const MethodResult r =
        find_method("voronoi-topological")->run(MethodInput{pts, {}}, options, {});
    EXPECT_GT(r.counters.extra.at("faults_injected"), 1000u);
    const CheckReport check = verify_voronoi(r.voronoi, pts, false);
    EXPECT_TRUE(check.ok()) << check.text();
    EXPECT_TRUE(r.tin.triangles.empty());  // no geometric triangulation from corrupted signs
    EXPECT_NE(r.stats_json.find("faults_injected"), std::string::npos);
}

TEST(VoronoiTopological, TheClassicMethodBreaksUnderCorruptedSigns) {
    // Sugihara and Iri's point (000 §3.6, Fig. 1): trusting each sign, the new region need not
    // close. The classic method must notice and stop with an error, never return a broken graph.
    int stopped = 0;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const auto pts = test::random_points(300, static_cast<std::uint32_t>(seed));
        std::uint32_t faces = 0;
        try {
            const detail::VoronoiGraph g =
                grow(pts, 0.1, seed, &detail::choose_tree_classic, faces);
            EXPECT_EQ(graph_problems(g, faces), "") << "seed " << seed;
        } catch (const Error&) {
            ++stopped;
        }
    }
    EXPECT_GT(stopped, 5);
}

// R3: H by method 2 has the sign of the exact in-circle determinant (opposite convention).
TEST(VoronoiTopological, MethodTwoHasTheExactSign) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1000.0, 1000.0);
    int agree = 0, total = 0;
    for (int i = 0; i < 20000; ++i) {
        Point2 a{u(rng), u(rng)}, b{u(rng), u(rng)}, c{u(rng), u(rng)}, d{u(rng), u(rng)};
        const int o = geom::orient2d(a, b, c);
        if (o == 0) continue;
        if (o < 0) std::swap(b, c);
        const double h = detail::sugihara_iri_h(a, b, c, d);
        const int exact = geom::incircle(a, b, c, d);
        ++total;
        agree += (h < 0) == (exact > 0) ? 1 : 0;
    }
    EXPECT_EQ(agree, total);
}

// R4: the circumcentre from the cached cofactors, (-J2/J4 + xk, J3/J4 + yk).
TEST(VoronoiTopological, CircumcentreFromTheCofactors) {
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 10000; ++i) {
        const Point2 a{700000 + u(rng), 1000000 + u(rng)}, b{700000 + u(rng), 1000000 + u(rng)},
            c{700000 + u(rng), 1000000 + u(rng)};
        const Point2 m = geom::circumcentre(a, b, c);
        // Reference in long double, relative to a.
        const long double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
        const long double d = 2 * (bx * cy - by * cx);
        if (std::abs(d) < 1e-6L) continue;
        const long double ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
        const long double uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
        const long double r = std::sqrt(ux * ux + uy * uy);
        EXPECT_NEAR(static_cast<double>(m.x - a.x), static_cast<double>(ux),
                    1e-9 * double(r) + 1e-9);
        EXPECT_NEAR(static_cast<double>(m.y - a.y), static_cast<double>(uy),
                    1e-9 * double(r) + 1e-9);
    }
}

}  // namespace
}  // namespace dtm::methods
