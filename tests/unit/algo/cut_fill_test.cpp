// SPDX-License-Identifier: MIT
#include "dtm/algo/cut_fill.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dtm/algo/difference_surface.hpp"
#include "dtm/algo/tin_topology.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/algo/volume.hpp"
#include "support/solid_fixtures.hpp"

namespace {

using dtm::test::Square;

double length(const dtm::ZeroLine& line) {
    double sum = 0.0;
    for (std::size_t i = 1; i < line.points.size(); ++i) {
        sum += std::hypot(line.points[i].x - line.points[i - 1].x,
                          line.points[i].y - line.points[i - 1].y);
    }
    return sum;
}

TEST(DifferenceSurface, IsAValidTinWhoseVolumeIsTheNetVolume) {
    const Square sq{-750000.0, -1050000.0, 60.0};
    const dtm::Tin top = dtm::test::frustum_tin(sq, 6.0, 8.0, 400, 1);
    const dtm::Tin base = dtm::test::plane_tin(sq, 2.0, 0.02, -0.03, 300, 2);
    const dtm::TinOverlay overlay(top, base);
    const dtm::DifferenceSurface diff = dtm::difference_surface(overlay);
    const dtm::CheckReport check = dtm::verify_topology(diff.tin);
    EXPECT_TRUE(check.ok()) << check.text();
    const dtm::VolumeResult v = dtm::volume(top, base);
    const dtm::VolumeResult flat = dtm::volume(diff.tin, 0.0);
    EXPECT_NEAR(flat.fill, v.fill, 1e-9 * v.fill);
    EXPECT_NEAR(flat.cut, v.cut, 1e-9 * v.cut);
    EXPECT_NEAR(dtm::tin_area(diff.tin), v.overlap_area, 1e-9 * v.overlap_area);
    ASSERT_EQ(diff.top_z.size(), diff.tin.vertices.size());
    // One thread or two: the same TIN, vertex for vertex.
    const dtm::TinOverlay one(top, base, {.threads = 1});
    const dtm::DifferenceSurface again = dtm::difference_surface(one);
    EXPECT_EQ(again.tin.vertices, diff.tin.vertices);
}

TEST(CutFill, CrossingPlanesGiveOneFillAndOneCutRegionAndAStraightZeroLine) {
    const Square sq{1000.0, 2000.0, 50.0};
    const double k = 0.4;
    const double xm = 0.3 * sq.side;
    const dtm::Tin top = dtm::test::plane_tin(sq, 100.0, 0.25, -0.1, 300, 5);
    const dtm::Tin base = dtm::test::plane_tin(sq, 100.0 + k * xm, 0.25 - k, -0.1, 200, 6);
    const dtm::TinOverlay overlay(top, base);
    const dtm::CutFillMap map = dtm::cut_fill_map(dtm::difference_surface(overlay));
    ASSERT_EQ(map.regions.size(), 2U);
    const dtm::VolumeResult v = dtm::volume(top, base);
    for (const dtm::CutFillRegion& r : map.regions) {
        ASSERT_EQ(r.rings.size(), 1U);
        EXPECT_GT(dtm::ring_area(r.rings[0]), 0.0);
        EXPECT_NEAR(dtm::ring_area(r.rings[0]), r.area, 1e-9 * r.area);
        EXPECT_NEAR(r.area, r.fill ? v.fill_area : v.cut_area, 1e-9 * r.area);
        EXPECT_NEAR(r.volume, r.fill ? v.fill : v.cut, 1e-9 * r.volume);
    }
    ASSERT_EQ(map.zero_lines.size(), 1U);
    const dtm::ZeroLine& zero = map.zero_lines[0];
    EXPECT_FALSE(zero.closed);
    EXPECT_NEAR(length(zero), sq.side, 1e-9);
    for (const dtm::Point3& p : zero.points) {
        EXPECT_NEAR(p.x, sq.x0 + xm, 1e-9);
        EXPECT_NEAR(p.z, 100.0 + 0.25 * xm - 0.1 * (p.y - sq.y0), 1e-9);  // on both planes
    }
}

TEST(CutFill, PyramidThroughALevelGivesAFillSquareInACutFrameWithAClosedZeroLine) {
    const Square sq{-750000.0, -1050000.0, 40.0};
    const double h = 8.0;
    const dtm::Tin pyramid = dtm::test::frustum_tin(sq, h, 0.0, 300, 3);
    const dtm::TinOverlay overlay(pyramid, h / 2.0);
    const dtm::CutFillMap map = dtm::cut_fill_map(dtm::difference_surface(overlay));
    ASSERT_EQ(map.regions.size(), 2U);
    const dtm::CutFillRegion& fill = map.regions[0].fill ? map.regions[0] : map.regions[1];
    const dtm::CutFillRegion& cut = map.regions[0].fill ? map.regions[1] : map.regions[0];
    ASSERT_TRUE(fill.fill);
    ASSERT_FALSE(cut.fill);
    EXPECT_EQ(fill.rings.size(), 1U);
    ASSERT_EQ(cut.rings.size(), 2U);  // the frame: outer square and the fill square as a hole
    EXPECT_LT(dtm::ring_area(cut.rings[1]), 0.0);
    EXPECT_NEAR(fill.area, 400.0, 1e-9);
    EXPECT_NEAR(fill.volume, 400.0 * (h / 2.0) / 3.0, 1e-9);
    EXPECT_NEAR(cut.area, 1200.0, 1e-9);
    EXPECT_NEAR(fill.max_depth, h / 2.0, 1e-12);
    ASSERT_EQ(map.zero_lines.size(), 1U);
    EXPECT_TRUE(map.zero_lines[0].closed);
    EXPECT_NEAR(length(map.zero_lines[0]), 80.0, 1e-9);
    for (const dtm::Point3& p : map.zero_lines[0].points) {
        EXPECT_NEAR(p.z, h / 2.0, 1e-9);
    }
}

TEST(CutFill, UnchangedGroundAroundAMoundIsNeitherCutNorFillAndTheMoundIsRinged) {
    // Top and base are the same grid TIN except one raised vertex: the difference is exactly zero
    // outside that vertex's star, which becomes the only fill region, ringed by a zero line.
    dtm::TerrainInput in;
    for (int j = 0; j <= 10; ++j) {
        for (int i = 0; i <= 10; ++i) {
            in.points.push_back({-750000.0 + i, -1050000.0 + j, 300.0});
        }
    }
    const dtm::Tin base = dtm::triangulate(in).tin;
    dtm::Tin top = base;
    top.vertices[5 * 11 + 5].z += 1.0;
    const dtm::TinOverlay overlay(top, base);
    const dtm::CutFillMap map = dtm::cut_fill_map(dtm::difference_surface(overlay));
    const dtm::VolumeResult v = dtm::volume(top, base);
    ASSERT_EQ(map.regions.size(), 1U);
    EXPECT_TRUE(map.regions[0].fill);
    EXPECT_EQ(map.regions[0].rings.size(), 1U);
    EXPECT_GE(v.fill_area, 2.0);  // at least four half-cells
    EXPECT_NEAR(map.regions[0].area, v.fill_area, 1e-12);
    EXPECT_NEAR(v.fill, v.fill_area / 3.0, 1e-12);
    EXPECT_NEAR(v.unchanged_area, 100.0 - v.fill_area, 1e-9);
    EXPECT_EQ(v.cut, 0.0);
    ASSERT_EQ(map.zero_lines.size(), 1U);
    EXPECT_TRUE(map.zero_lines[0].closed);
    for (const dtm::Point3& p : map.zero_lines[0].points) {
        EXPECT_EQ(p.z, 300.0);
    }
}

}  // namespace
