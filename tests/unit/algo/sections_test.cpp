// SPDX-License-Identifier: MIT
#include "dtm/algo/sections.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dtm/algo/volume.hpp"
#include "support/solid_fixtures.hpp"

namespace {

using dtm::Point3;
using dtm::test::Square;

TEST(Sections, LinesArePerpendicularAtTheStationsAndBisectAtVertices) {
    const std::vector<Point3> alignment{{0, 0, 0}, {30, 0, 0}, {30, 30, 0}};
    const auto lines = dtm::section_lines(alignment, {.interval = 10.0, .width = 8.0});
    ASSERT_EQ(lines.size(), 7U);  // 0, 10, ..., 60
    EXPECT_EQ(lines[1].station, 10.0);
    EXPECT_NEAR(lines[1].left.x, 10.0, 1e-12);
    EXPECT_NEAR(lines[1].left.y, 4.0, 1e-12);  // left of travel (east): north
    EXPECT_NEAR(lines[1].right.y, -4.0, 1e-12);
    // At the corner (station 30) the section runs along the bisector's normal.
    EXPECT_NEAR(lines[3].left.x - lines[3].centre.x, -4.0 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(lines[3].left.y - lines[3].centre.y, 4.0 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(lines[6].centre.y, 30.0, 1e-12);
}

TEST(Sections, AreasAndSlabVolumesBetweenCrossingPlanes) {
    // top - base = k (x - xm): across an east-west alignment the section areas vary linearly
    // except where the zero line passes; end areas are exact on the other slabs.
    const Square sq{-750000.0, -1050000.0, 100.0};
    const double k = 0.2;
    const double xm = 35.0;
    const dtm::Tin top = dtm::test::plane_tin(sq, 50.0, 0.1, 0.05, 600, 1);
    const dtm::Tin base = dtm::test::plane_tin(sq, 50.0 + k * xm, 0.1 - k, 0.05, 500, 2);
    const std::vector<Point3> alignment{{sq.x0 + 10, sq.y0 + 50, 0}, {sq.x0 + 90, sq.y0 + 50, 0}};
    const auto lines = dtm::section_lines(alignment, {.interval = 10.0, .width = 40.0});
    ASSERT_EQ(lines.size(), 9U);
    const dtm::TinSection top_section(top);
    const dtm::TinSection base_section(base);
    std::vector<dtm::SectionAreas> areas;
    for (const auto& l : lines) {
        const std::vector<Point3> cut{{l.left.x, l.left.y, 0}, {l.right.x, l.right.y, 0}};
        areas.push_back(dtm::section_areas(top_section.cut(cut), base_section.cut(cut)));
        const double d = k * (l.centre.x - (sq.x0 + xm));
        EXPECT_NEAR(areas.back().fill, std::max(d, 0.0) * 40.0, 1e-9);
        EXPECT_NEAR(areas.back().cut, std::max(-d, 0.0) * 40.0, 1e-9);
        EXPECT_NEAR(areas.back().width, 40.0, 1e-9);
    }
    const dtm::TinOverlay overlay(top, base);
    const auto slabs = dtm::slab_volumes(dtm::difference_surface(overlay), lines);
    ASSERT_EQ(slabs.size(), 8U);
    double fill = 0.0;
    double cut = 0.0;
    for (std::size_t i = 0; i < slabs.size(); ++i) {
        EXPECT_NEAR(slabs[i].area, 400.0, 1e-6);
        const double end_fill = 0.5 * (areas[i].fill + areas[i + 1].fill) * 10.0;
        if (i != 2) {  // the slab [30, 40] holds the zero line x = 35
            EXPECT_NEAR(slabs[i].fill, end_fill, 1e-6) << i;
        } else {
            EXPECT_GT(end_fill, slabs[i].fill);  // the kink: end areas over-estimate
        }
        fill += slabs[i].fill;
        cut += slabs[i].cut;
    }
    // Exact totals: over [10, 90] x [30, 70], fill = 40 k (90 - 35)^2 / 2, cut = 40 k 25^2 / 2.
    EXPECT_NEAR(fill, 40.0 * k * 55.0 * 55.0 / 2.0, 1e-6);
    EXPECT_NEAR(cut, 40.0 * k * 25.0 * 25.0 / 2.0, 1e-6);
}

}  // namespace
