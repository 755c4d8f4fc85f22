// SPDX-License-Identifier: MIT
// The map sheet read back by tools dtm did not write: pdfinfo gives the page size of the extent
// at scale, gdalinfo the CRS (EPSG:5514) and the neat line, pdftotext every placed contour label
// as one word equal to its contour level (in the default, -raw and -layout modes), and the word
// boxes pdftotext reports for the labels do not overlap. The report's label boxes do not overlap
// either (independent quadrilateral test). SVG and PNG come from the same drawing; sheets give
// one georeferenced page each and an index.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/map/map.hpp"
#include "support/map_fixtures.hpp"
#include "support/pdf_tools.hpp"
#include "support/test_support.hpp"

namespace {

using namespace dtm;
using namespace dtm::io::map;
using test::have_tool;

constexpr double e0 = -744200.0;  // S-JTSK site origin (Krovak East-North)
constexpr double n0 = -1045300.0;

const Tin& site() {
    static const Tin tin = test::hills_tin(6000, 21, e0, n0);
    return tin;
}

MapOptions options() {
    MapOptions o;
    o.scale = 500;
    o.crs_wkt = io::crs_to_wkt("EPSG:5514");
    o.interval = 1.0;
    o.label_spacing_mm = 80.0;
    o.date = "2026-01-01";
    o.sources = {"hills.csv"};
    return o;
}

/// The box of gdalinfo's NEATLINE polygon (empty if there is none).
Box2 neatline(const std::string& gdalinfo) {
    Box2 box;
    const std::size_t at = gdalinfo.find("NEATLINE=POLYGON ((");
    if (at == std::string::npos) return box;
    const char* p = gdalinfo.c_str() + at + 19;
    for (int i = 0; i < 5; ++i) {
        char* end = nullptr;
        const double x = std::strtod(p, &end);
        const double y = std::strtod(end, &end);
        box.add(x, y);
        p = end + 1;  // the comma
    }
    return box;
}

void expect_box_near(const Box2& a, const Box2& b, double tolerance) {
    EXPECT_NEAR(a.xmin, b.xmin, tolerance);
    EXPECT_NEAR(a.ymin, b.ymin, tolerance);
    EXPECT_NEAR(a.xmax, b.xmax, tolerance);
    EXPECT_NEAR(a.ymax, b.ymax, tolerance);
}

bool is_number(const std::string& w) {
    char* end = nullptr;
    std::strtod(w.c_str(), &end);
    return !w.empty() && end == w.c_str() + w.size();
}

TEST(MapWriter, PdfHasThePageOfTheExtentItsCrsNeatLineAndSearchableLabels) {
    if (!have_tool("pdfinfo") || !have_tool("pdftotext")) GTEST_SKIP() << "no poppler-utils";
    test::ScratchDir dir;
    const auto path = dir / "map.pdf";
    MapOptions o = options();
    o.extent = Box2{e0 + 10, n0 + 5, e0 + 190, n0 + 145};  // 180 x 140 m: 360 x 280 mm
    const MapReport r = write_map(site(), o, path);
    ASSERT_EQ(r.layout.pages.size(), 1U);
    const auto [w, h] = test::pdf_page_mm(path);
    EXPECT_NEAR(w, 360.0, 0.5);
    EXPECT_NEAR(h, 280.0, 0.5);
    ASSERT_GT(r.labels.size(), 5U);
    EXPECT_TRUE(r.georeferenced);

    // every placed label is one word, equal to a contour level, in every pdftotext mode
    std::multiset<std::string> placed;
    for (const LabelRecord& l : r.labels) {
        placed.insert(l.text);
        EXPECT_NEAR(std::strtod(l.text.c_str(), nullptr), l.level, 1e-9);
        EXPECT_NEAR(std::fmod(l.level, 5.0), 0.0, 1e-9);  // index contours: every 5th metre
    }
    for (const std::string mode : {"", "-raw", "-layout"}) {
        std::multiset<std::string> found;
        for (const std::string& word : test::pdf_words(path, mode)) {
            if (placed.count(word) > 0) found.insert(word);
        }
        for (const std::string& text : std::set<std::string>(placed.begin(), placed.end())) {
            EXPECT_GE(found.count(text), placed.count(text))
                << "pdftotext " << mode << ": " << text;
        }
    }
    // the word boxes pdftotext computes for the labels do not overlap
    std::vector<test::PdfWord> boxes;
    for (const test::PdfWord& word : test::pdf_word_boxes(path)) {
        if (placed.count(word.text) > 0) boxes.push_back(word);
    }
    EXPECT_GE(boxes.size(), r.labels.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        for (std::size_t j = i + 1; j < boxes.size(); ++j) {
            const auto& a = boxes[i];
            const auto& b = boxes[j];
            EXPECT_TRUE(a.x_max <= b.x_min || b.x_max <= a.x_min || a.y_max <= b.y_min ||
                        b.y_max <= a.y_min)
                << a.text << " and " << b.text;
        }
    }
    // the report's label boxes, on the page, do not overlap and lie on the page
    for (std::size_t i = 0; i < r.labels.size(); ++i) {
        for (const Point2& c : r.labels[i].box) {
            EXPECT_TRUE(c.x > 0 && c.x < 360 && c.y > 0 && c.y < 280);
        }
        for (std::size_t j = i + 1; j < r.labels.size(); ++j) {
            EXPECT_FALSE(test::quads_overlap(r.labels[i].box, r.labels[j].box));
        }
    }

    if (!have_tool("gdalinfo")) GTEST_SKIP() << "no gdalinfo";
    const std::string info = test::command_output("gdalinfo '" + path.string() + "'");
    EXPECT_NE(info.find("ID[\"EPSG\",5514]]"), std::string::npos) << info;
    expect_box_near(neatline(info), *o.extent, 1e-6);
}

TEST(MapWriter, ThinnedSpotHeightsAreDrawnAndNumbersStayApartFromThem) {
    if (!have_tool("pdftotext")) GTEST_SKIP() << "no poppler-utils";
    test::ScratchDir dir;
    const auto path = dir / "map.pdf";
    MapOptions o = options();
    o.scale = 1000;
    o.paper = io::draw::paper_named("A3");
    const MapReport r = write_map(site(), o, path);
    EXPECT_GT(r.spots_drawn, 10U);
    EXPECT_GE(r.summits, 2U);
    EXPECT_GE(r.pits, 1U);
    const auto [w, h] = test::pdf_page_mm(path);
    EXPECT_NEAR(w, 420.0, 0.5);
    EXPECT_NEAR(h, 297.0, 0.5);
    // spot heights at two decimals at 1:500; pdftotext finds them
    std::size_t two_decimals = 0;
    for (const std::string& word : test::pdf_words(path)) {
        const std::size_t dot = word.find('.');
        if (is_number(word) && dot != std::string::npos && word.size() - dot == 3) ++two_decimals;
    }
    EXPECT_GE(two_decimals, r.spots_drawn);
    const std::string json = map_report_json(r);
    EXPECT_NE(json.find("\"placed_labels\""), std::string::npos);
    EXPECT_NE(json.find("\"summits\": " + std::to_string(r.summits)), std::string::npos);
}

TEST(MapWriter, SvgAndPngFromTheSameDrawing) {
    test::ScratchDir dir;
    MapOptions o = options();
    o.extent = Box2{e0 + 10, n0 + 5, e0 + 190, n0 + 145};
    o.hillshade = true;
    const MapReport svg = write_map(site(), o, dir / "map.svg");
    const std::string text = test::read_file(dir / "map.svg");
    EXPECT_NE(text.find("<svg"), std::string::npos);
    EXPECT_NE(text.find("width=\"1020.47"), std::string::npos);  // 360 mm in points
    o.png_dpi = 50;
    const MapReport png = write_map(site(), o, dir / "map.png");
    const std::string bytes = test::read_file(dir / "map.png");
    ASSERT_GT(bytes.size(), 24U);
    EXPECT_EQ(bytes.substr(1, 3), "PNG");
    EXPECT_EQ(svg.labels.size(), png.labels.size());
    EXPECT_FALSE(svg.georeferenced);
}

TEST(MapWriter, SheetsAreGeoreferencedPageByPageAfterAnIndex) {
    if (!have_tool("pdfinfo") || !have_tool("gdalinfo")) GTEST_SKIP() << "no pdfinfo/gdalinfo";
    test::ScratchDir dir;
    const auto path = dir / "sheets.pdf";
    MapOptions o = options();
    o.sheets = true;
    o.paper = io::draw::paper_named("A4");  // 200 x 150 m at 1:500 on 297 x 210 mm sheets
    const MapReport r = write_map(site(), o, path);
    ASSERT_EQ(r.layout.pages.size(), 4U);
    EXPECT_TRUE(r.index_page);
    const std::string info = test::command_output("pdfinfo '" + path.string() + "'");
    EXPECT_NE(info.find("Pages:           5"), std::string::npos) << info;
    for (int page = 2; page <= 5; ++page) {
        const PageFrame& f = r.layout.pages[static_cast<std::size_t>(page - 2)];
        const std::string g = test::command_output("gdalinfo 'PDF:" + std::to_string(page) + ":" +
                                                   path.string() + "'");
        EXPECT_NE(g.find("ID[\"EPSG\",5514]]"), std::string::npos) << g;
        expect_box_near(neatline(g), f.extent, 1e-3);  // 1 mm on the ground
    }
    EXPECT_THROW((void)write_map(site(), o, dir / "sheets.svg"), UsageError);
}

TEST(MapWriter, BadRequestsAreClearErrorsAndLeaveNoFile) {
    test::ScratchDir dir;
    MapOptions o = options();
    o.scale = 20;  // 200 m at 1:20 is 10 m of paper
    o.extent = Box2{e0, n0, e0 + 200, n0 + 150};
    EXPECT_THROW((void)write_map(site(), o, dir / "big.pdf"), UsageError);
    EXPECT_FALSE(std::filesystem::exists(dir / "big.pdf"));
    o.scale = 500;
    EXPECT_THROW((void)write_map(site(), o, dir / "map.tif"), UsageError);
    EXPECT_THROW((void)write_map(Tin{}, o, dir / "empty.pdf"), InputError);
    o.crs_wkt = io::crs_to_wkt("EPSG:4326");
    EXPECT_THROW((void)write_map(site(), o, dir / "geo.pdf"), UsageError);
}

}  // namespace
