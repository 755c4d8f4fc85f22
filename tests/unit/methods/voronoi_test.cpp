// SPDX-License-Identifier: MIT
// The Voronoi methods (voronoi-dc, voronoi-incremental, voronoi-topological): every diagram
// passes the exact validator, its dual equals the production kernel's triangulation on inputs in
// general position, the counts of 000 §3.3 hold, and degenerate inputs (cocircular grids and
// circles, collinear points, duplicates) give the same canonical diagram from every method.
#include "dtm/methods/voronoi.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"
#include "dtm/methods/registry.hpp"
#include "methods_fixtures.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm::methods {
namespace {

const std::vector<std::string>& voronoi_methods() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const MethodInfo& m : registry()) {
            if (m.family == Family::voronoi) out.emplace_back(m.name);
        }
        return out;
    }();
    return names;
}

MethodResult run(const std::string& name,
                 std::span<const Point3> points,
                 MethodOptions options = {}) {
    const MethodInfo* m = find_method(name);
    EXPECT_NE(m, nullptr) << name;
    return m->run(MethodInput{points, {}}, options, Progress{});
}

/// The triangles as sorted index triples (for comparing triangulations of the same vertices).
std::set<std::array<VertexIndex, 3>> triples(const Tin& tin) {
    std::set<std::array<VertexIndex, 3>> out;
    for (const Triangle& t : tin.triangles) {
        std::array<VertexIndex, 3> v = t.v;
        std::sort(v.begin(), v.end());
        out.insert(v);
    }
    return out;
}

/// A diagram independent of numbering: each vertex as its generators in ccw order starting at
/// the smallest, each edge as (generator pair, its two end vertices' keys).
using VertexKey = std::vector<std::uint32_t>;
struct Canonical {
    std::set<VertexKey> vertices;
    std::set<std::tuple<std::uint32_t, std::uint32_t, VertexKey, VertexKey>> edges;
    friend bool operator==(const Canonical&, const Canonical&) = default;
};

Canonical canonical(const VoronoiDiagram& d) {
    std::vector<std::uint32_t> prev(d.half_edges.size());
    for (std::uint32_t h = 0; h < d.half_edges.size(); ++h) prev[d.half_edges[h].next] = h;
    std::vector<VertexKey> key(d.vertices.size());
    std::vector<std::uint32_t> out(d.vertices.size(), VoronoiDiagram::none);
    for (std::uint32_t h = 0; h < d.half_edges.size(); ++h) {
        if (d.half_edges[h].origin != VoronoiDiagram::none) out[d.half_edges[h].origin] = h;
    }
    Canonical c;
    for (std::uint32_t v = 0; v < d.vertices.size(); ++v) {
        VertexKey k;
        std::uint32_t h = out[v];
        do {
            k.push_back(d.half_edges[h].face);
            h = prev[h] ^ 1u;
        } while (h != out[v]);
        std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
        key[v] = k;
        c.vertices.insert(k);
    }
    for (std::uint32_t h = 0; h < d.half_edges.size(); h += 2) {
        std::uint32_t a = d.half_edges[h].face, b = d.half_edges[h + 1].face;
        VertexKey ka, kb;
        if (d.half_edges[h].origin != VoronoiDiagram::none) ka = key[d.half_edges[h].origin];
        if (d.half_edges[h + 1].origin != VoronoiDiagram::none)
            kb = key[d.half_edges[h + 1].origin];
        if (a > b) {
            std::swap(a, b);
            std::swap(ka, kb);
        }
        if (ka > kb && a == b) std::swap(ka, kb);
        c.edges.insert({a, b, ka, kb});
    }
    return c;
}

std::size_t hull_size(const Tin& tin) {
    std::size_t h = 0;
    for (const Triangle& t : tin.triangles) {
        for (TriangleIndex n : t.n) h += n == no_triangle ? 1 : 0;
    }
    return h;
}

void expect_valid(const std::string& name, std::span<const Point3> pts, const MethodResult& r) {
    const CheckReport check = verify_voronoi(r.voronoi, pts);
    EXPECT_TRUE(check.ok()) << name << ": " << check.text();
    const CheckReport topo = verify_topology(r.tin);
    EXPECT_TRUE(topo.ok()) << name << ": " << topo.text();
    const CheckReport del = verify_constrained_delaunay(r.tin);
    EXPECT_TRUE(del.ok()) << name << ": " << del.text();
}

TEST(Voronoi, DualEqualsTheKernelOnRandomPoints) {
    for (const std::uint32_t seed : {1u, 2u, 3u, 4u}) {
        for (const std::size_t n : {3u, 4u, 5u, 7u, 10u, 31u, 100u, 1000u}) {
            const auto pts =
                dtm::test::random_points(n, seed * 7919 + static_cast<std::uint32_t>(n));
            const MethodResult dc = run("dc", pts);
            for (const std::string& name : voronoi_methods()) {
                SCOPED_TRACE(name + " n=" + std::to_string(n) + " seed=" + std::to_string(seed));
                const MethodResult r = run(name, pts);
                expect_valid(name, pts, r);
                EXPECT_EQ(triples(r.tin), triples(dc.tin));
                // 000 §3.3: at most 2n - 5 vertices and 3n - 6 edges, all of degree 3 here.
                EXPECT_LE(r.voronoi.vertices.size(), 2 * n - 5);
                EXPECT_LE(r.voronoi.half_edges.size() / 2, 3 * n - 6);
                EXPECT_EQ(r.counters.extra.at("max_vertex_degree"), 3u);
                // Unbounded regions exactly for hull points: one ray per hull edge.
                EXPECT_EQ(r.counters.extra.at("unbounded_edges"), hull_size(dc.tin));
                // 2n - 2 - h triangles.
                EXPECT_EQ(r.tin.triangles.size(), 2 * n - 2 - hull_size(dc.tin));
            }
        }
    }
}

std::vector<Point3> integer_points(std::size_t n, std::uint32_t seed, int range) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> u(0, range);
    std::vector<Point3> pts(n);
    for (Point3& p : pts) p = {double(u(rng)), double(u(rng)), double(u(rng))};
    return pts;
}

std::string describe(std::span<const Point3> pts) {
    std::string s;
    for (const Point3& p : pts) s += "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ") ";
    return s;
}

// Small sets on tiny integer grids: duplicates, collinear runs and cocircular quadruples
// everywhere. Every method gives a valid diagram, the same one (vertices of degree > 3
// included), and a Delaunay dual with the kernel's triangle count.
TEST(Voronoi, DegenerateSmallSetsGiveOneCanonicalDiagram) {
    int failures = 0;
    for (std::uint32_t seed = 0; seed < 1500 && failures < 3; ++seed) {
        const std::size_t n = 2 + seed % 15;
        const auto pts = integer_points(n, seed, seed % 3 == 0 ? 3 : 6);
        std::vector<Canonical> diagrams;
        std::size_t triangles = 0;
        for (const std::string& name : voronoi_methods()) {
            MethodResult r;
            try {
                r = run(name, pts);
            } catch (const InputError&) {  // fewer than two distinct points
                continue;
            }
            const CheckReport check = verify_voronoi(r.voronoi, pts);
            const CheckReport topo = verify_topology(r.tin);
            const CheckReport del = verify_constrained_delaunay(r.tin);
            if (!check.ok() || !topo.ok() || !del.ok()) {
                ++failures;
                ADD_FAILURE() << name << " seed " << seed << ": " << describe(pts) << "\n"
                              << check.text() << topo.text() << del.text();
            }
            diagrams.push_back(canonical(r.voronoi));
            triangles = r.tin.triangles.size();
        }
        for (std::size_t i = 1; i < diagrams.size(); ++i) {
            EXPECT_TRUE(diagrams[i] == diagrams[0]) << "seed " << seed << ": " << describe(pts);
        }
        if (diagrams.empty()) continue;
        try {
            EXPECT_EQ(triangles, run("dc", pts).tin.triangles.size()) << describe(pts);
        } catch (const InputError&) {
            EXPECT_EQ(triangles, 0u);  // collinear: the kernel refuses, the diagram is lines
        }
    }
}

// A tilted grid is cocircular everywhere: one Voronoi vertex of degree 4 per grid square.
TEST(Voronoi, GridVerticesHaveDegreeFour) {
    const auto pts = dtm::test::tilted_grid(9, 7, 2.5, 0.0, 100.0, 200.0);
    for (const std::string& name : voronoi_methods()) {
        SCOPED_TRACE(name);
        const MethodResult r = run(name, pts);
        expect_valid(name, pts, r);
        EXPECT_EQ(r.voronoi.vertices.size(), 8u * 6u);
        EXPECT_EQ(r.counters.extra.at("max_vertex_degree"), 4u);
        EXPECT_EQ(r.tin.triangles.size(), 2u * 8u * 6u);
        EXPECT_EQ(r.counters.extra.at("unbounded_edges"), 2u * (8u + 6u));
    }
}

// Twelve points with integer coordinates on the circle of radius 5: a single vertex of degree
// 12 at the centre, twelve rays, and a fan of ten triangles.
TEST(Voronoi, CocircularPointsMeetInOneVertex) {
    std::vector<Point3> pts;
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{{5, 0},
                                                               {4, 3},
                                                               {3, 4},
                                                               {0, 5},
                                                               {-3, 4},
                                                               {-4, 3},
                                                               {-5, 0},
                                                               {-4, -3},
                                                               {-3, -4},
                                                               {0, -5},
                                                               {3, -4},
                                                               {4, -3}}) {
        pts.push_back({1000.0 + x, 2000.0 + y, 1.0});
    }
    std::shuffle(pts.begin(), pts.end(), std::mt19937(3));
    for (const std::string& name : voronoi_methods()) {
        SCOPED_TRACE(name);
        const MethodResult r = run(name, pts);
        expect_valid(name, pts, r);
        ASSERT_EQ(r.voronoi.vertices.size(), 1u);
        EXPECT_NEAR(r.voronoi.vertices[0].x, 1000.0, 1e-9);
        EXPECT_NEAR(r.voronoi.vertices[0].y, 2000.0, 1e-9);
        EXPECT_EQ(r.counters.extra.at("max_vertex_degree"), 12u);
        EXPECT_EQ(r.voronoi.half_edges.size(), 24u);
        EXPECT_EQ(r.tin.triangles.size(), 10u);
    }
}

// Collinear generators: parallel bisectors, no vertex, no triangle (where the kernel refuses).
TEST(Voronoi, CollinearPointsGiveParallelLines) {
    for (const auto& [dx, dy] :
         std::vector<std::pair<double, double>>{{1, 0}, {0, 1}, {1, 1}, {3, -2}}) {
        std::vector<Point3> pts;
        for (const int i : {4, 0, 7, 2, 2, 9, 1}) pts.push_back({10 + i * dx, 20 + i * dy, 0.0});
        for (const std::string& name : voronoi_methods()) {
            SCOPED_TRACE(name);
            const MethodResult r = run(name, pts);
            const CheckReport check = verify_voronoi(r.voronoi, pts);
            EXPECT_TRUE(check.ok()) << check.text();
            EXPECT_TRUE(r.voronoi.vertices.empty());
            EXPECT_EQ(r.voronoi.half_edges.size(), 2u * 5u);  // six distinct points
            EXPECT_TRUE(r.tin.triangles.empty());
            EXPECT_EQ(r.tin.vertices.size(), 6u);
            EXPECT_EQ(r.counters.extra.at("duplicates"), 1u);
        }
    }
}

TEST(Voronoi, DuplicatesHaveNoRegionAndTheTinKeepsTheFirst) {
    auto pts = dtm::test::random_points(200, 11);
    pts.insert(pts.begin() + 50, pts[10]);
    pts.push_back(pts[3]);
    pts.push_back({pts[7].x, pts[7].y, 99.0});
    for (const std::string& name : voronoi_methods()) {
        SCOPED_TRACE(name);
        const MethodResult r = run(name, pts);
        expect_valid(name, pts, r);
        EXPECT_EQ(r.counters.extra.at("duplicates"), 3u);
        EXPECT_EQ(r.tin.vertices.size(), 200u);
        EXPECT_EQ(r.voronoi.face_edge[50], VoronoiDiagram::none);
        EXPECT_EQ(r.voronoi.face_edge[pts.size() - 1], VoronoiDiagram::none);
        EXPECT_NE(r.voronoi.face_edge[10], VoronoiDiagram::none);
        EXPECT_EQ(r.tin.vertices[7].z, pts[7].z);  // the first occurrence's height
    }
}

TEST(Voronoi, SurveyCoordinatesAndClusters) {
    auto pts = dtm::test::random_points(3000, 5, dtm::test::sjtsk_e, dtm::test::sjtsk_n, 500.0);
    // A tight cluster and a nearly collinear arc of a huge circle next to it.
    std::mt19937_64 rng(2);
    std::normal_distribution<double> g(0.0, 0.01);
    for (int i = 0; i < 500; ++i)
        pts.push_back({dtm::test::sjtsk_e + 250 + g(rng), dtm::test::sjtsk_n + 250 + g(rng), 0});
    for (int i = 0; i < 300; ++i) {
        const double t = -0.00071234 + 0.002 * i / 300.0;  // not symmetric about 0
        pts.push_back({dtm::test::sjtsk_e + 1e6 * std::sin(t),
                       dtm::test::sjtsk_n - 1e6 * (1 - std::cos(t)) - 10, 0});
    }
    const MethodResult dc = run("dc", pts);
    for (const std::string& name : voronoi_methods()) {
        SCOPED_TRACE(name);
        const MethodResult r = run(name, pts);
        expect_valid(name, pts, r);
        EXPECT_EQ(triples(r.tin), triples(dc.tin));
    }
}

TEST(Voronoi, TypedRefusalsAndParameters) {
    const std::vector<Point3> one{{1, 2, 3}, {1, 2, 4}};
    MethodOptions bad;
    bad.params["nonsense"] = "1";
    MethodOptions faults;
    faults.params["faults"] = "2";
    const auto pts = dtm::test::random_points(20, 1);
    for (const std::string& name : voronoi_methods()) {
        EXPECT_THROW((void)run(name, one), InputError) << name;
        EXPECT_THROW((void)run(name, pts, bad), UsageError) << name;
        if (name != "voronoi-dc") {
            EXPECT_THROW((void)run(name, pts, faults), UsageError) << name;
        }
    }
}

// 000 §3.3.2: the Preparata-Shamos edge nodes; VRCHOL lists a vertex's edges counter-clockwise,
// OBLAST a region's edges clockwise (checked through the generators they lead to).
TEST(Voronoi, EdgeNodeDcelTraversals) {
    const auto pts = dtm::test::random_points(300, 17);
    const MethodResult r = run("voronoi-dc", pts);
    const EdgeNodeDcel dcel = edge_node_dcel(r.voronoi);
    ASSERT_EQ(dcel.v1.size(), r.voronoi.half_edges.size() / 2);
    for (std::uint32_t v = 0; v < r.voronoi.vertices.size(); ++v) {
        const auto edges = vrchol(dcel, v);
        ASSERT_EQ(edges.size(), 3u);
        // Counter-clockwise around v: the directions to the other ends turn left.
        std::vector<double> angles;
        for (std::uint32_t e : edges) {
            const std::uint32_t other = dcel.v1[e] == v ? dcel.v2[e] : dcel.v1[e];
            Point2 dir;
            if (other != EdgeNodeDcel::none) {
                dir = {r.voronoi.vertices[other].x - r.voronoi.vertices[v].x,
                       r.voronoi.vertices[other].y - r.voronoi.vertices[v].y};
            } else {
                const std::uint32_t h = dcel.v1[e] == v ? 2 * e : 2 * e + 1;
                dir = voronoi_direction(r.voronoi, pts, h);
            }
            angles.push_back(std::atan2(dir.y, dir.x));
        }
        int turns = 0;
        for (int i = 0; i < 3; ++i) {
            double d = angles[(i + 1) % 3] - angles[i];
            while (d < 0) d += 2 * std::numbers::pi;
            turns += d < std::numbers::pi ? 1 : 0;
        }
        EXPECT_GE(turns, 2) << "vertex " << v;
    }
    for (std::uint32_t f = 0; f < pts.size(); ++f) {
        const auto edges = oblast(dcel, f);
        ASSERT_FALSE(edges.empty());
        // Clockwise around f: consecutive neighbours (meeting at a finite vertex) turn right
        // around p_f.
        const auto other = [&](std::uint32_t e) {
            return dcel.f1[e] == f ? dcel.f2[e] : dcel.f1[e];
        };
        for (std::size_t i = 0; i < edges.size(); ++i) {
            const std::uint32_t e = edges[i];
            const std::uint32_t n = edges[(i + 1) % edges.size()];
            const std::uint32_t shared =
                (dcel.v1[e] == dcel.v1[n] || dcel.v1[e] == dcel.v2[n]) ? dcel.v1[e] : dcel.v2[e];
            if (shared == EdgeNodeDcel::none) continue;  // across infinity
            EXPECT_LT(geom::orient2d(pts[f], pts[other(e)], pts[other(n)]), 0) << "region " << f;
        }
    }
}

// R32: the convex hull read off the rays (each separates two hull neighbours) is the hull of
// the kernel's triangulation.
TEST(Voronoi, HullFromTheRays) {
    const auto pts = dtm::test::random_points(1000, 23);
    const MethodResult dc = run("dc", pts);
    std::set<std::pair<VertexIndex, VertexIndex>> hull;
    for (const Triangle& t : dc.tin.triangles) {
        for (int i = 0; i < 3; ++i) {
            if (t.n[i] == no_triangle) hull.insert(std::minmax(t.v[(i + 1) % 3], t.v[(i + 2) % 3]));
        }
    }
    for (const std::string& name : voronoi_methods()) {
        const MethodResult r = run(name, pts);
        std::set<std::pair<VertexIndex, VertexIndex>> rays;
        for (std::uint32_t h = 0; h < r.voronoi.half_edges.size(); h += 2) {
            if (r.voronoi.half_edges[h].origin == VoronoiDiagram::none ||
                r.voronoi.half_edges[h + 1].origin == VoronoiDiagram::none) {
                rays.insert(
                    std::minmax(r.voronoi.half_edges[h].face, r.voronoi.half_edges[h + 1].face));
            }
        }
        EXPECT_EQ(rays, hull) << name;
    }
}

// The lab's and the degenerate families of point_sets.hpp, plain and at survey coordinates
// with millimetre rounding: valid diagrams, the same from every method, duals that are
// Delaunay triangulations (the kernel's where that is unique).
TEST(Voronoi, EveryPointSetFamily) {
    for (const Distribution dist : all_distributions()) {
        for (const std::size_t n : {60u, 700u}) {
            for (const bool survey : {false, true}) {
                SCOPED_TRACE(std::string(distribution_name(dist)) + " n=" + std::to_string(n) +
                             (survey ? " survey" : ""));
                const auto pts =
                    generate_points(dist, n, 3, survey ? test::sjtsk_mm() : PointSetOptions{});
                std::vector<Canonical> diagrams;
                for (const std::string& name : voronoi_methods()) {
                    SCOPED_TRACE(name);
                    test::expect_delaunay_like_dc(name, pts);
                    const MethodResult r = run(name, pts);
                    const CheckReport check = verify_voronoi(r.voronoi, pts);
                    EXPECT_TRUE(check.ok()) << check.text();
                    diagrams.push_back(canonical(r.voronoi));
                }
                for (std::size_t i = 1; i < diagrams.size(); ++i)
                    EXPECT_TRUE(diagrams[i] == diagrams[0]);
            }
        }
    }
}

// The validator can fail: each corruption of a valid diagram is caught.
TEST(Voronoi, ValidatorCatchesCorruptions) {
    const auto pts = dtm::test::random_points(200, 29);
    const MethodResult r = run("voronoi-dc", pts);
    ASSERT_TRUE(verify_voronoi(r.voronoi, pts).ok());
    const auto broken = [&](auto&& mutate) {
        VoronoiDiagram d = r.voronoi;
        mutate(d);
        return !verify_voronoi(d, pts).ok();
    };
    EXPECT_TRUE(
        broken([](VoronoiDiagram& d) { std::swap(d.half_edges[4].next, d.half_edges[9].next); }));
    EXPECT_TRUE(broken([](VoronoiDiagram& d) { d.half_edges[6].face = d.half_edges[7].face; }));
    EXPECT_TRUE(broken([](VoronoiDiagram& d) { d.vertices[3].x += 1.0; }));
    EXPECT_TRUE(broken([](VoronoiDiagram& d) { d.face_edge[5] = VoronoiDiagram::none; }));
    EXPECT_TRUE(broken([](VoronoiDiagram& d) { d.half_edges.pop_back(); }));
    // A combinatorially consistent but non-Delaunay diagram: the generators swapped between
    // two regions (all their half-edges), which breaks the geometry only.
    EXPECT_TRUE(broken([&](VoronoiDiagram& d) {
        const std::uint32_t a = d.half_edges[0].face, b = d.half_edges[1].face;
        for (auto& e : d.half_edges) {
            if (e.face == a)
                e.face = b;
            else if (e.face == b)
                e.face = a;
        }
        std::swap(d.face_edge[a], d.face_edge[b]);
    }));
}

}  // namespace
}  // namespace dtm::methods
