// SPDX-License-Identifier: MIT
// Sheets: a framed sheet with a title block and a content rectangle holding a chart (the way
// profiles and sections print), the title block and legend sizes, paper orientation.
#include "dtm/io/draw/sheet.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "dtm/core/error.hpp"
#include "dtm/io/draw/chart.hpp"
#include "support/pdf_tools.hpp"
#include "support/test_support.hpp"

namespace dtm::io::draw {
namespace {

TitleBlock block() {
    TitleBlock b;
    b.title = "Profile P1";
    b.fields = {{"Scale", "1 : 500 / 1 : 50"}, {"Date", "2026-01-01"}};
    return b;
}

TEST(Sheet, LayoutPutsTheTitleBlockInTheLowerRightAndTheContentAboveIt) {
    const SheetLayout l = sheet_layout(paper_named("A3"), Orientation::landscape, block());
    EXPECT_DOUBLE_EQ(l.width_mm, 420.0);
    EXPECT_DOUBLE_EQ(l.height_mm, 297.0);
    EXPECT_DOUBLE_EQ(l.frame.x, 10.0);
    EXPECT_DOUBLE_EQ(l.frame.right(), 410.0);
    EXPECT_DOUBLE_EQ(l.title_block.right(), l.frame.right());
    EXPECT_DOUBLE_EQ(l.title_block.bottom(), l.frame.bottom());
    EXPECT_LE(l.content.bottom(), l.title_block.y);
    EXPECT_GE(l.content.x, l.frame.x);
    EXPECT_LE(l.content.right(), l.frame.right());
    EXPECT_THROW((void)sheet_layout(paper_named("30x40mm"), Orientation::portrait, block()),
                 UsageError);
}

TEST(Sheet, TitleBlockGrowsWithItsFieldsAndLongValuesWrap) {
    TitleBlock b = block();
    const double h = title_block_height(b, 100.0);
    b.fields.emplace_back("Sources",
                          "a.csv, b.shp, c.shp, d.shp, e.shp, f.shp, g.shp, h.shp, "
                          "i.shp, j.shp, k.shp, l.shp, m.shp, n.shp");
    const double wrapped = title_block_height(b, 100.0);
    EXPECT_GT(wrapped, h + 2.0 * 2.5);  // at least two more lines
    const auto [lw, lh] = legend_size({{LegendEntry::Kind::line, {}, {}, 0.6, "Contour"},
                                       {LegendEntry::Kind::marker, {}, {}, 0.6, "Spot height"}});
    EXPECT_GT(lw, 10.0 + measure_text("Spot height", TextStyle{}).width * 0.5);
    EXPECT_GT(lh, 0.0);
}

TEST(Sheet, ChartPrintsInTheContentOfAFramedSheet) {
    test::ScratchDir dir;
    const auto path = dir / "profile.pdf";
    const SheetLayout l = sheet_layout(paper_named("A4"), Orientation::landscape, block());
    {
        Canvas c(path, l.width_mm, l.height_mm);
        draw_sheet(c, l, block());
        Chart chart;
        chart.title = "Longitudinal profile";
        chart.x.label = "chainage [m]";
        chart.y.label = "height [m]";
        Series terrain;
        terrain.name = "terrain";
        terrain.points = {{0, 310}, {50, 312.5}, {100, 311}};
        terrain.color = Color::rgb(0x8b4513);
        chart.series.push_back(terrain);
        draw_chart(c, chart, {l.content.x, l.content.y}, l.content.width, l.content.height);
        draw_scale_bar(c, {l.content.x, l.content.bottom() - 10.0}, 60.0, 500.0);
        c.finish();
    }
    if (!test::have_tool("pdftotext")) GTEST_SKIP() << "no poppler-utils";
    const std::vector<std::string> words = test::pdf_words(path);
    for (const char* w : {"Profile", "P1", "Longitudinal", "chainage", "Surveyor", "Signature"}) {
        EXPECT_NE(std::find(words.begin(), words.end(), w), words.end()) << w;
    }
    const auto [w, h] = test::pdf_page_mm(path);
    EXPECT_NEAR(w, 297.0, 0.5);
    EXPECT_NEAR(h, 210.0, 0.5);
}

}  // namespace
}  // namespace dtm::io::draw
