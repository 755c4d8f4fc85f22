// SPDX-License-Identifier: MIT
// Constrained edges chained into lines: every edge in exactly one line, a breakline comes back
// as one line between its end points, a boundary and a hole as closed rings, junctions split.
#include "dtm/algo/constraint_lines.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "dtm/algo/triangulate.hpp"
#include "support/terrain_fixtures.hpp"

namespace {

using namespace dtm;

std::pair<double, double> key(const Point3& p) { return {p.x, p.y}; }

TEST(ConstraintLines, EveryEdgeOnceAndLinesWhereTheInputHadThem) {
    TerrainInput in;
    in.points = test::random_points(400, 4, 0.0, 0.0, 100.0);
    in.breaklines.push_back({{{10, 10, 1}, {30, 20, 2}, {50, 15, 3}, {70, 30, 4}}, false, ""});
    in.boundaries.push_back(
        {{{1, 1, 0}, {99, 1, 0}, {99, 99, 0}, {1, 99, 0}, {1, 1, 0}}, true, ""});
    in.holes.push_back(
        {{{60, 60, 0}, {80, 60, 0}, {80, 80, 0}, {60, 80, 0}, {60, 60, 0}}, true, ""});
    // a T junction of two soft breaklines
    in.soft_breaklines.push_back({{{20, 50, 0}, {40, 50, 0}}, false, ""});
    in.soft_breaklines.push_back({{{40, 40, 0}, {40, 50, 0}, {40, 58, 0}}, false, ""});
    const Tin tin = triangulate(in).tin;
    const std::vector<ConstraintLine> lines = constraint_lines(tin);
    std::map<ConstraintKind, std::size_t> count;
    std::multiset<std::pair<std::pair<double, double>, std::pair<double, double>>> edges;
    for (const ConstraintLine& l : lines) {
        ++count[l.kind];
        for (std::size_t i = 0; i + 1 < l.points.size(); ++i) {
            auto a = key(l.points[i]);
            auto b = key(l.points[i + 1]);
            if (b < a) std::swap(a, b);
            edges.insert({a, b});
        }
        if (l.kind == ConstraintKind::breakline) {
            ASSERT_FALSE(l.closed);
            const auto front = key(l.points.front());
            const auto back = key(l.points.back());
            EXPECT_TRUE(
                (front == std::make_pair(10.0, 10.0) && back == std::make_pair(70.0, 30.0)) ||
                (back == std::make_pair(10.0, 10.0) && front == std::make_pair(70.0, 30.0)));
        }
        if (l.kind == ConstraintKind::boundary || l.kind == ConstraintKind::hole) {
            EXPECT_TRUE(l.closed);
            EXPECT_EQ(key(l.points.front()), key(l.points.back()));
        }
    }
    EXPECT_EQ(count[ConstraintKind::breakline], 1U);
    EXPECT_EQ(count[ConstraintKind::boundary], 1U);
    EXPECT_EQ(count[ConstraintKind::hole], 1U);
    EXPECT_EQ(count[ConstraintKind::soft_breakline], 3U);  // split at the junction (40, 50)
    std::multiset<std::pair<std::pair<double, double>, std::pair<double, double>>> expected;
    for (const ConstrainedEdge& e : tin.constraints) {
        auto a = key(tin.vertices[e.a]);
        auto b = key(tin.vertices[e.b]);
        if (b < a) std::swap(a, b);
        expected.insert({a, b});
    }
    EXPECT_EQ(edges, expected);
}

}  // namespace
