// SPDX-License-Identifier: MIT
#include "dtm/algo/volume.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dtm/algo/validate.hpp"
#include "dtm/algo/volume_surfaces.hpp"
#include "support/solid_fixtures.hpp"

namespace {

using dtm::test::Square;

constexpr double rel = 1e-9;

void expect_rel(double actual, double expected, double tolerance = rel) {
    EXPECT_NEAR(actual, expected, tolerance * std::max(std::fabs(expected), 1.0))
        << "expected " << expected;
}

struct Site {
    const char* name;
    double x0;
    double y0;
};
class VolumeSolids : public ::testing::TestWithParam<Site> {};

TEST_P(VolumeSolids, PyramidOverPlaneIsAreaTimesHeightOverThree) {
    const Square sq{GetParam().x0, GetParam().y0, 80.0};
    const double h = 12.0;
    const dtm::Tin pyramid = dtm::test::frustum_tin(sq, h, 0.0, 300, 1);
    const double expected = sq.side * sq.side * h / 3.0;
    const dtm::VolumeResult plane = dtm::volume(pyramid, 0.0);
    expect_rel(plane.fill, expected);
    EXPECT_EQ(plane.cut, 0.0);
    expect_rel(plane.fill_area, sq.side * sq.side);
    // The same against a flat TIN whose triangles have nothing to do with the pyramid's.
    const dtm::Tin ground = dtm::test::plane_tin(sq, 0.0, 0.0, 0.0, 500, 2);
    const dtm::VolumeResult r = dtm::volume(pyramid, ground);
    expect_rel(r.fill, expected);
    EXPECT_EQ(r.cut, 0.0);
    expect_rel(r.overlap_area, sq.side * sq.side);
    EXPECT_EQ(r.top_only_area, 0.0);
    EXPECT_EQ(r.base_only_area, 0.0);
    // Each face of the pyramid rises h over a run of side / 2.
    const double slant = std::hypot(1.0, h / (sq.side / 2.0));
    expect_rel(r.fill_area_top_3d, sq.side * sq.side * slant);
    expect_rel(r.fill_area_base_3d, sq.side * sq.side);
    expect_rel(r.max_fill, h);
    // Swapped: the same volume as cut.
    const dtm::VolumeResult swapped = dtm::volume(ground, pyramid);
    expect_rel(swapped.cut, expected);
    EXPECT_EQ(swapped.fill, 0.0);
}

TEST_P(VolumeSolids, FrustumIsHeightThirdOfAreasAndTheirMean) {
    const Square sq{GetParam().x0, GetParam().y0, 60.0};
    const double h = 7.5;
    const double top_half = 12.0;
    const dtm::Tin frustum = dtm::test::frustum_tin(sq, h, top_half, 400, 3);
    const double a1 = sq.side * sq.side;
    const double a2 = 4.0 * top_half * top_half;
    const double expected = h / 3.0 * (a1 + a2 + std::sqrt(a1 * a2));
    const dtm::Tin ground = dtm::test::plane_tin(sq, -2.0, 0.0, 0.0, 300, 4);
    const dtm::VolumeResult r = dtm::volume(frustum, ground);
    expect_rel(r.fill, expected + 2.0 * a1);  // the ground is 2 below the frustum's foot
    EXPECT_EQ(r.cut, 0.0);
    expect_rel(dtm::volume(frustum, 0.0).fill, expected);
}

TEST_P(VolumeSolids, TwoCrossingPlanesSplitIntoCutAndFill) {
    const Square sq{GetParam().x0, GetParam().y0, 50.0};
    // top - base = k (x - xm), xm at 30 % of the side: fill east of xm, cut west of it.
    const double k = 0.4;
    const double xm = 0.3 * sq.side;
    const dtm::Tin top = dtm::test::plane_tin(sq, 100.0, 0.25, -0.1, 700, 5);
    const dtm::Tin base = dtm::test::plane_tin(sq, 100.0 + k * xm, 0.25 - k, -0.1, 600, 6);
    const dtm::VolumeResult r = dtm::volume(top, base);
    const double l = sq.side;
    expect_rel(r.fill, k * l * (l - xm) * (l - xm) / 2.0);
    expect_rel(r.cut, k * l * xm * xm / 2.0);
    expect_rel(r.fill_area, l * (l - xm));
    expect_rel(r.cut_area, l * xm);
    expect_rel(r.net(), r.fill - r.cut);
    expect_rel(r.fill_area_top_3d, l * (l - xm) * std::hypot(1.0, 0.25, 0.1));
    expect_rel(r.cut_area_base_3d, l * xm * std::hypot(1.0, 0.25 - k, 0.1));
}

INSTANTIATE_TEST_SUITE_P(Sites,
                         VolumeSolids,
                         ::testing::Values(Site{"local", 0.0, 0.0},
                                           Site{"sjtsk", -750123.25, -1050987.5}),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(Volume, PartialOverlapReportsTheAreasWhereOnlyOneSurfaceExists) {
    const dtm::Tin top = dtm::test::plane_tin({0.0, 0.0, 10.0}, 5.0, 0.0, 0.0, 50, 7);
    const dtm::Tin base = dtm::test::plane_tin({4.0, 3.0, 10.0}, 2.0, 0.0, 0.0, 60, 8);
    const dtm::VolumeResult r = dtm::volume(top, base);
    expect_rel(r.overlap_area, 6.0 * 7.0);
    expect_rel(r.top_only_area, 100.0 - 42.0);
    expect_rel(r.base_only_area, 100.0 - 42.0);
    expect_rel(r.fill, 42.0 * 3.0);
}

TEST(Volume, IdenticalSurfacesAreUnchangedEverywhere) {
    const dtm::Tin a = dtm::test::frustum_tin({-750000.0, -1050000.0, 40.0}, 3.0, 5.0, 200, 9);
    const dtm::VolumeResult r = dtm::volume(a, a);
    EXPECT_EQ(r.fill, 0.0);
    EXPECT_EQ(r.cut, 0.0);
    expect_rel(r.unchanged_area, 1600.0);
    EXPECT_EQ(r.pieces, a.triangles.size());
}

TEST(Volume, GridAgainstShiftedGridWithEdgesThroughVertices) {
    // Two regular grids, the second shifted by half a step in x: half the vertices of one lie on
    // edges of the other, many edges are collinear. Planes give the closed form.
    const auto grid = [](double dx, double z0, double gx) {
        dtm::TerrainInput in;
        for (int j = 0; j <= 20; ++j) {
            for (int i = -1; i <= 20; ++i) {
                const double x = std::clamp(i * 1.0 + dx, 0.0, 20.0);
                const double y = j * 1.0;
                in.points.push_back({x, y, z0 + gx * x});
            }
        }
        return dtm::triangulate(in).tin;
    };
    const dtm::Tin top = grid(0.0, 1.0, 0.5);
    const dtm::Tin base = grid(0.5, 0.0, 0.5);
    const dtm::VolumeResult r = dtm::volume(top, base);
    expect_rel(r.overlap_area, 400.0);
    expect_rel(r.fill, 400.0);
    EXPECT_EQ(r.cut, 0.0);
}

TEST(Volume, ResultDoesNotDependOnTheThreadCount) {
    const Square sq{-750000.0, -1050000.0, 100.0};
    const dtm::Tin top = dtm::test::frustum_tin(sq, 5.0, 10.0, 3000, 10);
    const dtm::Tin base = dtm::test::plane_tin(sq, 2.0, 0.01, 0.02, 2000, 11);
    const dtm::VolumeResult one = dtm::volume(top, base, {.threads = 1});
    const dtm::VolumeResult two = dtm::volume(top, base, {.threads = 2});
    EXPECT_EQ(one.fill, two.fill);
    EXPECT_EQ(one.cut, two.cut);
    EXPECT_EQ(one.fill_area, two.fill_area);
    EXPECT_EQ(one.pieces, two.pieces);
}

TEST(Volume, DisjointSurfacesHaveNoOverlap) {
    const dtm::Tin top = dtm::test::plane_tin({0.0, 0.0, 10.0}, 5.0, 0.0, 0.0, 20, 12);
    const dtm::Tin base = dtm::test::plane_tin({10.0, 0.0, 10.0}, 2.0, 0.0, 0.0, 20, 13);
    const dtm::VolumeResult r = dtm::volume(top, base);  // they share an edge only
    EXPECT_EQ(r.overlap_area, 0.0);
    EXPECT_EQ(r.pieces, 0U);
    expect_rel(r.top_only_area, 100.0);
}

}  // namespace

namespace {

TEST(VolumeSurfaces, StockpileOverItsSpannedFootIsThePyramid) {
    // A pyramid standing on a tilted plane: its foot spans the tilted plane exactly.
    const dtm::test::Square sq{-750000.0, -1050000.0, 40.0};
    const double h = 6.0;
    const auto z = [&](double x, double y) {
        return 200.0 + 0.05 * (x - sq.x0) - 0.02 * (y - sq.y0) +
               dtm::test::frustum_z(sq, h, 0.0, x, y);
    };
    const double cx = sq.x0 + 20.0;
    const double cy = sq.y0 + 20.0;
    const dtm::Tin pile = dtm::test::sampled_tin(sq, 200, 21, z,
                                                 {{{sq.x0, sq.y0}, {cx, cy}},
                                                  {{sq.x0 + 40.0, sq.y0}, {cx, cy}},
                                                  {{sq.x0 + 40.0, sq.y0 + 40.0}, {cx, cy}},
                                                  {{sq.x0, sq.y0 + 40.0}, {cx, cy}}});
    const dtm::Tin floor = dtm::spanned_base(pile);
    const dtm::VolumeResult r = dtm::volume(pile, floor);
    expect_rel(r.fill, 1600.0 * h / 3.0);
    EXPECT_NEAR(r.cut, 0.0, 1e-9);
    expect_rel(r.overlap_area, 1600.0);
}

TEST(VolumeSurfaces, ClippedToAPolygonKeepsTheSurfaceInsideIt) {
    const dtm::test::Square sq{-750000.0, -1050000.0, 40.0};
    const dtm::Tin pyramid = dtm::test::frustum_tin(sq, 8.0, 0.0, 300, 22);
    // The inner square of half the side, as the area, with a 4 x 4 hole in it.
    dtm::TerrainInput area;
    dtm::Polyline ring;
    for (const auto& [u, v] :
         std::vector<std::pair<double, double>>{{10, 10}, {30, 10}, {30, 30}, {10, 30}, {10, 10}}) {
        ring.points.push_back({sq.x0 + u, sq.y0 + v, 0.0});
    }
    area.boundaries.push_back(ring);
    dtm::Polyline hole;
    for (const auto& [u, v] :
         std::vector<std::pair<double, double>>{{12, 12}, {16, 12}, {16, 16}, {12, 16}, {12, 12}}) {
        hole.points.push_back({sq.x0 + u, sq.y0 + v, 0.0});
    }
    area.holes.push_back(hole);
    const dtm::Tin inner = dtm::clip_tin(pyramid, area);
    expect_rel(dtm::tin_area(inner), 400.0 - 16.0);
    // Above the level h / 2 = 4 the pyramid is the inner pyramid of volume 400 * 4 / 3; the hole
    // removes the part of it over [12, 16]^2, where the height is 8 (20 - r) / 20 with the
    // Chebyshev radius r from the centre (20, 20): between 4 and 6.4.
    const dtm::VolumeResult r = dtm::volume(inner, 4.0);
    const dtm::VolumeResult whole = dtm::volume(pyramid, 4.0);
    const dtm::VolumeResult hole_part = dtm::volume(dtm::clip_tin(pyramid,
                                                                  [&] {
                                                                      dtm::TerrainInput h;
                                                                      h.boundaries.push_back(hole);
                                                                      return h;
                                                                  }()),
                                                    4.0);
    expect_rel(whole.fill, 400.0 * 4.0 / 3.0);
    expect_rel(r.fill, whole.fill - hole_part.fill);
    expect_rel(r.fill_area + r.cut_area, 384.0);
}

}  // namespace
