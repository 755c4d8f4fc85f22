// SPDX-License-Identifier: MIT
// Contours: every vertex on its level and on a TIN edge, per-level length equal to an
// independent per-triangle sum, rings closed, no crossings, vertices exactly on levels handled.
#include "dtm/algo/contour.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace {

using dtm::Contour;
using dtm::Point3;
using dtm::Tin;
using dtm::Triangle;

/// n x n jittered grid, spacing 1, z from @p height; cells whose centre is in @p hole are left out.
template <class F>
Tin grid_tin(int n, double jitter, std::uint32_t seed, F height, std::array<double, 4> hole = {}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter, jitter);
    Tin tin;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const double x = i + (i > 0 && i < n - 1 ? u(rng) : 0.0);
            const double y = j + (j > 0 && j < n - 1 ? u(rng) : 0.0);
            tin.vertices.push_back({x, y, height(x, y, rng)});
        }
    }
    const auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * n + i); };
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            if (i + 0.5 > hole[0] && i + 0.5 < hole[2] && j + 0.5 > hole[1] && j + 0.5 < hole[3]) {
                continue;
            }
            if ((i + j) % 2 == 0) {
                tin.triangles.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}, {}});
                tin.triangles.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}, {}});
            } else {
                tin.triangles.push_back({{id(i, j), id(i + 1, j), id(i, j + 1)}, {}});
                tin.triangles.push_back({{id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}, {}});
            }
        }
    }
    for (const Triangle& t : tin.triangles) {  // the fixture must be a valid TIN
        const Point3 &a = tin.vertices[t.v[0]], &b = tin.vertices[t.v[1]],
                     &c = tin.vertices[t.v[2]];
        EXPECT_GT(dtm::geom::orient2d(a, b, c), 0) << "fixture triangle is not counter-clockwise";
    }
    dtm::link_neighbours(tin);
    return tin;
}

Tin random_tin(std::uint32_t seed) {
    return grid_tin(16, 0.2, seed,
                    [](double x, double y, std::mt19937& rng) {
                        std::uniform_real_distribution<double> noise(-0.4, 0.4);
                        return 100.0 + 3.0 * std::sin(x / 2.5) + 2.0 * std::cos(y / 3.0) +
                               noise(rng);
                    },
                    {5, 6, 9, 10});
}

/// Heights on a 0.5 m lattice: many vertices lie exactly on the levels.
Tin integer_tin(std::uint32_t seed) {
    return grid_tin(14, 0.0, seed, [](double, double, std::mt19937& rng) {
        return std::floor(std::uniform_real_distribution<double>(0.0, 8.0)(rng)) * 0.5;
    });
}

double length(std::span<const Point3> line) {
    double sum = 0.0;
    for (std::size_t i = 1; i < line.size(); ++i) {
        sum += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
    }
    return sum;
}

std::map<double, double> length_per_level(const std::vector<Contour>& contours) {
    std::map<double, double> out;
    for (const Contour& c : contours) {
        out[c.level.value] += length(c.line);
    }
    return out;
}

/// Independent per-triangle sum: the level set of the linear surface on each triangle. A piece
/// lying along an edge (two vertices on the level) is counted once per edge, and only when a
/// triangle beside it goes below the level (a vertex on a level counts as slightly above it).
double independent_length(const Tin& tin, double level) {
    double sum = 0.0;
    std::set<std::pair<std::uint32_t, std::uint32_t>> along;
    for (const Triangle& t : tin.triangles) {
        std::vector<std::pair<double, double>> pts;
        std::vector<std::uint32_t> on;
        bool below = false;
        for (int e = 0; e < 3; ++e) {
            const Point3& p = tin.vertices[t.v[static_cast<std::size_t>(e)]];
            const Point3& q = tin.vertices[t.v[static_cast<std::size_t>((e + 1) % 3)]];
            below = below || p.z < level;
            if (p.z == level) {
                pts.emplace_back(p.x, p.y);
                on.push_back(t.v[static_cast<std::size_t>(e)]);
            } else if ((p.z < level && q.z > level) || (p.z > level && q.z < level)) {
                const double s = (level - p.z) / (q.z - p.z);
                pts.emplace_back(p.x + s * (q.x - p.x), p.y + s * (q.y - p.y));
            }
        }
        if (pts.size() != 2) {
            continue;  // a single touching vertex, or a flat triangle
        }
        if (on.size() == 2) {
            if (!below || !along.insert(std::minmax(on[0], on[1])).second) {
                continue;
            }
        }
        sum += std::hypot(pts[0].first - pts[1].first, pts[0].second - pts[1].second);
    }
    return sum;
}

void expect_vertices_on_levels_and_edges(const Tin& tin, const std::vector<Contour>& contours) {
    for (const Contour& c : contours) {
        for (const Point3& p : c.line) {
            ASSERT_EQ(p.z, c.level.value);
            bool on_edge = false;
            for (const Triangle& t : tin.triangles) {
                for (int e = 0; e < 3 && !on_edge; ++e) {
                    Point3 a = tin.vertices[t.v[static_cast<std::size_t>(e)]];
                    Point3 b = tin.vertices[t.v[static_cast<std::size_t>((e + 1) % 3)]];
                    if (a.z > b.z) {
                        std::swap(a, b);
                    }
                    if (!(a.z < p.z && p.z <= b.z)) {
                        continue;
                    }
                    const double s = (p.z - a.z) / (b.z - a.z);
                    on_edge = std::abs(a.x + s * (b.x - a.x) - p.x) < 1e-12 &&
                              std::abs(a.y + s * (b.y - a.y) - p.y) < 1e-12;
                }
            }
            ASSERT_TRUE(on_edge) << "level " << c.level.value << " point " << p.x << "," << p.y;
        }
    }
}

bool segments_meet(const Point3& p1, const Point3& p2, const Point3& q1, const Point3& q2) {
    using dtm::geom::orient2d;
    const int a = orient2d(p1, p2, q1), b = orient2d(p1, p2, q2);
    const int c = orient2d(q1, q2, p1), d = orient2d(q1, q2, p2);
    if (a == 0 && b == 0) {  // collinear: overlap of the boxes
        return std::max(std::min(p1.x, p2.x), std::min(q1.x, q2.x)) <=
                   std::min(std::max(p1.x, p2.x), std::max(q1.x, q2.x)) &&
               std::max(std::min(p1.y, p2.y), std::min(q1.y, q2.y)) <=
                   std::min(std::max(p1.y, p2.y), std::max(q1.y, q2.y));
    }
    return a * b <= 0 && c * d <= 0;
}

/// Counts pairs of segments of different contour lines that meet (lines of the same level may
/// touch at a shared point), and non-adjacent segments of one line that meet.
std::size_t crossing_count(const std::vector<Contour>& contours) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < contours.size(); ++i) {
        for (std::size_t j = i; j < contours.size(); ++j) {
            const auto& a = contours[i].line;
            const auto& b = contours[j].line;
            for (std::size_t s = 0; s + 1 < a.size(); ++s) {
                for (std::size_t t = (i == j ? s + 2 : 0); t + 1 < b.size(); ++t) {
                    if (i == j && contours[i].closed && s == 0 && t + 2 == b.size()) {
                        continue;  // first and last segment of a ring share the closing point
                    }
                    if (!segments_meet(a[s], a[s + 1], b[t], b[t + 1])) {
                        continue;
                    }
                    // Lines of one level may touch where they share a point (a TIN vertex
                    // exactly on the level, e.g. a saddle); anything else is a crossing.
                    const bool shared_end = a[s] == b[t] || a[s] == b[t + 1] || a[s + 1] == b[t] ||
                                            a[s + 1] == b[t + 1];
                    const bool same_level = contours[i].level.value == contours[j].level.value;
                    count += (same_level && shared_end) ? 0 : 1;
                }
            }
        }
    }
    return count;
}

TEST(ContourLevels, AreBasePlusMultiplesOfTheIntervalStrictlyAboveZmin) {
    const auto levels =
        dtm::contour_levels(10.0, 13.0, {.interval = 1.0, .base = 0.5, .index_every = 2});
    ASSERT_EQ(levels.size(), 3U);
    EXPECT_EQ(levels[0].value, 10.5);
    EXPECT_EQ(levels[2].value, 12.5);
    EXPECT_EQ(levels[0].number, 10);
    EXPECT_TRUE(levels[0].index);
    EXPECT_FALSE(levels[1].index);
    const auto on_zmin = dtm::contour_levels(10.0, 12.0, {.interval = 1.0});
    ASSERT_EQ(on_zmin.size(), 2U);  // 10 is not cut (zmin < level), 12 is (level <= zmax)
    EXPECT_EQ(on_zmin[0].value, 11.0);
    EXPECT_EQ(on_zmin[1].value, 12.0);
    const auto negative = dtm::contour_levels(-3.0, -1.0, {.interval = 1.0, .index_every = 2});
    ASSERT_EQ(negative.size(), 2U);
    EXPECT_TRUE(negative[0].index);  // -2
    EXPECT_FALSE(negative[1].index);
}

TEST(ContourLevels, FixedLevelsOverrideTheIntervalAndAbsurdCountsAreRejected) {
    const auto levels = dtm::contour_levels(0.0, 10.0, {.fixed_levels = {7.0, 2.0, 20.0, 2.0}});
    ASSERT_EQ(levels.size(), 2U);
    EXPECT_EQ(levels[0].value, 2.0);
    EXPECT_EQ(levels[1].value, 7.0);
    EXPECT_THROW((void)dtm::contour_levels(0.0, 1e9, {.interval = 0.001}), dtm::UsageError);
    EXPECT_THROW((void)dtm::contour_levels(0.0, 1.0, {.interval = 0.0}), dtm::UsageError);
}

TEST(Contour, EveryVertexIsOnItsLevelAndOnATinEdge) {
    const Tin tin = random_tin(11);
    const auto contours = dtm::contour(tin, {.interval = 0.5});
    ASSERT_GT(contours.size(), 10U);
    expect_vertices_on_levels_and_edges(tin, contours);
}

TEST(Contour, LengthPerLevelEqualsAnIndependentPerTriangleSum) {
    for (const Tin& tin : {random_tin(3), integer_tin(5)}) {
        const auto contours = dtm::contour(tin, {.interval = 0.5});
        const auto lengths = length_per_level(contours);
        for (double level = -1.0; level <= 106.0; level += 0.5) {
            const double expected = independent_length(tin, level);
            const double got = lengths.contains(level) ? lengths.at(level) : 0.0;
            ASSERT_NEAR(got, expected, 1e-9 * (1.0 + expected)) << "level " << level;
        }
    }
}

TEST(Contour, VerticesExactlyOnLevelsGiveNoZeroLengthPartsNoDoubledPiecesAndNoGaps) {
    const Tin tin = integer_tin(9);
    const auto contours = dtm::contour(tin, {.interval = 0.5});
    expect_vertices_on_levels_and_edges(tin, contours);
    std::set<std::tuple<double, double, double, double, double>> pieces;
    for (const Contour& c : contours) {
        for (std::size_t i = 1; i < c.line.size(); ++i) {
            const Point3 &a = c.line[i - 1], &b = c.line[i];
            ASSERT_FALSE(a.x == b.x && a.y == b.y) << "zero-length part at level " << c.level.value;
            const auto key =
                std::min(std::tuple(a.x, a.y, b.x, b.y, a.z), std::tuple(b.x, b.y, a.x, a.y, a.z));
            ASSERT_TRUE(pieces.insert(key).second) << "doubled piece at level " << c.level.value;
        }
    }
}

TEST(Contour, RidgeExactlyOnALevelGivesOneLineAlongIt) {
    // Column x = 2 is a ridge at z = 10; everything else is lower.
    Tin tin = grid_tin(5, 0.0, 1,
                       [](double x, double, std::mt19937&) { return 10.0 - std::abs(x - 2.0); });
    const auto contours = dtm::contour(tin, {.fixed_levels = {10.0}});
    ASSERT_EQ(contours.size(), 1U);
    EXPECT_FALSE(contours[0].closed);
    EXPECT_DOUBLE_EQ(length(contours[0].line), 4.0);
    for (const Point3& p : contours[0].line) {
        EXPECT_EQ(p.x, 2.0);
    }
}

TEST(Contour, HillGivesClosedClockwiseRingsWithHigherGroundOnTheRight) {
    const Tin tin = grid_tin(15, 0.3, 2, [](double x, double y, std::mt19937&) {
        return 50.0 - std::hypot(x - 7.1, y - 6.9);
    });
    const auto contours = dtm::contour(tin, {.interval = 1.0});
    std::size_t rings = 0;
    for (const Contour& c : contours) {
        if (!c.closed) {
            continue;
        }
        ++rings;
        EXPECT_EQ(c.line.front(), c.line.back());
        double area2 = 0.0;
        for (std::size_t i = 1; i < c.line.size(); ++i) {
            area2 += c.line[i - 1].x * c.line[i].y - c.line[i].x * c.line[i - 1].y;
        }
        EXPECT_LT(area2, 0.0) << "level " << c.level.value;
    }
    EXPECT_GE(rings, 5U);
}

TEST(Contour, OpenLinesEndOnTheBorderOfTheTin) {
    const Tin tin = random_tin(4);  // has a hole: lines end on the hull or on the hole's edges
    for (const Contour& c : dtm::contour(tin, {.interval = 0.25})) {
        if (c.closed) {
            EXPECT_EQ(c.line.front(), c.line.back());
            continue;
        }
        for (const Point3* end : {&c.line.front(), &c.line.back()}) {
            const bool on_hull = end->x == 0.0 || end->x == 15.0 || end->y == 0.0 || end->y == 15.0;
            const bool on_hole = end->x >= 4.6 && end->x <= 9.4 && end->y >= 5.6 && end->y <= 10.4;
            EXPECT_TRUE(on_hull || on_hole) << end->x << "," << end->y;
        }
    }
}

TEST(Contour, LinesOfDifferentLevelsNeverIntersect) {
    for (std::uint32_t seed : {1U, 2U}) {
        const Tin tin = random_tin(seed);
        EXPECT_EQ(crossing_count(dtm::contour(tin, {.interval = 0.25})), 0U);
    }
}

/// Height of the TIN surface at (x, y), or NaN outside.
double surface(const Tin& tin, double x, double y) {
    for (const Triangle& t : tin.triangles) {
        const Point3 &a = tin.vertices[t.v[0]], &b = tin.vertices[t.v[1]],
                     &c = tin.vertices[t.v[2]];
        const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        const double wb = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
        const double wc = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
        if (wb >= -1e-12 && wc >= -1e-12 && wb + wc <= 1 + 1e-12) {
            return (1 - wb - wc) * a.z + wb * b.z + wc * c.z;
        }
    }
    return std::nan("");
}

TEST(Contour, SmoothedLinesStayInTheirHeightBandAndNeverIntersect) {
    const Tin tin = random_tin(6);
    const auto raw = dtm::contour(tin, {.interval = 0.1});
    const auto smooth = dtm::contour(tin, {.interval = 0.1, .smooth = 3});
    EXPECT_EQ(crossing_count(smooth), 0U);
    std::size_t moved = 0, points = 0;
    for (const Contour& c : smooth) {
        for (const Point3& p : c.line) {
            const double z = surface(tin, p.x, p.y);
            ASSERT_FALSE(std::isnan(z)) << "smoothed point left the TIN";
            ASSERT_LT(std::abs(z - c.level.value), 0.05) << "left the level's band";
            EXPECT_EQ(p.z, c.level.value);
            moved += std::abs(z - c.level.value) > 1e-9 ? 1 : 0;
            ++points;
        }
    }
    EXPECT_GT(points, 2 * raw.size());
    EXPECT_GT(moved, points / 4);  // smoothing did something
}

class CollectingSink final : public dtm::ContourSink {
public:
    void add(const dtm::ContourLevel& level, std::span<const Point3> line, bool closed) override {
        out.push_back({level, {line.begin(), line.end()}, closed});
    }
    std::vector<Contour> out;
};

TEST(Contour, LevelRangesTracedApartConcatenateToTheWholeRun) {
    const Tin tin = random_tin(9);
    const dtm::ContourOptions options{.interval = 0.25, .smooth = 1, .threads = 1};
    CollectingSink whole;
    dtm::contour(tin, options, whole);
    double zmin = 1e300, zmax = -1e300;
    for (const Point3& p : tin.vertices) {
        zmin = std::min(zmin, p.z);
        zmax = std::max(zmax, p.z);
    }
    const std::vector<dtm::ContourLevel> levels = dtm::contour_levels(zmin, zmax, options);
    ASSERT_GT(levels.size(), 5U);
    CollectingSink pieces;
    const std::size_t cuts[] = {0, 1, 2, levels.size() / 2, levels.size() - 1, levels.size()};
    for (std::size_t i = 0; i + 1 < std::size(cuts); ++i) {
        dtm::contour_level_range(tin, levels, cuts[i], cuts[i + 1], options, pieces);
    }
    dtm::contour_level_range(tin, levels, 3, 3, options, pieces);  // empty range: nothing
    ASSERT_EQ(pieces.out.size(), whole.out.size());
    for (std::size_t i = 0; i < whole.out.size(); ++i) {
        EXPECT_EQ(pieces.out[i].line, whole.out[i].line);
        EXPECT_EQ(pieces.out[i].level.number, whole.out[i].level.number);
        EXPECT_EQ(pieces.out[i].closed, whole.out[i].closed);
    }
}

TEST(Contour, OutputIsInLevelOrderAndIndependentOfTheThreadCount) {
    const Tin tin = random_tin(8);
    CollectingSink one, all;
    dtm::contour(tin, {.interval = 0.25, .threads = 1}, one);
    dtm::contour(tin, {.interval = 0.25, .threads = 0}, all);
    ASSERT_EQ(one.out.size(), all.out.size());
    for (std::size_t i = 0; i < one.out.size(); ++i) {
        EXPECT_EQ(one.out[i].line, all.out[i].line);
        if (i > 0) {
            EXPECT_LE(one.out[i - 1].level.value, one.out[i].level.value);
        }
    }
}

}  // namespace

#include "dtm/algo/triangulate.hpp"

namespace {

TEST(Contour, TriangulatedSurveyWithBreaklineAndHoleKeepsAllInvariants) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(0.0, 40.0);
    dtm::TerrainInput input;
    for (int i = 0; i < 600; ++i) {
        const double x = u(rng), y = u(rng);
        // heights on a centimetre lattice: many vertices land exactly on 0.25 m levels
        input.points.push_back(
            {x, y, std::round(100.0 * (50.0 + 3.0 * std::sin(x / 6.0) + 0.1 * y)) / 100.0});
    }
    input.breaklines.push_back({{{5, 5, 52.0}, {35, 30, 51.5}}, false, "ridge"});
    input.holes.push_back(
        {{{15, 25, 0}, {25, 25, 0}, {25, 35, 0}, {15, 35, 0}, {15, 25, 0}}, true, "hole"});
    const Tin tin = dtm::triangulate(input).tin;
    const auto contours = dtm::contour(tin, {.interval = 0.25});
    ASSERT_GT(contours.size(), 20U);
    expect_vertices_on_levels_and_edges(tin, contours);
    const auto lengths = length_per_level(contours);
    for (const auto& [level, got] : lengths) {
        EXPECT_NEAR(got, independent_length(tin, level), 1e-9 * (1.0 + got)) << level;
    }
    EXPECT_EQ(crossing_count(contours), 0U);
}

}  // namespace

namespace {

TEST(Contour, CancellationFromTheProgressCallbackThrowsCancelled) {
    const Tin tin = random_tin(12);
    const dtm::Progress stop([](double fraction, std::string_view) { return fraction < 0.3; });
    EXPECT_THROW((void)dtm::contour(tin, {.interval = 0.05}, stop), dtm::Cancelled);
}

}  // namespace
