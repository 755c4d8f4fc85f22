// SPDX-License-Identifier: MIT
// Tin helpers: neighbour links rebuilt from the triangles, half-edges and their twins, and the
// constraint kind encoding.
#include "dtm/core/tin.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"

namespace {

/// Two triangles sharing the diagonal 0-2 of the unit square, plus a third one on its right.
dtm::Tin square() {
    dtm::Tin tin;
    tin.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}};
    tin.triangles.resize(3);
    tin.triangles[0].v = {0, 1, 2};
    tin.triangles[1].v = {0, 2, 3};
    tin.triangles[2].v = {1, 4, 2};
    return tin;
}

TEST(LinkNeighbours, LinksSharedEdgesAndLeavesTheBorderOpen) {
    dtm::Tin tin = square();
    tin.triangles[0].n = {7, 7, 7};  // stale links are replaced
    dtm::link_neighbours(tin);
    const auto none = dtm::no_triangle;
    // triangle 0 = (0, 1, 2): side 0 (1-2) borders triangle 2, side 1 (2-0) triangle 1
    EXPECT_EQ(tin.triangles[0].n, (std::array<dtm::TriangleIndex, 3>{2, 1, none}));
    EXPECT_EQ(tin.triangles[1].n, (std::array<dtm::TriangleIndex, 3>{none, none, 0}));
    EXPECT_EQ(tin.triangles[2].n, (std::array<dtm::TriangleIndex, 3>{none, 0, none}));
}

TEST(LinkNeighbours, AnEdgeUsedTwiceInTheSameDirectionIsAnInputError) {
    dtm::Tin tin = square();
    tin.triangles[1].v = {0, 1, 3};  // 0 -> 1 again
    try {
        dtm::link_neighbours(tin);
        FAIL() << "no exception";
    } catch (const dtm::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("edge 0-1"), std::string::npos) << e.what();
    }
}

/// The links and the first error of one sequential pass over rows of sides listed under their
/// smaller vertex (link_neighbours' definition; it computes the same in parallel passes).
std::string reference_links(dtm::Tin& tin) {
    struct Listed {
        dtm::VertexIndex other;
        std::uint32_t code;
        bool forward;
    };
    std::vector<std::vector<Listed>> rows(tin.vertices.size());
    for (std::uint32_t t = 0; t < tin.triangles.size(); ++t) {
        tin.triangles[t].n = {dtm::no_triangle, dtm::no_triangle, dtm::no_triangle};
        for (std::uint32_t s = 0; s < 3; ++s) {
            const dtm::VertexIndex a = tin.triangles[t].v[(s + 1) % 3];
            const dtm::VertexIndex b = tin.triangles[t].v[(s + 2) % 3];
            rows[std::min(a, b)].push_back({std::max(a, b), 3 * t + s, a < b});
        }
    }
    for (std::size_t a = 0; a < rows.size(); ++a) {
        const auto& row = rows[a];
        for (std::size_t k = 0; k < row.size(); ++k) {
            for (std::size_t j = k + 1; j < row.size(); ++j) {
                if (row[j].other != row[k].other) continue;
                if (row[j].forward == row[k].forward) {
                    return "edge " + std::to_string(row[k].forward ? a : row[k].other) + "-" +
                           std::to_string(row[k].forward ? row[k].other : a);
                }
                tin.triangles[row[k].code / 3].n[row[k].code % 3] = row[j].code / 3;
                tin.triangles[row[j].code / 3].n[row[j].code % 3] = row[k].code / 3;
            }
        }
    }
    return "";
}

/// A triangulated random TIN with its vertices and triangles in random orders.
dtm::Tin shuffled_tin(std::size_t points, std::uint64_t seed) {
    dtm::TerrainInput input;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    for (std::size_t i = 0; i < points; ++i) input.points.push_back({u(rng), u(rng), 0.0});
    dtm::Tin tin = dtm::triangulate(input).tin;
    std::vector<dtm::VertexIndex> renumber(tin.vertices.size());
    std::iota(renumber.begin(), renumber.end(), dtm::VertexIndex{0});
    std::shuffle(renumber.begin(), renumber.end(), rng);
    std::vector<dtm::Point3> vertices(tin.vertices.size());
    for (std::size_t v = 0; v < renumber.size(); ++v) vertices[renumber[v]] = tin.vertices[v];
    tin.vertices = vertices;
    for (dtm::Triangle& t : tin.triangles) {
        for (dtm::VertexIndex& v : t.v) v = renumber[v];
    }
    std::shuffle(tin.triangles.begin(), tin.triangles.end(), rng);
    return tin;
}

TEST(LinkNeighbours, EqualsOneSequentialPassOnLargeShuffledTinsAndOnEveryThreadCount) {
    for (const std::size_t points : {std::size_t{300}, std::size_t{60000}}) {
        dtm::Tin tin = shuffled_tin(points, points);
        dtm::Tin want = tin;
        ASSERT_EQ(reference_links(want), "");
        for (const int threads : {1, 2}) {
            tbb::task_arena arena(threads);
            dtm::Tin got = tin;
            arena.execute([&] { dtm::link_neighbours(got); });
            for (std::size_t t = 0; t < want.triangles.size(); ++t) {
                ASSERT_EQ(got.triangles[t].n, want.triangles[t].n) << "triangle " << t;
            }
        }
    }
}

TEST(LinkNeighbours, ReportsTheOverlapOneSequentialPassFindsFirst) {
    dtm::Tin base = shuffled_tin(60000, 3);
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 6; ++trial) {
        dtm::Tin tin = base;
        // Overlaps: a triangle turned clockwise (each of its sides now runs the way its
        // neighbour's does), or copied onto another slot (every side used twice).
        for (int k = 0; k < 3; ++k) {
            const std::size_t t = rng() % tin.triangles.size();
            if (trial % 2 == 0) {
                std::swap(tin.triangles[t].v[0], tin.triangles[t].v[1]);
            } else {
                tin.triangles[(t + 1) % tin.triangles.size()].v = tin.triangles[t].v;
            }
        }
        dtm::Tin reference = tin;
        const std::string want = reference_links(reference);
        ASSERT_FALSE(want.empty());
        try {
            dtm::link_neighbours(tin);
            FAIL() << "no exception, expected " << want;
        } catch (const dtm::InputError& e) {
            EXPECT_NE(std::string(e.what()).find(want + " "), std::string::npos)
                << e.what() << " instead of " << want;
        }
    }
}

TEST(HalfEdge, OriginDestinationAndTwin) {
    dtm::Tin tin = square();
    dtm::link_neighbours(tin);
    const dtm::HalfEdge diagonal{0, 1};  // opposite v[1] = 1: runs 2 -> 0
    EXPECT_EQ(dtm::origin(tin, diagonal), 2U);
    EXPECT_EQ(dtm::destination(tin, diagonal), 0U);
    const dtm::HalfEdge back = dtm::twin(tin, diagonal);
    EXPECT_EQ(back, (dtm::HalfEdge{1, 2}));  // in triangle (0, 2, 3), opposite 3: runs 0 -> 2
    EXPECT_EQ(dtm::origin(tin, back), 0U);
    EXPECT_EQ(dtm::destination(tin, back), 2U);
    EXPECT_EQ(dtm::twin(tin, back), diagonal);
    EXPECT_EQ(dtm::twin(tin, dtm::HalfEdge{0, 2}).triangle, dtm::no_triangle);  // 0 -> 1, border
}

TEST(ConstraintKind, BitsAreOnePerKindAndNamesAreDistinct) {
    EXPECT_EQ(dtm::constraint_bit(dtm::ConstraintKind::breakline), 1);
    EXPECT_EQ(dtm::constraint_bit(dtm::ConstraintKind::soft_breakline), 2);
    EXPECT_EQ(dtm::constraint_bit(dtm::ConstraintKind::boundary), 4);
    EXPECT_EQ(dtm::constraint_bit(dtm::ConstraintKind::hole), 8);
    EXPECT_STREQ(dtm::constraint_kind_name(dtm::ConstraintKind::soft_breakline), "soft breakline");
    EXPECT_STREQ(dtm::constraint_kind_name(dtm::ConstraintKind::hole), "hole");
}

}  // namespace

TEST(LinkNeighbours, ATinWithoutTrianglesIsLinkedAsItIs) {
    dtm::Tin none;
    EXPECT_NO_THROW(dtm::link_neighbours(none));
    dtm::Tin points_only;
    points_only.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_NO_THROW(dtm::link_neighbours(points_only));
    EXPECT_TRUE(points_only.triangles.empty());
}
