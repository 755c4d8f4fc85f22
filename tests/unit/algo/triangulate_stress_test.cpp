// SPDX-License-Identifier: MIT
// Degenerate-input stress: small integer lattices where breaklines overlap, cross at vertices
// and at new points, share endpoints and run along each other. Every result must be a valid,
// exactly constrained Delaunay TIN holding every breakline, for one and two threads alike.
#include <gtest/gtest.h>

#include <random>

#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"

namespace dtm {
namespace {

TerrainInput lattice_case(std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> coord(0, 8);
    std::uniform_int_distribution<int> count(1, 12);
    TerrainInput in;
    for (int x = 0; x <= 8; x += 2) {
        for (int y = 0; y <= 8; y += 2) in.points.push_back({x + 1e6, y - 1e6, double(x + y)});
    }
    const int lines = count(rng);
    for (int k = 0; k < lines; ++k) {
        Polyline line;
        const int vertices = 2 + k % 3;
        for (int i = 0; i < vertices; ++i) {
            line.points.push_back({coord(rng) + 1e6, coord(rng) - 1e6, double(coord(rng))});
        }
        in.breaklines.push_back(line);
    }
    return in;
}

TEST(TriangulateStress, DegenerateLatticeBreaklinesAlwaysGiveAValidConstrainedTin) {
    for (std::uint32_t seed = 1; seed <= 300; ++seed) {
        const TerrainInput in = lattice_case(seed);
        for (const unsigned threads : {1u, 2u}) {
            TriangulateOptions options;
            options.threads = threads;
            options.tiles = 4;
            const TriangulateResult r = triangulate(in, options);
            const CheckReport topology = verify_topology(r.tin);
            const CheckReport delaunay = verify_constrained_delaunay(r.tin);
            const CheckReport constraints = verify_constraints(r.tin, in, r.input_to_vertex);
            ASSERT_TRUE(topology.ok()) << "seed " << seed << "\n" << topology.text();
            ASSERT_TRUE(delaunay.ok()) << "seed " << seed << "\n" << delaunay.text();
            ASSERT_TRUE(constraints.ok()) << "seed " << seed << "\n" << constraints.text();
        }
    }
}

}  // namespace
}  // namespace dtm
