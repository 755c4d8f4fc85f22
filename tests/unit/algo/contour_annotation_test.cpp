// SPDX-License-Identifier: MIT
// annotate_contours on a slope with a hill: every contour number stands on its index contour (the
// TIN's height at the anchor is the level), reads uphill (the surface rises along the up vector),
// and no two labels (numbers and spot height texts, boxes as estimated) overlap; spot heights are
// TIN vertices with their height as text.
#include "dtm/algo/contour_annotation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "dtm/algo/surface_sampler.hpp"
#include "dtm/algo/triangulate.hpp"

namespace {

dtm::Tin hill_tin() {
    dtm::TerrainInput input;
    for (int i = 0; i <= 80; ++i) {
        for (int j = 0; j <= 60; ++j) {
            const double x = 5.0 * i + ((i > 0 && i < 80) ? 0.37 * ((i * 7 + j * 3) % 5) : 0.0);
            const double y = 5.0 * j + ((j > 0 && j < 60) ? 0.29 * ((i * 3 + j * 5) % 7) : 0.0);
            const double r2 = (x - 200.0) * (x - 200.0) + (y - 150.0) * (y - 150.0);
            input.points.push_back(
                {x, y, 200.0 + 0.05 * x + 15.0 * std::exp(-r2 / (2.0 * 60.0 * 60.0))});
        }
    }
    return dtm::triangulate(input).tin;
}

TEST(ContourAnnotation, NumbersStandOnTheirLevelReadUphillAndNeverOverlap) {
    const dtm::Tin tin = hill_tin();
    dtm::ContourOptions co;
    co.interval = 0.5;
    const std::vector<dtm::Contour> lines = dtm::contour(tin, co);
    dtm::ContourAnnotationOptions o;
    o.units_per_mm = 0.5;
    o.spot_heights = true;
    const dtm::ContourAnnotation a = dtm::annotate_contours(tin, lines, o);
    EXPECT_DOUBLE_EQ(a.text_height, 1.25);
    ASSERT_GE(a.labels.size(), 10U);
    const dtm::SurfaceSampler sampler(tin);
    dtm::SurfaceSampler::Cursor cursor;
    std::vector<dtm::LabelBox> boxes;
    for (const dtm::ContourLabel& l : a.labels) {
        EXPECT_DOUBLE_EQ(std::strtod(l.text.c_str(), nullptr), l.level);
        EXPECT_NEAR(std::remainder(l.level, 2.5), 0.0, 1e-9) << l.text;
        EXPECT_NEAR(sampler.height(l.anchor, cursor), l.level, 1e-9) << l.text;
        const dtm::Point2 up = l.box.up();
        const double d = 0.1 * a.text_height;
        EXPECT_GT(sampler.height({l.anchor.x + d * up.x, l.anchor.y + d * up.y}, cursor), l.level);
        EXPECT_LT(sampler.height({l.anchor.x - d * up.x, l.anchor.y - d * up.y}, cursor), l.level);
        // the box as a reader draws it: centred on the anchor
        boxes.push_back({l.anchor, l.box.axis, l.box.half_width, l.box.half_height});
    }
    ASSERT_GE(a.spots.size(), 3U);
    for (const dtm::SpotAnnotation& s : a.spots) {
        EXPECT_NEAR(sampler.height(s.spot.point.xy(), cursor), s.spot.point.z, 1e-9);
        if (s.box) boxes.push_back(*s.box);
    }
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (std::size_t j = i + 1; j < boxes.size(); ++j) {
            EXPECT_FALSE(dtm::overlaps(boxes[i], boxes[j])) << i << " " << j;
        }
    }
}

TEST(ContourAnnotation, LevelTextIsTheShortestExactDecimal) {
    EXPECT_EQ(dtm::level_text(245.0), "245");
    EXPECT_EQ(dtm::level_text(247.5), "247.5");
    EXPECT_EQ(dtm::level_text(-0.0), "0");
    EXPECT_EQ(dtm::level_text(0.125), "0.125");
}

}  // namespace
