// SPDX-License-Identifier: MIT
// Spot heights: the summits, the hollow and the saddle of an analytic terrain are found where
// the terrain has them; selected spots keep the spacing and cover the site; `all` gives every
// vertex; a count limit holds; flat ground and a noisy plane give no critical points. Point
// labels never overlap markers, other texts or obstacles, and failures are counted.
#include "dtm/algo/spot_heights.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dtm/algo/triangulate.hpp"
#include "support/map_fixtures.hpp"

namespace {

using namespace dtm;
using dtm::test::hills_tin;
using dtm::test::hills_z;
using dtm::test::quads_overlap;

double distance(const SpotHeight& s, double x, double y) {
    return std::hypot(s.point.x - x, s.point.y - y);
}

bool has_kind_near(const SpotHeightResult& r, SpotKind kind, double x, double y, double within) {
    for (const SpotHeight& s : r.spots) {
        if (s.kind == kind && distance(s, x, y) < within) return true;
    }
    return false;
}

/// The saddle of hills_z between the two hills, by brute force: the lowest point of the ridge
/// (the highest point of each north-south section) between them.
Point2 true_saddle() {
    Point2 best{0, 0};
    double lowest = 1e300;
    for (double x = 70; x <= 130; x += 0.05) {
        double ridge = -1e300;
        double at = 0;
        for (double y = 40; y <= 110; y += 0.05) {
            if (hills_z(x, y) > ridge) {
                ridge = hills_z(x, y);
                at = y;
            }
        }
        if (ridge < lowest) {
            lowest = ridge;
            best = {x, at};
        }
    }
    return best;
}

TEST(SpotHeights, FindsSummitsPitAndSaddleAndKeepsTheSpacing) {
    const Tin tin = hills_tin(4000, 11);
    SpotHeightOptions o;
    o.spacing = 15.0;
    const SpotHeightResult r = select_spot_heights(tin, o);
    EXPECT_TRUE(has_kind_near(r, SpotKind::summit, 60, 75, 3.0));
    EXPECT_TRUE(has_kind_near(r, SpotKind::summit, 140, 75, 3.0));
    EXPECT_TRUE(has_kind_near(r, SpotKind::pit, 100, 20, 3.0));
    const Point2 saddle = true_saddle();
    EXPECT_TRUE(has_kind_near(r, SpotKind::saddle, saddle.x, saddle.y, 6.0))
        << "saddle at " << saddle.x << " " << saddle.y;
    EXPECT_EQ(r.summits, 2U);
    EXPECT_EQ(r.pits, 1U);
    EXPECT_EQ(r.summits + r.pits + r.saddles + r.regular, r.spots.size());
    // the critical ones come first, summits highest first
    ASSERT_GE(r.spots.size(), 3U);
    EXPECT_EQ(r.spots[0].kind, SpotKind::summit);
    EXPECT_GT(r.spots[0].point.z, r.spots[1].point.z);
    for (std::size_t i = 0; i < r.spots.size(); ++i) {
        EXPECT_EQ(r.spots[i].point, tin.vertices[r.spots[i].vertex]);
        for (std::size_t j = i + 1; j < r.spots.size(); ++j) {
            EXPECT_GE(std::hypot(r.spots[i].point.x - r.spots[j].point.x,
                                 r.spots[i].point.y - r.spots[j].point.y),
                      15.0);
        }
    }
    // every vertex has a spot height within twice the spacing
    for (const Point3& v : tin.vertices) {
        double nearest = 1e300;
        for (const SpotHeight& s : r.spots) nearest = std::min(nearest, distance(s, v.x, v.y));
        EXPECT_LT(nearest, 30.0);
    }
}

TEST(SpotHeights, AllCountLimitAndExtent) {
    const Tin tin = hills_tin(1500, 5, -744000.0, -1045000.0);
    SpotHeightOptions all;
    all.all = true;
    const SpotHeightResult a = select_spot_heights(tin, all);
    EXPECT_EQ(a.spots.size(), tin.vertices.size());
    SpotHeightOptions few;
    few.spacing = 10.0;
    few.max_count = 12;
    const SpotHeightResult f = select_spot_heights(tin, few);
    EXPECT_LE(f.spots.size(), 12U);
    EXPECT_GE(f.spots.size(), 6U);
    EXPECT_GT(f.spacing, 10.0);
    EXPECT_EQ(f.spots[0].kind, SpotKind::summit);
    SpotHeightOptions part;
    part.spacing = 10.0;
    part.extent = Box2{-744000.0, -1045000.0, -743900.0, -1044925.0};
    for (const SpotHeight& s : select_spot_heights(tin, part).spots) {
        EXPECT_LE(s.point.x, -743900.0);
        EXPECT_LE(s.point.y, -1044925.0);
    }
}

TEST(SpotHeights, FlatGroundAndANoisyPlaneHaveNoCriticalPoints) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    std::uniform_real_distribution<double> noise(-0.01, 0.01);
    TerrainInput flat;
    TerrainInput plane;
    for (int i = 0; i < 2000; ++i) {
        const double x = u(rng), y = u(rng);
        flat.points.push_back({x, y, 100.0});
        plane.points.push_back({x, y, 100.0 + 0.1 * x + 0.05 * y + noise(rng)});
    }
    SpotHeightOptions o;
    o.spacing = 8.0;
    for (const TerrainInput* in : {&flat, &plane}) {
        const SpotHeightResult r = select_spot_heights(triangulate(*in).tin, o);
        EXPECT_EQ(r.summits + r.pits + r.saddles, 0U);
        EXPECT_GT(r.regular, 50U);
    }
}

TEST(PointLabels, NeverOverlapAndCountFailures) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(0.0, 60.0);
    std::vector<PointLabelRequest> req;
    for (int i = 0; i < 150; ++i) req.push_back({{u(rng), u(rng)}, 0.4, 8.0, 2.5});
    const std::vector<LabelBox> obstacles{LabelBox::of({20, 20, 30, 30})};
    PointLabelOptions o;
    o.frame = Box2{0, 0, 60, 60};
    const PointLabelResult r = place_point_labels(req, {}, obstacles, o);
    EXPECT_EQ(r.labels.size() + r.failed.size(), req.size());
    EXPECT_GT(r.labels.size(), 30U);
    EXPECT_GT(r.failed.size(), 0U);  // 150 labels of 8 x 2.5 do not fit 60 x 60 with markers
    for (std::size_t i = 0; i < r.labels.size(); ++i) {
        const PointLabel& a = r.labels[i];
        const Box2 b = a.box.bounds();
        EXPECT_TRUE(b.xmin >= 0 && b.xmax <= 60 && b.ymin >= 0 && b.ymax <= 60);
        EXPECT_FALSE(quads_overlap(a.box.corners(), obstacles[0].corners()));
        for (std::size_t j = i + 1; j < r.labels.size(); ++j) {
            EXPECT_FALSE(quads_overlap(a.box.corners(), r.labels[j].box.corners()));
        }
        for (const LabelBox& m : r.markers) {
            EXPECT_FALSE(quads_overlap(a.box.corners(), m.corners()));
        }
    }
    // A lone point: the text goes to the right, vertically centred on the marker.
    const std::vector<PointLabelRequest> one{{{10, 10}, 0.5, 6.0, 2.0}};
    const PointLabelResult single = place_point_labels(one, {}, {}, {});
    ASSERT_EQ(single.labels.size(), 1U);
    EXPECT_EQ(single.labels[0].position, 0);
    EXPECT_NEAR(single.labels[0].box.centre.x, 10 + 0.5 + 0.6 + 3.0, 1e-12);
    EXPECT_NEAR(single.labels[0].box.centre.y, 10, 1e-12);
    // A line through the right-hand position pushes the text to a free one.
    std::vector<Point3> line{{13, 0, 0}, {13, 20, 0}};
    const std::vector<LabelLine> lines{{line, false, 0.0, LabelLine::no_label}};
    const PointLabelResult moved = place_point_labels(one, lines, {}, {});
    ASSERT_EQ(moved.labels.size(), 1U);
    EXPECT_EQ(moved.labels[0].position, 3);  // left
    // A contour through every position: the text still goes right (over the contour, with its
    // halo); a breakline through every position: the spot height is left out and counted.
    std::vector<Point3> ring{{8, 8, 0}, {16, 8, 0}, {16, 12, 0}, {8, 12, 0}, {8, 8, 0}};
    std::vector<Point3> cross{{4, 10, 0}, {20, 10, 0}};
    std::vector<Point3> upright{{10, 4, 0}, {10, 16, 0}};
    std::vector<LabelLine> caged{{ring, true, 0.0, LabelLine::no_label},
                                 {cross, false, 0.0, LabelLine::no_label},
                                 {upright, false, 0.0, LabelLine::no_label}};
    const PointLabelResult over_contours = place_point_labels(one, caged, {}, {});
    ASSERT_EQ(over_contours.labels.size(), 1U);
    EXPECT_EQ(over_contours.labels[0].position, 0);
    for (LabelLine& l : caged) l.passable = false;
    const PointLabelResult on_breaklines = place_point_labels(one, caged, {}, {});
    EXPECT_TRUE(on_breaklines.labels.empty());
    EXPECT_EQ(on_breaklines.failed, std::vector<std::size_t>{0});
}

}  // namespace
