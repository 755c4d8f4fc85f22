// SPDX-License-Identifier: MIT
// The PSLG pre-pass (algo/detail/segment_split.hpp): after it no two segments meet except at a
// shared endpoint (checked pair by pair against every other, with the exact predicates directly,
// not the grid), every input segment is still a chain of pieces, each crossing is counted once,
// and the result does not depend on the thread count. The special cases: T-junctions, overlaps,
// equal segments, several lines through one point, a crossing on an existing point, soft lines.
#include "algo/detail/segment_split.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "algo/detail/ghost_mesh.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

using geom::orient2d;

bool strictly_inside(const Point3& a, const Point3& b, const Point3& q) {
    return orient2d(a, b, q) == 0 && std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) &&
           std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y) && !(q.x == a.x && q.y == a.y) &&
           !(q.x == b.x && q.y == b.y);
}

/// Brute force over all pairs: the first pair that meets other than at one shared endpoint.
std::string first_touching_pair(const MergedInput& in) {
    const auto& v = in.vertices;
    for (std::size_t i = 0; i < in.segments.size(); ++i) {
        for (std::size_t j = i + 1; j < in.segments.size(); ++j) {
            const InputSegment &s = in.segments[i], &t = in.segments[j];
            const std::string name = std::to_string(i) + "/" + std::to_string(j);
            const std::set<VertexIndex> ends{s.a, s.b, t.a, t.b};
            if (ends.size() == 2) return name + " equal";
            for (const VertexIndex e : {t.a, t.b})
                if (strictly_inside(v[s.a], v[s.b], v[e])) return name + " T-junction";
            for (const VertexIndex e : {s.a, s.b})
                if (strictly_inside(v[t.a], v[t.b], v[e])) return name + " T-junction";
            if (ends.size() == 4 &&
                orient2d(v[s.a], v[s.b], v[t.a]) * orient2d(v[s.a], v[s.b], v[t.b]) < 0 &&
                orient2d(v[t.a], v[t.b], v[s.a]) * orient2d(v[t.a], v[t.b], v[s.b]) < 0) {
                return name + " crossing";
            }
        }
    }
    return "";
}

/// Segment a-b is a chain of pieces through vertices within @p tol of it.
bool chain_covers(const MergedInput& in, VertexIndex a, VertexIndex b, double tol) {
    const Point3 &pa = in.vertices[a], &pb = in.vertices[b];
    const double len = std::hypot(pb.x - pa.x, pb.y - pa.y);
    const auto near = [&](VertexIndex v) {
        const Point3& q = in.vertices[v];
        return std::abs((pb.x - pa.x) * (q.y - pa.y) - (pb.y - pa.y) * (q.x - pa.x)) / len <= tol;
    };
    std::multimap<VertexIndex, VertexIndex> next;
    for (const InputSegment& s : in.segments) {
        next.emplace(s.a, s.b);
        next.emplace(s.b, s.a);
    }
    std::set<VertexIndex> seen{a};
    std::vector<VertexIndex> stack{a};
    while (!stack.empty()) {
        const VertexIndex u = stack.back();
        stack.pop_back();
        if (u == b) return true;
        for (auto [it, end] = next.equal_range(u); it != end; ++it) {
            if (near(it->second) && seen.insert(it->second).second) stack.push_back(it->second);
        }
    }
    return false;
}

MergedInput input_of(std::vector<Point3> vertices, std::vector<InputSegment> segments) {
    MergedInput in;
    in.z_known.assign(vertices.size(), true);
    in.vertices = std::move(vertices);
    in.segments = std::move(segments);
    return in;
}

MergedInput random_segments(std::size_t count, std::uint64_t seed, double e, double n) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    std::vector<Point3> v;
    std::vector<InputSegment> s;
    for (std::size_t k = 0; k < count; ++k) {
        const auto a = static_cast<VertexIndex>(v.size());
        v.push_back({e + u(rng), n + u(rng), u(rng)});
        v.push_back({e + u(rng), n + u(rng), u(rng)});
        s.push_back({a, a + 1, constraint_breakline});
    }
    return input_of(std::move(v), std::move(s));
}

TEST(SplitSegments, RandomCrossingLinesEndFreeCoveredAndCountedAtSjtskMagnitudes) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
        MergedInput in = random_segments(120, seed, -750000.0, -1050000.0);
        const MergedInput original = in;
        std::size_t crossing_pairs = 0;
        for (std::size_t i = 0; i < original.segments.size(); ++i) {
            for (std::size_t j = i + 1; j < original.segments.size(); ++j) {
                const auto &s = original.segments[i], &t = original.segments[j];
                const auto& v = original.vertices;
                crossing_pairs +=
                    orient2d(v[s.a], v[s.b], v[t.a]) * orient2d(v[s.a], v[s.b], v[t.b]) < 0 &&
                    orient2d(v[t.a], v[t.b], v[s.a]) * orient2d(v[t.a], v[t.b], v[s.b]) < 0;
            }
        }
        const SegmentSplit split = split_segments(in, 0.001);
        SCOPED_TRACE("seed " + std::to_string(seed));
        EXPECT_TRUE(split.all_free);
        EXPECT_EQ(first_touching_pair(in), "");
        EXPECT_GT(crossing_pairs, 1000u);
        // Each crossing of the input is one; rounding may add a few between pieces near one.
        EXPECT_GE(split.crossings.size(), crossing_pairs);
        EXPECT_LE(split.crossings.size(), crossing_pairs + crossing_pairs / 100);
        EXPECT_EQ(in.vertices.size(), original.vertices.size() + split.crossings.size());
        for (const InputSegment& s : original.segments) {
            EXPECT_TRUE(chain_covers(in, s.a, s.b, 1e-6));
        }
        for (std::size_t v = original.vertices.size(); v < in.vertices.size(); ++v) {
            EXPECT_TRUE(in.z_known[v]);
        }
    }
}

TEST(SplitSegments, TheResultDoesNotDependOnTheThreadCount) {
    MergedInput one = random_segments(3000, 7, 0.0, 0.0);
    for (InputSegment& s : one.segments) {  // short segments: a grid of many cells
        one.vertices[s.b] = {(one.vertices[s.a].x + one.vertices[s.b].x * 0.02) / 1.02,
                             (one.vertices[s.a].y + one.vertices[s.b].y * 0.02) / 1.02, 1.0};
    }
    MergedInput two = one;
    tbb::task_arena(1).execute([&] { (void)split_segments(one, 0.001); });
    tbb::task_arena(2).execute([&] { (void)split_segments(two, 0.001); });
    ASSERT_EQ(one.vertices.size(), two.vertices.size());
    EXPECT_EQ(one.vertices, two.vertices);
    ASSERT_EQ(one.segments.size(), two.segments.size());
    for (std::size_t i = 0; i < one.segments.size(); ++i) {
        EXPECT_EQ(one.segments[i].a, two.segments[i].a);
        EXPECT_EQ(one.segments[i].b, two.segments[i].b);
    }
    EXPECT_GT(one.vertices.size(), 6000u);
    EXPECT_EQ(first_touching_pair(one), "");
}

TEST(SplitSegments, TJunctionsAndOverlapsSplitWithoutNewVerticesAndEqualPiecesMerge) {
    // 0-1 along y = 0 from 0 to 10; 2 (at 4, 0) starts a line up; 3-4 overlaps 0-1 from 6 to 14.
    MergedInput in =
        input_of({{0, 0, 0}, {10, 0, 10}, {4, 0, 4}, {4, 5, 4}, {6, 0, 6}, {14, 0, 14}},
                 {{0, 1, constraint_breakline},
                  {2, 3, constraint_breakline},
                  {4, 5, constraint_boundary},
                  {1, 0, constraint_hole}});  // equal to the first
    const SegmentSplit split = split_segments(in, 0.001);
    EXPECT_TRUE(split.all_free);
    EXPECT_TRUE(split.crossings.empty());
    EXPECT_EQ(in.vertices.size(), 6u);
    std::map<std::pair<VertexIndex, VertexIndex>, std::uint8_t> got;
    for (const InputSegment& s : in.segments)
        got[{std::min(s.a, s.b), std::max(s.a, s.b)}] = s.bits;
    const std::uint8_t line_hole = constraint_breakline | constraint_hole;
    const std::map<std::pair<VertexIndex, VertexIndex>, std::uint8_t> want{
        {{0, 2}, line_hole},
        {{2, 4}, line_hole},
        {{1, 4}, line_hole | constraint_boundary},  // 6..10: both lines and the boundary
        {{1, 5}, constraint_boundary},
        {{2, 3}, constraint_breakline}};
    EXPECT_EQ(got, want);
}

TEST(SplitSegments, LinesThroughOnePointMeetAtOneVertexAndAnExistingPointIsUsed) {
    // Three lines through (5, 5); a survey point 6 sits where two others cross, at (2, 8).
    MergedInput in = input_of({{0, 0, 1},
                               {10, 10, 1},
                               {0, 10, 3},
                               {10, 0, 3},
                               {5, 0, 9},
                               {5, 10, 9},
                               {2, 8, 7},
                               {0, 8, 1},
                               {4, 8, 1}},
                              {{0, 1, constraint_breakline},
                               {2, 3, constraint_breakline},
                               {4, 5, constraint_breakline},
                               {7, 8, constraint_breakline}});
    const SegmentSplit split = split_segments(in, 0.001);
    EXPECT_TRUE(split.all_free);
    EXPECT_EQ(split.crossings.size(), 4u);  // three pairs at (5, 5), one at (2, 8)
    ASSERT_EQ(in.vertices.size(), 10u);     // (5, 5) once; (2, 8) is point 6
    EXPECT_EQ(in.vertices[9].x, 5.0);
    EXPECT_EQ(in.vertices[9].y, 5.0);
    EXPECT_DOUBLE_EQ(in.vertices[9].z, 2.0);  // the first pair's mean: (1 + 3) / 2
    EXPECT_DOUBLE_EQ(in.vertices[6].z, 7.0);  // an existing point keeps its height
    std::size_t conflicts = 0;
    for (const Crossing& c : split.crossings) conflicts += c.conflict;
    EXPECT_EQ(conflicts, 4u);  // 1 against 3, 1 against 9, 3 against 9; 1 against 3 at (2, 8)
    EXPECT_EQ(in.segments.size(), 9u);
    EXPECT_EQ(first_touching_pair(in), "");
}

TEST(SplitSegments, ACrossingAtASliverOfAnAngleGetsAFiniteVertexNextToBothLines) {
    // The two direction vectors' cross product rounds to 0, but the exact predicates say the
    // segments cross: the intersection formula divides by zero.
    MergedInput in =
        input_of({{-0.25, -0.25, 1}, {0.75, 0.7499999999999999, 1}, {0, 0, 3}, {1 + 0x1p-52, 1, 3}},
                 {{0, 1, constraint_breakline}, {2, 3, constraint_breakline}});
    const SegmentSplit split = split_segments(in, 0.001);
    EXPECT_TRUE(split.all_free);
    ASSERT_EQ(split.crossings.size(), 1u);
    EXPECT_EQ(first_touching_pair(in), "");
    for (const Point3& v : in.vertices) {
        EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    }
    EXPECT_TRUE(chain_covers(in, 0, 1, 1e-12));
    EXPECT_TRUE(chain_covers(in, 2, 3, 1e-12));
}

TEST(SplitSegments, SoftLinesTakeTheHardLinesHeightsAndTwoSoftLinesLeaveItToTheSurface) {
    // Hard 0-1 (z 0 to 10) crossed by soft 2-3; soft 4-5 crosses soft 2-3; soft vertex 6 is on 0-1.
    MergedInput in = input_of({{0, 0, 0},
                               {10, 0, 10},
                               {2, -5, 0},
                               {2, 5, 0},
                               {0, 3, 0},
                               {4, 3, 0},
                               {7, 0, 0},
                               {7, -4, 0}},
                              {{0, 1, constraint_breakline},
                               {2, 3, constraint_soft},
                               {4, 5, constraint_soft},
                               {6, 7, constraint_soft}});
    in.z_known = {true, true, false, false, false, false, false, false};
    const SegmentSplit split = split_segments(in, 0.001);
    EXPECT_TRUE(split.all_free);
    ASSERT_EQ(in.vertices.size(), 10u);
    EXPECT_EQ(split.crossings.size(), 2u);
    for (const Crossing& c : split.crossings) EXPECT_FALSE(c.conflict);
    EXPECT_DOUBLE_EQ(in.vertices[8].x, 2.0);  // hard x soft at (2, 0): the hard line's 2
    EXPECT_DOUBLE_EQ(in.vertices[8].z, 2.0);
    EXPECT_TRUE(in.z_known[8]);
    EXPECT_FALSE(in.z_known[9]);  // soft x soft at (2, 3)
    EXPECT_TRUE(in.z_known[6]);   // soft vertex on the hard line: 7
    EXPECT_DOUBLE_EQ(in.vertices[6].z, 7.0);
    for (const InputSegment& s : in.segments) {  // every non-soft piece has known heights
        if (s.bits != constraint_soft) {
            EXPECT_TRUE(in.z_known[s.a] && in.z_known[s.b]);
        }
    }
}

}  // namespace
}  // namespace dtm::detail
