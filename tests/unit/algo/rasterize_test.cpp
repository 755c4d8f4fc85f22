// SPDX-License-Identifier: MIT
// Rasterisation: values equal a brute-force barycentric evaluation at cell centres, NoData
// exactly outside the triangles, every centre owned by one triangle, streaming in row order.
#include "dtm/algo/rasterize.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>

#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace {

using dtm::Point3;
using dtm::Tin;
using dtm::Triangle;

/// A (jittered) regular grid of n x n vertices with spacing h, split into triangles with
/// alternating diagonals; triangles whose centroid falls in @p hole (x0,y0,x1,y1 relative to the
/// origin) are left out.
Tin grid_tin(double ox,
             double oy,
             int n,
             double h,
             double jitter,
             std::uint32_t seed,
             std::array<double, 4> hole = {0, 0, 0, 0}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter, jitter);
    Tin tin;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const double x = i * h + (i > 0 && i < n - 1 ? u(rng) : 0.0);
            const double y = j * h + (j > 0 && j < n - 1 ? u(rng) : 0.0);
            tin.vertices.push_back(
                {ox + x, oy + y, 200.0 + 10.0 * std::sin(x / 7.0) * std::cos(y / 5.0) + 0.1 * x});
        }
    }
    const auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * n + i); };
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            const double cx = (i + 0.5) * h, cy = (j + 0.5) * h;
            if (cx > hole[0] && cx < hole[2] && cy > hole[1] && cy < hole[3]) {
                continue;
            }
            Triangle a, b;
            if ((i + j) % 2 == 0) {
                a.v = {id(i, j), id(i + 1, j), id(i + 1, j + 1)};
                b.v = {id(i, j), id(i + 1, j + 1), id(i, j + 1)};
            } else {
                a.v = {id(i, j), id(i + 1, j), id(i, j + 1)};
                b.v = {id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
            }
            tin.triangles.push_back(a);
            tin.triangles.push_back(b);
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

/// Brute force: the first triangle containing (x, y) (closed, exact test) and its barycentric
/// interpolation in long double; nullopt outside every triangle.
std::optional<double> brute_force(const Tin& tin, double x, double y) {
    for (const Triangle& t : tin.triangles) {
        const Point3& a = tin.vertices[t.v[0]];
        const Point3& b = tin.vertices[t.v[1]];
        const Point3& c = tin.vertices[t.v[2]];
        if (dtm::geom::orient2d(a.x, a.y, b.x, b.y, x, y) < 0 ||
            dtm::geom::orient2d(b.x, b.y, c.x, c.y, x, y) < 0 ||
            dtm::geom::orient2d(c.x, c.y, a.x, a.y, x, y) < 0) {
            continue;
        }
        using L = long double;
        const L det = (L(b.x) - a.x) * (L(c.y) - a.y) - (L(c.x) - a.x) * (L(b.y) - a.y);
        const L wb = ((L(x) - a.x) * (L(c.y) - a.y) - (L(c.x) - a.x) * (L(y) - a.y)) / det;
        const L wc = ((L(b.x) - a.x) * (L(y) - a.y) - (L(x) - a.x) * (L(b.y) - a.y)) / det;
        return static_cast<double>((1 - wb - wc) * a.z + wb * b.z + wc * c.z);
    }
    return std::nullopt;
}

void expect_matches_brute_force(const Tin& tin, const dtm::Grid& grid) {
    std::size_t inside = 0, outside = 0;
    for (std::size_t r = 0; r < grid.spec.rows; ++r) {
        for (std::size_t c = 0; c < grid.spec.cols; ++c) {
            const auto expected = brute_force(tin, grid.spec.center_x(c), grid.spec.center_y(r));
            if (expected) {
                ++inside;
                ASSERT_NEAR(grid.at(r, c), *expected, 2e-5 * std::abs(*expected)) << r << "," << c;
            } else {
                ++outside;
                ASSERT_EQ(grid.at(r, c), grid.nodata) << r << "," << c;
            }
        }
    }
    EXPECT_GT(inside, 0U);
    EXPECT_GT(outside, 0U);
}

TEST(Rasterize, ValuesEqualBruteForceBarycentricAndNoDataOutsideAtSjtskOffsets) {
    const Tin tin = grid_tin(-750'123.25, -1'050'321.75, 14, 3.0, 0.9, 7, {10, 12, 22, 26});
    dtm::Box2 box{-750'126.0, -1'050'325.0, -750'080.0, -1'050'280.0};  // wider than the TIN
    const dtm::Grid grid = dtm::rasterize(tin, dtm::extent_grid_spec(box, 0.37), {.nodata = -1.0F});
    expect_matches_brute_force(tin, grid);
}

TEST(Rasterize, CentresOnVerticesAndEdgesGetExactValues) {
    // Vertices sit exactly on cell centres: every centre is on a vertex or an edge of the TIN.
    const Tin tin = grid_tin(0.5, 0.5, 9, 2.0, 0.0, 1);
    const dtm::GridSpec spec{.xmin = 0.0, .ymax = 18.0, .cell = 1.0, .cols = 18, .rows = 18};
    const dtm::Grid grid = dtm::rasterize(tin, spec);
    expect_matches_brute_force(tin, grid);
    for (const Point3& v : tin.vertices) {
        const auto c = static_cast<std::size_t>(v.x - 0.5);
        const auto r = static_cast<std::size_t>(17.5 - v.y);
        EXPECT_EQ(grid.at(r, c), static_cast<float>(v.z));
    }
}

TEST(Rasterize, EveryInteriorCellCentreIsOwnedByExactlyOneTriangle) {
    const Tin tin = grid_tin(0.5, 0.5, 9, 2.0, 0.0, 1, {5, 5, 9, 9});
    const dtm::GridSpec spec{.xmin = 0.0, .ymax = 18.0, .cell = 1.0, .cols = 18, .rows = 18};
    std::vector<int> owners(spec.cell_count(), 0);
    for (const Triangle& t : tin.triangles) {
        Tin single{tin.vertices, {t}, {}};  // keeps t's neighbour links: the tie rule sees them
        const dtm::Grid g = dtm::rasterize(single, spec, {.nodata = -1.0F});
        for (std::size_t k = 0; k < g.values.size(); ++k) {
            owners[k] += g.values[k] != -1.0F ? 1 : 0;
        }
    }
    const dtm::Grid whole = dtm::rasterize(tin, spec, {.nodata = -1.0F});
    std::size_t shared = 0;
    for (std::size_t r = 0; r < spec.rows; ++r) {
        for (std::size_t c = 0; c < spec.cols; ++c) {
            const double x = spec.center_x(c), y = spec.center_y(r);
            const bool border = x == 0.5 || x == 16.5 || y == 0.5 || y == 16.5 ||
                                (x >= 4.5 && x <= 8.5 && y >= 4.5 && y <= 8.5);
            const int n = owners[r * spec.cols + c];
            if (whole.values[r * spec.cols + c] == -1.0F) {
                EXPECT_EQ(n, 0);
            } else if (border) {
                EXPECT_GE(n, 1) << r << "," << c;
            } else {
                EXPECT_EQ(n, 1) << r << "," << c;
                ++shared;
            }
        }
    }
    EXPECT_GT(shared, 100U);
}

TEST(Rasterize, ThreadCountAndBandHeightDoNotChangeTheResult) {
    const Tin tin = grid_tin(1000.0, 2000.0, 30, 1.7, 0.35, 3, {10, 10, 20, 30});
    const dtm::GridSpec spec = dtm::snapped_grid_spec(dtm::tin_bounds(tin), 0.25);
    const dtm::Grid a = dtm::rasterize(tin, spec, {.band_rows = 1, .threads = 1});
    const dtm::Grid b = dtm::rasterize(tin, spec, {.band_rows = 0, .threads = 0});
    const dtm::Grid c = dtm::rasterize(tin, spec, {.band_rows = 7, .threads = 2});
    EXPECT_EQ(a.values, b.values);
    EXPECT_EQ(a.values, c.values);
}

TEST(Rasterize, RowWindowsStitchedTogetherEqualTheWholeRaster) {
    const Tin tin = grid_tin(-750'000.0, -1'050'000.0, 25, 2.0, 0.0, 9, {10, 10, 20, 30});
    const dtm::GridSpec spec = dtm::snapped_grid_spec(dtm::tin_bounds(tin), 0.5);
    const dtm::Grid whole = dtm::rasterize(tin, spec, {.nodata = -1.0F});
    for (const std::size_t parts : {2U, 3U, 7U, 200U}) {
        dtm::Grid stitched = whole;
        std::fill(stitched.values.begin(), stitched.values.end(), 5.0F);
        for (std::size_t k = 0; k < parts; ++k) {
            const std::size_t first = k * spec.rows / parts, end = (k + 1) * spec.rows / parts;
            if (first == end) continue;
            const dtm::Grid part = dtm::rasterize(
                tin, spec,
                {.nodata = -1.0F, .band_rows = 3, .first_row = first, .row_count = end - first});
            std::copy(part.values.begin() + static_cast<std::ptrdiff_t>(first * spec.cols),
                      part.values.begin() + static_cast<std::ptrdiff_t>(end * spec.cols),
                      stitched.values.begin() + static_cast<std::ptrdiff_t>(first * spec.cols));
        }
        EXPECT_EQ(stitched.values, whole.values) << parts << " windows";
    }
}

TEST(Rasterize, VertexNumbersAndTriangleOrderDoNotChangeABit) {
    // Vertices on cell centres and a 1:1 lattice: many centres on edges, where the value is
    // interpolated from one end; the end is chosen by position, so renumbering changes nothing.
    const Tin tin = grid_tin(0.5, 0.5, 13, 2.0, 0.0, 1);
    Tin permuted = tin;
    std::vector<std::uint32_t> to(tin.vertices.size());
    std::iota(to.begin(), to.end(), 0U);
    std::mt19937 rng(11);
    std::shuffle(to.begin(), to.end(), rng);
    for (std::size_t v = 0; v < to.size(); ++v) permuted.vertices[to[v]] = tin.vertices[v];
    for (Triangle& t : permuted.triangles) {
        for (auto& v : t.v) v = to[v];
    }
    std::reverse(permuted.triangles.begin(), permuted.triangles.end());
    dtm::link_neighbours(permuted);
    const dtm::GridSpec spec{.xmin = 0.375, .ymax = 24.625, .cell = 0.25, .cols = 96, .rows = 96};
    EXPECT_EQ(dtm::rasterize(tin, spec).values, dtm::rasterize(permuted, spec).values);
}

class RecordingSink final : public dtm::GridSink {
public:
    void write_rows(std::size_t first_row,
                    std::size_t row_count,
                    std::span<const float> values) override {
        calls.push_back({first_row, row_count});
        sizes.push_back(values.size());
    }
    std::vector<std::pair<std::size_t, std::size_t>> calls;
    std::vector<std::size_t> sizes;
};

TEST(Rasterize, StreamsConsecutiveBandsNorthToSouth) {
    const Tin tin = grid_tin(0.0, 0.0, 10, 1.0, 0.2, 5);
    const dtm::GridSpec spec{.xmin = 0.0, .ymax = 9.0, .cell = 0.1, .cols = 90, .rows = 90};
    RecordingSink sink;
    dtm::rasterize(tin, spec, {.band_rows = 8}, sink);
    std::size_t next = 0;
    for (std::size_t i = 0; i < sink.calls.size(); ++i) {
        EXPECT_EQ(sink.calls[i].first, next);
        EXPECT_LE(sink.calls[i].second, 8U);
        EXPECT_EQ(sink.sizes[i], sink.calls[i].second * spec.cols);
        next += sink.calls[i].second;
    }
    EXPECT_EQ(next, spec.rows);
}

TEST(Rasterize, SnappedSpecCoversTheBoxWithEdgesOnCellMultiples) {
    const dtm::Box2 box{-750'000.3, -1'050'000.8, -749'990.1, -1'049'995.0};
    const dtm::GridSpec s = dtm::snapped_grid_spec(box, 0.5);
    EXPECT_EQ(s.xmin, -750'000.5);
    EXPECT_EQ(s.ymax, -1'049'995.0);
    EXPECT_EQ(s.cols, 21U);
    EXPECT_EQ(s.rows, 12U);
    EXPECT_LE(s.xmin, box.xmin);
    EXPECT_GE(s.xmax(), box.xmax);
    EXPECT_LE(s.ymin(), box.ymin);
}

TEST(Rasterize, SnappedSpecCoversTheBoxForCellSizesThatAreNotBinaryFractions) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1000.0, 1000.0);
    for (const double cell : {0.1, 0.3, 0.7, 1.1, 2.5}) {
        for (int i = 0; i < 200; ++i) {
            const double x = -750'000.0 + u(rng), y = -1'050'000.0 + u(rng);
            const dtm::Box2 box{x, y, x + std::abs(u(rng)), y + std::abs(u(rng))};
            const dtm::GridSpec s = dtm::snapped_grid_spec(box, cell);
            ASSERT_LE(s.xmin, box.xmin);
            ASSERT_GE(s.xmax(), box.xmax);
            ASSERT_LE(s.ymin(), box.ymin);
            ASSERT_GE(s.ymax, box.ymax);
            ASSERT_LT(s.xmax() - box.xmax, cell * 1.000001 + (box.xmin - s.xmin));
        }
    }
}

TEST(Rasterize, ExtentSpecUsesTheExtentAsOuterEdges) {
    const dtm::GridSpec s = dtm::extent_grid_spec({0.0, 0.0, 2000.0, 1000.0}, 1.0);
    EXPECT_EQ(s.cols, 2000U);
    EXPECT_EQ(s.rows, 1000U);
    EXPECT_EQ(s.center_x(0), 0.5);
    EXPECT_EQ(s.center_y(0), 999.5);
    const dtm::GridSpec t = dtm::extent_grid_spec({0.0, 0.0, 10.2, 10.0}, 1.0);
    EXPECT_EQ(t.cols, 11U);  // the eastern edge moves out to a whole cell
}

}  // namespace

#include "dtm/algo/triangulate.hpp"

namespace {

TEST(Rasterize, TriangulatedSurveyWithAHoleMatchesBruteForceAndIsNoDataInTheHole) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0.0, 60.0);
    dtm::TerrainInput input;
    for (int i = 0; i < 1500; ++i) {
        const double x = u(rng), y = u(rng);
        input.points.push_back(
            {-750'000.0 + x, -1'050'000.0 + y, 300.0 + std::sin(x / 9.0) * 5.0 + 0.2 * y});
    }
    const auto p = [](double x, double y) {
        return Point3{-750'000.0 + x, -1'050'000.0 + y, 305.0};
    };
    input.holes.push_back({{p(20, 20), p(40, 22), p(35, 41), p(21, 38), p(20, 20)}, true, "hole"});
    const Tin tin = dtm::triangulate(input).tin;
    ASSERT_GT(tin.triangles.size(), 2000U);
    const dtm::GridSpec spec = dtm::snapped_grid_spec(dtm::tin_bounds(tin), 0.7);
    const dtm::Grid grid = dtm::rasterize(tin, spec);
    expect_matches_brute_force(tin, grid);
    // The centre of the hole is NoData, a point well outside it has data.
    const auto col = [&](double x) {
        return static_cast<std::size_t>((-750'000.0 + x - spec.xmin) / spec.cell);
    };
    const auto row = [&](double y) {
        return static_cast<std::size_t>((spec.ymax - (-1'050'000.0 + y)) / spec.cell);
    };
    EXPECT_TRUE(grid.is_nodata(row(30), col(30)));
    EXPECT_FALSE(grid.is_nodata(row(10), col(10)));
}

}  // namespace

namespace {

TEST(Rasterize, CancellationFromTheProgressCallbackThrowsCancelled) {
    const Tin tin = grid_tin(0.0, 0.0, 20, 1.0, 0.2, 9);
    const dtm::GridSpec spec{.xmin = 0.0, .ymax = 19.0, .cell = 0.05, .cols = 380, .rows = 380};
    const dtm::Progress stop([](double fraction, std::string_view) { return fraction < 0.3; });
    EXPECT_THROW((void)dtm::rasterize(tin, spec, {.band_rows = 4}, stop), dtm::Cancelled);
}

}  // namespace
