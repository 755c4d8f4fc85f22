// SPDX-License-Identifier: MIT
// The Delaunay kernel on triangles with ghosts (algo/detail/delaunay_dc.cpp, ghost_mesh.hpp),
// checked directly: the structure's invariants (twins, 2 n - 2 slots, the hull a closed cycle of
// ghosts, counter-clockwise triangles), the exact empty-circle property of every edge, and the
// same triangles in the same slots for every tile size. Inputs: random, lattices with
// cocircular cells, points on a circle, collinear chains, and the smallest sizes.
#include "algo/detail/delaunay_dc.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

using Points = std::vector<Point2>;

Points random_points(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-750000.0, -749000.0);
    Points p(n);
    for (Point2& q : p) q = {u(rng), u(rng) - 300000.0};
    return p;
}

Points lattice(std::size_t side) {
    Points p;
    for (std::size_t i = 0; i < side; ++i) {
        for (std::size_t j = 0; j < side; ++j) p.push_back({double(i), double(j)});
    }
    std::shuffle(p.begin(), p.end(), std::mt19937_64(7));
    return p;
}

Points circle(std::size_t n) {
    Points p;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = 2.0 * std::numbers::pi * double(i) / double(n);
        p.push_back({std::round(1e6 * std::cos(a)) / 8.0, std::round(1e6 * std::sin(a)) / 8.0});
    }
    return p;
}

Points chain(std::size_t n) {
    Points p;
    for (std::size_t i = 0; i < n; ++i) p.push_back({3.0 * double(i), -2.0 * double(i)});
    std::shuffle(p.begin(), p.end(), std::mt19937_64(3));
    return p;
}

GhostMesh triangulate_points(const Points& input, std::size_t cutoff) {
    BigArray<KernelPoint> pts(input.size());
    for (std::size_t i = 0; i < input.size(); ++i) {
        pts[i] = {{input[i].x, input[i].y}, static_cast<std::uint32_t>(i)};
    }
    GhostMesh mesh;
    DelaunayDcOptions options;
    options.parallel_cutoff = cutoff;
    delaunay_divide_and_conquer(pts, mesh, options, Progress{});
    return mesh;
}

Point2 at(const GhostMesh& m, VertexId v) { return m.points[v].xy(); }

void check_structure(const GhostMesh& m, std::size_t n, bool collinear) {
    ASSERT_EQ(m.tris.size(), 2 * n);
    std::size_t unused = 0;
    std::size_t real = 0;
    HalfEdge some_ghost_base = no_half_edge;
    for (std::size_t t = 0; t < m.tris.size(); ++t) {
        const auto& v = m.tris[t].v;
        const int ghosts = (v[0] == ghost) + (v[1] == ghost) + (v[2] == ghost);
        if (ghosts == 3) {
            ++unused;
            continue;
        }
        ASSERT_LE(ghosts, 1) << "triangle " << t;
        for (unsigned i = 0; i < 3; ++i) {
            const HalfEdge h = half_edge(t, i);
            const HalfEdge tw = m.twin(h);
            ASSERT_EQ(m.twin(tw), h) << "twin of twin, half-edge " << h;
            ASSERT_EQ(m.org(tw), m.dest(h));
            ASSERT_EQ(m.dest(tw), m.org(h));
            if (ghosts == 1 && m.org(h) != ghost && m.dest(h) != ghost) some_ghost_base = h;
        }
        if (ghosts == 0) {
            ++real;
            ASSERT_GT(geom::orient2d(at(m, v[0]), at(m, v[1]), at(m, v[2])), 0) << "triangle " << t;
        }
    }
    EXPECT_EQ(unused, 2u);
    if (collinear) {
        EXPECT_EQ(real, 0u);
    }
    // The hull: a closed cycle of ghosts through every ghost triangle.
    ASSERT_NE(some_ghost_base, no_half_edge);
    std::size_t hull = 0;
    HalfEdge g = some_ghost_base;
    do {
        g = next(m.twin(next(g)));
        ASSERT_LE(++hull, 2 * n);
    } while (g != some_ghost_base);
    EXPECT_EQ(hull + real + unused, 2 * n);
}

/// Every edge between two real triangles is locally Delaunay (exactly): together with a convex
/// hull this is the empty-circle property of the whole triangulation.
void check_delaunay(const GhostMesh& m) {
    for (std::size_t t = 0; t < m.tris.size(); ++t) {
        if (m.is_ghost(t)) continue;
        for (unsigned i = 0; i < 3; ++i) {
            const HalfEdge h = half_edge(t, i);
            const HalfEdge tw = m.twin(h);
            if (m.is_ghost(tri_of(tw))) continue;
            const VertexId far = m.org(prev(tw));
            const auto& v = m.tris[t].v;
            ASSERT_LE(geom::incircle(at(m, v[0]), at(m, v[1]), at(m, v[2]), at(m, far)), 0)
                << "edge " << h << " is not locally Delaunay";
        }
    }
}

struct Case {
    const char* name;
    Points points;
    bool collinear = false;
};

std::vector<Case> cases() {
    return {{"two", {{0, 0}, {1, 1}}},
            {"three", {{0, 0}, {2, 0}, {1, 1}}},
            {"three clockwise", {{0, 0}, {1, 1}, {2, 0}}},
            {"three collinear", {{0, 0}, {2, 2}, {1, 1}}, true},
            {"four square", {{0, 0}, {1, 0}, {0, 1}, {1, 1}}},
            {"chain", chain(41), true},
            {"vertical chain", {{5, 3}, {5, 1}, {5, 2}, {5, 0}, {5, 7}, {5, 4}}, true},
            {"lattice", lattice(37)},
            {"circle", circle(300)},
            {"random", random_points(20000, 11)}};
}

TEST(DelaunayKernel, GhostMeshInvariantsAndEmptyCircles) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const GhostMesh m = triangulate_points(c.points, 0);
        check_structure(m, c.points.size(), c.collinear);
        check_delaunay(m);
    }
}

TEST(DelaunayKernel, SameTrianglesInTheSameSlotsForEveryTileSize) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const GhostMesh whole = triangulate_points(c.points, 0);
        for (const std::size_t cutoff : {4, 64, 1000}) {
            const GhostMesh tiled = triangulate_points(c.points, cutoff);
            ASSERT_EQ(tiled.tris.size(), whole.tris.size());
            for (std::size_t t = 0; t < whole.tris.size(); ++t) {
                ASSERT_EQ(tiled.tris[t].v, whole.tris[t].v)
                    << "slot " << t << ", cutoff " << cutoff;
                ASSERT_EQ(tiled.tris[t].n, whole.tris[t].n)
                    << "slot " << t << ", cutoff " << cutoff;
            }
        }
    }
}

}  // namespace
}  // namespace dtm::detail
