// SPDX-License-Identifier: MIT
// Tin helpers: neighbour links rebuilt from the triangles, half-edges and their twins, and the
// constraint kind encoding.
#include "dtm/core/tin.hpp"

#include <gtest/gtest.h>

#include <string>

#include "dtm/core/error.hpp"

namespace {

/// Two triangles sharing the diagonal 0-2 of the unit square, plus a third one on its right.
dtm::Tin square()
{
    dtm::Tin tin;
    tin.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}};
    tin.triangles.resize(3);
    tin.triangles[0].v = {0, 1, 2};
    tin.triangles[1].v = {0, 2, 3};
    tin.triangles[2].v = {1, 4, 2};
    return tin;
}

TEST(LinkNeighbours, LinksSharedEdgesAndLeavesTheBorderOpen)
{
    dtm::Tin tin = square();
    tin.triangles[0].n = {7, 7, 7};  // stale links are replaced
    dtm::link_neighbours(tin);
    const auto none = dtm::no_triangle;
    // triangle 0 = (0, 1, 2): side 0 (1-2) borders triangle 2, side 1 (2-0) triangle 1
    EXPECT_EQ(tin.triangles[0].n, (std::array<dtm::TriangleIndex, 3>{2, 1, none}));
    EXPECT_EQ(tin.triangles[1].n, (std::array<dtm::TriangleIndex, 3>{none, none, 0}));
    EXPECT_EQ(tin.triangles[2].n, (std::array<dtm::TriangleIndex, 3>{none, 0, none}));
}

TEST(LinkNeighbours, AnEdgeUsedTwiceInTheSameDirectionIsAnInputError)
{
    dtm::Tin tin = square();
    tin.triangles[1].v = {0, 1, 3};  // 0 -> 1 again
    try {
        dtm::link_neighbours(tin);
        FAIL() << "no exception";
    } catch (const dtm::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("edge 0-1"), std::string::npos) << e.what();
    }
}

TEST(HalfEdge, OriginDestinationAndTwin)
{
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

TEST(ConstraintKind, BitsAreOnePerKindAndNamesAreDistinct)
{
    EXPECT_EQ(dtm::constraint_bit(dtm::ConstraintKind::breakline), 1);
    EXPECT_EQ(dtm::constraint_bit(dtm::ConstraintKind::soft_breakline), 2);
    EXPECT_EQ(dtm::constraint_bit(dtm::ConstraintKind::boundary), 4);
    EXPECT_EQ(dtm::constraint_bit(dtm::ConstraintKind::hole), 8);
    EXPECT_STREQ(dtm::constraint_kind_name(dtm::ConstraintKind::soft_breakline), "soft breakline");
    EXPECT_STREQ(dtm::constraint_kind_name(dtm::ConstraintKind::hole), "hole");
}

}  // namespace
