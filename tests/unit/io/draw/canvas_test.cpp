// SPDX-License-Identifier: MIT
// The drawing page and charts: files of the right kind and size, text kept as text in PDFs
// (poppler's pdftotext and pdfinfo, when installed, are the independent readers), atomic output.
#include "dtm/io/draw/canvas.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/draw/chart.hpp"
#include "support/pdf_tools.hpp"
#include "support/test_support.hpp"

namespace dtm::io::draw {
namespace {

using test::command_output;

bool have(const char* tool) { return test::have_tool(tool); }

void draw_sample(Canvas& c) {
    const std::vector<Point2> line{{10, 10}, {100, 50}, {150, 20}};
    c.polyline(line, Stroke{Color::rgb(0x8b4513), 0.5, {}, true});
    TextStyle style;
    style.size_pt = 10;
    style.halo_mm = 0.4;
    c.text({50, 60}, "415.0", style, 90.0);
    c.text({80, 60}, "diagonal", style, 30.0);
    c.text({20, 80}, "Ústí nad Labem", style);
}

TEST(Canvas, PdfKeepsTextAndPageSize) {
    test::ScratchDir dir;
    const auto path = dir / "page.pdf";
    {
        Canvas c(path, 210.0, 297.0);
        draw_sample(c);
        c.finish();
    }
    ASSERT_TRUE(std::filesystem::exists(path));
    EXPECT_EQ(test::read_file(path).substr(0, 5), "%PDF-");
    if (!have("pdftotext") || !have("pdfinfo")) GTEST_SKIP() << "poppler-utils not installed";
    const std::string text = command_output("pdftotext '" + path.string() + "' -");
    EXPECT_NE(text.find("415.0"), std::string::npos) << text;
    EXPECT_NE(text.find("Ústí nad Labem"), std::string::npos) << text;
    const std::string info = command_output("pdfinfo '" + path.string() + "'");
    // A4 in points: 595.276 x 841.89.
    EXPECT_NE(info.find("595.276 x 841.89"), std::string::npos) << info;
}

TEST(Canvas, RotatedTextIsExtractedAsWholeWords) {
    // pdftotext reads text at angles other than multiples of 90 degrees one glyph at a time
    // unless the glyphs carry an /ActualText span: every label must come back whole, in the
    // default, -raw and -layout modes.
    test::ScratchDir dir;
    const auto path = dir / "labels.pdf";
    const std::vector<std::pair<std::string, double>> labels{{"245", 30.0},    {"250.5", -60.0},
                                                             {"1255", 75.0},   {"260", 180.0},
                                                             {"-3.25", 200.0}, {"Ústí", 145.0}};
    {
        Canvas c(path, 200.0, 200.0);
        TextStyle style;
        style.halo_mm = 0.3;
        for (std::size_t i = 0; i < labels.size(); ++i) {
            c.text({30.0 + 25.0 * static_cast<double>(i), 40.0 + 20.0 * static_cast<double>(i)},
                   labels[i].first, style, labels[i].second);
        }
        c.finish();
    }
    if (!have("pdftotext")) GTEST_SKIP() << "poppler-utils not installed";
    for (const std::string mode : {"", "-raw", "-layout"}) {
        std::vector<std::string> words = test::pdf_words(path, mode);
        std::sort(words.begin(), words.end());
        std::vector<std::string> expected;
        for (const auto& l : labels) expected.push_back(l.first);
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(words, expected) << "pdftotext " << mode;
    }
}

TEST(Canvas, MeasuredWidthIsTheDrawnWidth) {
    // Label boxes are computed from measure_text; pdftotext -bbox reports the drawn word.
    test::ScratchDir dir;
    const auto path = dir / "measure.pdf";
    TextStyle style;
    style.size_pt = 6.5;
    const std::string word = "Index-contour-every-5m";
    {
        Canvas c(path, 200.0, 100.0);
        c.text({20.0, 50.0}, word, style);
        c.finish();
    }
    if (!have("pdftotext")) GTEST_SKIP() << "poppler-utils not installed";
    const std::string xml = command_output("pdftotext -bbox '" + path.string() + "' -");
    const auto attr = [&](const std::string& name) {
        const std::size_t at = xml.find(name + "=\"");
        return at == std::string::npos ? -1.0 : std::stod(xml.substr(at + name.size() + 2));
    };
    const double drawn_mm = (attr("xMax") - attr("xMin")) * 25.4 / 72.0;
    const double measured = measure_text(word, style).width;
    EXPECT_NEAR(drawn_mm, measured, 0.01 * measured) << xml;
    EXPECT_NEAR(attr("xMin") * 25.4 / 72.0, 20.0, 0.05);
}

TEST(Canvas, PngHasThePixelSizeOfItsDpi) {
    test::ScratchDir dir;
    const auto path = dir / "page.png";
    Canvas c(path, 25.4, 50.8, 100.0);
    draw_sample(c);
    c.finish();
    const std::string bytes = test::read_file(path);
    ASSERT_GT(bytes.size(), 24u);
    EXPECT_EQ(bytes.substr(1, 3), "PNG");
    const auto be32 = [&](std::size_t at) {
        return (static_cast<unsigned>(static_cast<unsigned char>(bytes[at])) << 24) |
               (static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 1])) << 16) |
               (static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 2])) << 8) |
               static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 3]));
    };
    EXPECT_EQ(be32(16), 100u);  // IHDR width
    EXPECT_EQ(be32(20), 200u);  // IHDR height
}

TEST(Canvas, SvgIsXml) {
    test::ScratchDir dir;
    const auto path = dir / "page.svg";
    Canvas c(path, 100.0, 100.0);
    draw_sample(c);
    c.finish();
    const std::string text = test::read_file(path);
    EXPECT_EQ(text.substr(0, 5), "<?xml");
    EXPECT_NE(text.find("<svg"), std::string::npos);
}

TEST(Canvas, UnfinishedPageWritesNothingAndKeepsTheOldFile) {
    test::ScratchDir dir;
    const auto path = dir / "old.pdf";
    test::write_file(path, "old");
    {
        Canvas c(path, 100.0, 100.0);
        draw_sample(c);
    }
    EXPECT_EQ(test::read_file(path), "old");
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) {
        ++entries;
    }
    EXPECT_EQ(entries, 1u) << "no temporary left behind";
}

TEST(Canvas, RejectsUnknownExtensionsAndEmptyPages) {
    test::ScratchDir dir;
    EXPECT_THROW(Canvas(dir / "page.bmp", 10, 10), UsageError);
    EXPECT_THROW(Canvas(dir / "page.pdf", 0, 10), UsageError);
    EXPECT_THROW(
        {
            Canvas c(dir / "page.svg", 10, 10);
            c.new_page();
        },
        UsageError);
}

TEST(Canvas, MeasuredTextGrowsWithLengthAndSize) {
    TextStyle style;
    const TextSize a = measure_text("100", style);
    const TextSize b = measure_text("1000", style);
    EXPECT_GT(a.width, 0.0);
    EXPECT_GT(b.width, a.width);
    style.size_pt *= 2;
    const TextSize c = measure_text("100", style);
    EXPECT_NEAR(c.width, 2.0 * a.width, 0.05 * a.width);
    EXPECT_GT(c.ascent, a.ascent);
}

TEST(Chart, TicksAreRoundAndCoverTheRange) {
    EXPECT_EQ(axis_ticks(0.0, 10.0, false), (std::vector<double>{0, 2, 4, 6, 8, 10}));
    const auto t = axis_ticks(0.013, 0.087, false);
    ASSERT_FALSE(t.empty());
    EXPECT_NEAR(t.front(), 0.02, 1e-12);
    EXPECT_NEAR(t.back(), 0.08, 1e-12);
    EXPECT_EQ(axis_ticks(1e3, 1e6, true), (std::vector<double>{1e3, 1e4, 1e5, 1e6}));
    EXPECT_EQ(axis_ticks(1.0, 10.0, true), (std::vector<double>{1, 2, 5, 10}));
}

TEST(Chart, WritesLogLogChartsAndRefusesNonPositiveLogValues) {
    test::ScratchDir dir;
    Chart chart;
    chart.title = "time / (N log N)";
    chart.x = {"N", true, {}, {}};
    chart.y = {"ns", true, {}, {}};
    Series walk;
    walk.name = "incremental-walk";
    walk.points = {{1e3, 40}, {1e4, 42}, {1e5, 47}};
    walk.color = Color::rgb(0xd62728);
    chart.series.push_back(walk);
    Bars bars;
    bars.name = "angles";
    bars.edges = {1e3, 1e4, 1e5};
    bars.counts = {10, 20};
    chart.bars.push_back(bars);
    for (const char* name : {"c.pdf", "c.svg", "c.png"}) {
        write_chart(chart, dir / name);
        EXPECT_GT(std::filesystem::file_size(dir / name), 200u) << name;
    }
    if (have("pdftotext")) {
        const std::string text = command_output("pdftotext '" + (dir / "c.pdf").string() + "' -");
        EXPECT_NE(text.find("incremental-walk"), std::string::npos) << text;
    }
    chart.series[0].points.push_back({0.0, 3.0});
    chart.x.min = 0.0;
    EXPECT_THROW(write_chart(chart, dir / "bad.pdf"), UsageError);
    Chart empty;
    EXPECT_THROW(write_chart(empty, dir / "empty.pdf"), UsageError);
}

}  // namespace
}  // namespace dtm::io::draw
