// SPDX-License-Identifier: MIT
// Map sheet layout: the page is the extent at scale (100 m at 1:500 is 200 mm), the extent
// follows from the paper, sheets tile the site, and impossible requests are clear errors that
// name what would fit. Paper names and the sheet furniture sizes.
#include "dtm/io/map/map_layout.hpp"

#include <gtest/gtest.h>

#include "dtm/core/error.hpp"

namespace {

using namespace dtm;
using namespace dtm::io::map;
using dtm::io::draw::Orientation;
using dtm::io::draw::paper_named;

TEST(MapLayout, PageIsTheExtentAtScale) {
    LayoutRequest r;
    r.data = {-744500, -1045400, -744300, -1045250};
    r.extent = Box2{-744400, -1045350, -744300, -1045270};
    r.scale = 500;
    const MapLayout l = layout_map(r);
    ASSERT_EQ(l.pages.size(), 1U);
    EXPECT_DOUBLE_EQ(l.pages[0].width_mm, 200.0);
    EXPECT_DOUBLE_EQ(l.pages[0].height_mm, 160.0);
    EXPECT_EQ(l.pages[0].extent.xmin, -744400);
    const Point2 corner = l.pages[0].to_page({-744300, -1045350});
    EXPECT_NEAR(corner.x, 200.0, 1e-9);
    EXPECT_NEAR(corner.y, 160.0, 1e-9);
    const Point2 back = l.pages[0].to_ground({100.0, 80.0});
    EXPECT_NEAR(back.x, -744350.0, 1e-9);
    EXPECT_NEAR(back.y, -1045310.0, 1e-9);
    // feet: 1 ft = 0.3048 m, so 1000 ft at 1:1000 is 304.8 mm
    r.extent = Box2{0, 0, 1000, 500};
    r.data = *r.extent;
    r.unit_m = 0.3048;
    r.scale = 1000;
    EXPECT_NEAR(layout_map(r).pages[0].width_mm, 304.8, 1e-9);
}

TEST(MapLayout, PaperGivesTheExtentCentredOnTheSite) {
    LayoutRequest r;
    r.data = {1000, 2000, 1150, 2060};  // 150 x 60 m: landscape
    r.scale = 1000;
    r.paper = paper_named("A4");
    const MapLayout l = layout_map(r);
    ASSERT_EQ(l.pages.size(), 1U);
    EXPECT_DOUBLE_EQ(l.pages[0].width_mm, 297.0);
    EXPECT_DOUBLE_EQ(l.pages[0].height_mm, 210.0);
    EXPECT_NEAR(l.pages[0].extent.xmax - l.pages[0].extent.xmin, 297.0, 1e-9);
    EXPECT_NEAR((l.pages[0].extent.xmin + l.pages[0].extent.xmax) / 2, 1075.0, 1e-9);
    EXPECT_NEAR((l.pages[0].extent.ymin + l.pages[0].extent.ymax) / 2, 2030.0, 1e-9);
    r.orientation = Orientation::portrait;
    EXPECT_DOUBLE_EQ(layout_map(r).pages[0].width_mm, 210.0);
}

TEST(MapLayout, SheetsTileTheSite) {
    LayoutRequest r;
    r.data = {0, 0, 1000, 500};
    r.scale = 1000;
    r.sheets = true;
    r.paper = paper_named("A3");  // 420 x 297 landscape: 3 x 2 sheets
    const MapLayout l = layout_map(r);
    EXPECT_EQ(l.cols, 3);
    EXPECT_EQ(l.rows, 2);
    ASSERT_EQ(l.pages.size(), 6U);
    EXPECT_EQ(l.pages[0].name, "1");
    EXPECT_EQ(l.pages[5].name, "6");
    for (const PageFrame& p : l.pages) {
        EXPECT_DOUBLE_EQ(p.width_mm, 420.0);
        EXPECT_DOUBLE_EQ(p.height_mm, 297.0);
    }
    EXPECT_LE(l.covered.xmin, 0.0);
    EXPECT_GE(l.covered.xmax, 1000.0);
    EXPECT_LE(l.covered.ymin, 0.0);
    EXPECT_GE(l.covered.ymax, 500.0);
    // neighbouring sheets share their edge
    EXPECT_DOUBLE_EQ(l.pages[0].extent.xmax, l.pages[1].extent.xmin);
    EXPECT_DOUBLE_EQ(l.pages[0].extent.ymin, l.pages[3].extent.ymax);
    EXPECT_GT(l.pages[0].extent.ymin, l.pages[3].extent.ymin);  // row 0 is the northern one
}

TEST(MapLayout, ImpossibleRequestsAreClearErrors) {
    LayoutRequest r;
    r.data = {0, 0, 3000, 2000};
    r.scale = 500;  // 6 x 4 m of paper
    try {
        (void)layout_map(r);
        FAIL() << "expected a UsageError";
    } catch (const UsageError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("larger than A0"), std::string::npos) << what;
        EXPECT_NE(what.find("1:5000"), std::string::npos) << what;  // the largest that fits
    }
    r.scale = 0.0;
    EXPECT_THROW((void)layout_map(r), UsageError);
    r.scale = 500;
    r.extent = Box2{10, 10, 10, 20};
    EXPECT_THROW((void)layout_map(r), UsageError);  // empty
    r.extent = Box2{5000, 5000, 5100, 5100};
    EXPECT_THROW((void)layout_map(r), UsageError);  // off the surface
    r.extent.reset();
    r.data = {0, 0, 300, 200};
    r.paper = paper_named("A4");
    try {
        (void)layout_map(r);
        FAIL() << "expected a UsageError";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("`sheets`"), std::string::npos) << e.what();
    }
    EXPECT_DOUBLE_EQ(largest_fitting_scale(300, 200, 1.0, 297, 210), 2000.0);
}

TEST(Paper, NamesAndCustomSizes) {
    EXPECT_DOUBLE_EQ(paper_named("a3").height_mm, 420.0);
    EXPECT_DOUBLE_EQ(paper_named("A0").width_mm, 841.0);
    const auto custom = paper_named("700x500mm");
    EXPECT_DOUBLE_EQ(custom.width_mm, 500.0);
    EXPECT_DOUBLE_EQ(custom.height_mm, 700.0);
    EXPECT_DOUBLE_EQ(paper_named("300x200").width_mm, 200.0);
    EXPECT_THROW((void)paper_named("B5"), UsageError);
    EXPECT_THROW((void)paper_named("0x100mm"), UsageError);
    EXPECT_THROW((void)io::draw::orientation_named("sideways"), UsageError);
}

}  // namespace
