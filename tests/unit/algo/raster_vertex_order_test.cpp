// SPDX-License-Identifier: MIT
// First-use renumbering of a TIN's vertices (algo/detail/raster_vertex_order.hpp): the numbering
// of one sequential pass over the corners, on one thread and on two, unused vertices dropped;
// the same renumbering in place, and the test that tells whether a TIN needs it.
#include "algo/detail/raster_vertex_order.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <random>
#include <string>

#include "dtm/algo/triangulate.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm::detail {
namespace {

Tin sequential_reference(const Tin& tin) {
    Tin out;
    out.triangles = tin.triangles;
    std::vector<VertexIndex> renumber(tin.vertices.size(), no_vertex);
    for (Triangle& t : out.triangles) {
        for (VertexIndex& v : t.v) {
            if (renumber[v] == no_vertex) {
                renumber[v] = static_cast<VertexIndex>(out.vertices.size());
                out.vertices.push_back(tin.vertices[v]);
            }
            v = renumber[v];
        }
    }
    return out;
}

/// A triangulation with its vertices in a random order, one of them used by no triangle.
Tin shuffled_tin() {
    TerrainInput input;
    input.points = test::random_points(120000, 4);
    Tin tin = triangulate(input).tin;
    // Vertices in a random order, one of them used by no triangle.
    std::vector<VertexIndex> shuffle(tin.vertices.size());
    for (std::size_t i = 0; i < shuffle.size(); ++i) shuffle[i] = static_cast<VertexIndex>(i);
    std::shuffle(shuffle.begin(), shuffle.end(), std::mt19937_64(8));
    std::vector<Point3> moved(tin.vertices.size() + 1);
    for (std::size_t i = 0; i < shuffle.size(); ++i) moved[shuffle[i]] = tin.vertices[i];
    moved.back() = {1e9, 1e9, 0};
    for (Triangle& t : tin.triangles) {
        for (VertexIndex& v : t.v) v = shuffle[v];
    }
    tin.vertices = std::move(moved);
    return tin;
}

void expect_same(const Tin& got, const Tin& want) {
    ASSERT_EQ(got.vertices, want.vertices);
    ASSERT_EQ(got.triangles.size(), want.triangles.size());
    for (std::size_t t = 0; t < want.triangles.size(); ++t) {
        ASSERT_EQ(got.triangles[t].v, want.triangles[t].v) << "triangle " << t;
        ASSERT_EQ(got.triangles[t].n, want.triangles[t].n) << "triangle " << t;
    }
}

TEST(CoherentVertices, EqualsOneSequentialPassOnEveryThreadCount) {
    const Tin tin = shuffled_tin();
    const Tin want = sequential_reference(tin);
    for (const int threads : {1, 2}) {
        tbb::task_arena arena(threads);
        SCOPED_TRACE(std::to_string(threads) + " threads");
        expect_same(arena.execute([&] { return with_coherent_vertices(tin); }), want);
    }
}

TEST(CoherentVertices, InPlaceEqualsOneSequentialPassAndIsRecognised) {
    const Tin shuffled = shuffled_tin();
    const Tin want = sequential_reference(shuffled);
    EXPECT_FALSE(has_coherent_vertices(shuffled));
    for (const int threads : {1, 2}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        Tin copy = shuffled;
        tbb::task_arena(threads).execute([&] { make_vertices_coherent(copy); });
        expect_same(copy, want);
    }
    Tin tin = shuffled;
    make_vertices_coherent(tin);
    EXPECT_TRUE(has_coherent_vertices(tin));
    // One swapped pair of first uses is enough to need the renumbering again.
    std::swap(tin.triangles[0].v[0], tin.triangles[0].v[1]);
    EXPECT_FALSE(has_coherent_vertices(tin));
    EXPECT_TRUE(has_coherent_vertices(Tin{}));
}

}  // namespace
}  // namespace dtm::detail
