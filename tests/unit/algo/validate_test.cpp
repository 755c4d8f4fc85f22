// SPDX-License-Identifier: MIT
// The validators behind `dtm tin --check`: what verify_constraints accepts and what it reports.
#include "dtm/algo/validate.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "dtm/algo/triangulate.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm {
namespace {

/// 400 random points on a 1000 m square, a boundary ring around the middle and a breakline that
/// runs inside it, leaves it through its right side, comes back, and ends inside.
TerrainInput clipped_breakline_input() {
    TerrainInput input;
    input.points = test::random_points(400, 21);
    input.boundaries.push_back(
        {{{100, 100, 0}, {700, 100, 0}, {700, 900, 0}, {100, 900, 0}}, true, "boundary"});
    input.breaklines.push_back(
        {{{200, 300, 5}, {650, 350, 5}, {850, 500, 5}, {650, 650, 5}, {200, 700, 5}},
         false,
         "breakline"});
    return input;
}

/// Removes the TIN's constrained edges for which @p drop holds.
template <class Drop>
void drop_constraints(Tin& tin, Drop drop) {
    tin.constraints.erase(std::remove_if(tin.constraints.begin(), tin.constraints.end(), drop),
                          tin.constraints.end());
}

TEST(VerifyConstraints, BreaklineThatLeavesTheBoundaryIsRequiredOnlyInside) {
    const TerrainInput input = clipped_breakline_input();
    const TriangulateResult r = triangulate(input);
    const CheckReport report = verify_constraints(r.tin, input);
    EXPECT_TRUE(report.ok()) << report.text();
    // The piece beyond x = 700 was clipped with the outside triangles: no vertex of the TIN lies
    // there, so the check above really passed over a gap.
    for (const Triangle& t : r.tin.triangles) {
        for (const VertexIndex v : t.v) EXPECT_LE(r.tin.vertices[v].x, 700.0);
    }
}

TEST(VerifyConstraints, SegmentWithBothEndsInsideThatCrossesANotchIsRequiredOnlyInside) {
    // The boundary has a notch cut in from its right side; the breakline runs from (600, 300) to
    // (600, 700), both ends inside, through the notch (x = 600 is outside for 470 < y < 530).
    TerrainInput input;
    input.points = test::random_points(400, 22);
    input.boundaries.push_back({{{100, 100, 0},
                                 {700, 100, 0},
                                 {700, 450, 0},
                                 {450, 500, 0},
                                 {700, 550, 0},
                                 {700, 900, 0},
                                 {100, 900, 0}},
                                true,
                                "boundary"});
    input.breaklines.push_back({{{600, 300, 5}, {600, 700, 5}}, false, "breakline"});
    const TriangulateResult r = triangulate(input);
    EXPECT_EQ(r.stats.intersections, 2u);
    const CheckReport report = verify_constraints(r.tin, input);
    EXPECT_TRUE(report.ok()) << report.text();
}

TEST(VerifyConstraints, MissingPieceInsideTheSurfaceIsReportedEvenWhenTheSegmentLeavesIt) {
    const TerrainInput input = clipped_breakline_input();
    TriangulateResult r = triangulate(input);
    ASSERT_TRUE(verify_constraints(r.tin, input).ok());
    // Forget the breakline's constrained edges between x = 650 and x = 700 (inside the boundary,
    // on the segment from (650, 350) to (850, 500) that then leaves through x = 700).
    const std::size_t before = r.tin.constraints.size();
    drop_constraints(r.tin, [&](const ConstrainedEdge& c) {
        const Point3& a = r.tin.vertices[c.a];
        const Point3& b = r.tin.vertices[c.b];
        return c.kind == ConstraintKind::breakline && std::min(a.x, b.x) >= 650.0 &&
               std::max(a.x, b.x) <= 700.001 && std::min(a.y, b.y) < 400.0;
    });
    ASSERT_LT(r.tin.constraints.size(), before);
    const CheckReport report = verify_constraints(r.tin, input);
    ASSERT_FALSE(report.ok());
    EXPECT_NE(report.text().find("breakline 1 segment 2: not present"), std::string::npos)
        << report.text();
}

TEST(VerifyConstraints, MissingBreaklineEdgeInsideIsReported) {
    TerrainInput input;
    input.points = test::random_points(300, 4);
    input.breaklines.push_back({{{100, 200, 1}, {900, 800, 2}}, false, "b"});
    TriangulateResult r = triangulate(input);
    ASSERT_TRUE(verify_constraints(r.tin, input).ok());
    ASSERT_FALSE(r.tin.constraints.empty());
    r.tin.constraints.pop_back();
    const CheckReport report = verify_constraints(r.tin, input);
    ASSERT_FALSE(report.ok());
    EXPECT_NE(report.text().find("breakline 1 segment 1: not present"), std::string::npos)
        << report.text();
}

}  // namespace
}  // namespace dtm
