// SPDX-License-Identifier: MIT
// Contour labels: the text's up vector points uphill on the TIN, labels sit on straight
// stretches of their line, never overlap each other or obstacles (checked by an independent
// quadrilateral intersection), stay inside the frame, are spread along long lines, and every
// wanted position that found no room is counted with its reason.
#include "dtm/algo/contour_labels.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "dtm/algo/contour.hpp"
#include "dtm/core/error.hpp"
#include "support/map_fixtures.hpp"

namespace {

using namespace dtm;
using dtm::test::hills_tin;
using dtm::test::quads_overlap;
using dtm::test::tin_height;

struct Labelled {
    std::vector<Contour> contours;
    std::vector<LabelLine> lines;
    std::vector<LabelText> texts;
    std::map<double, std::size_t> text_of_level;
};

/// Contours of @p tin every metre, index every 5; texts sized like 8 pt digits (2 mm per
/// character, 3 mm high).
Labelled labelled_contours(const Tin& tin, double char_mm = 2.0) {
    Labelled l;
    ContourOptions co;
    co.interval = 1.0;
    co.index_every = 5;
    l.contours = contour(tin, co);
    for (const Contour& c : l.contours) {
        LabelLine line{c.line, c.closed, c.level.value, LabelLine::no_label};
        if (c.level.index) {
            auto [it, fresh] = l.text_of_level.try_emplace(c.level.value, l.texts.size());
            if (fresh) {
                const std::string t = std::to_string(static_cast<long>(std::lround(c.level.value)));
                l.texts.push_back({t, char_mm * static_cast<double>(t.size()), 3.0});
            }
            line.text = it->second;
        }
        l.lines.push_back(line);
    }
    return l;
}

/// Distance from @p p to the polyline.
double distance_to_line(std::span<const Point3> line, Point2 p) {
    double best = 1e300;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const double ax = line[i].x, ay = line[i].y;
        const double bx = line[i + 1].x - ax, by = line[i + 1].y - ay;
        const double len2 = bx * bx + by * by;
        double t = len2 > 0 ? ((p.x - ax) * bx + (p.y - ay) * by) / len2 : 0.0;
        t = std::clamp(t, 0.0, 1.0);
        best = std::min(best, std::hypot(p.x - ax - t * bx, p.y - ay - t * by));
    }
    return best;
}

TEST(ContourLabels, ReadUphillSitOnTheirLineAndNeverOverlap) {
    const Tin tin = hills_tin(3000, 7, -744000.0, -1045000.0);
    const Labelled l = labelled_contours(tin);
    ContourLabelOptions o;
    o.units_per_mm = 0.5;  // 1:500
    o.spacing_mm = 80.0;
    const ContourLabelResult r = place_contour_labels(l.lines, l.texts, {}, o);
    ASSERT_GT(r.labels.size(), 10U);
    std::size_t checked = 0;
    for (const ContourLabel& a : r.labels) {
        const Contour& c = l.contours[a.line];
        EXPECT_TRUE(c.level.index);
        EXPECT_EQ(a.level, c.level.value);
        EXPECT_EQ(a.text, std::to_string(static_cast<long>(std::lround(c.level.value))));
        // on its line, within the straightness tolerance (0.25 of 3 mm at 1:500)
        EXPECT_LT(distance_to_line(c.line, a.box.centre), 0.25 * 3.0 * 0.5 + 1e-9);
        // the top of the text faces higher ground: 1.5 m either side along the up vector
        const Point2 up = a.box.up();
        const auto above =
            tin_height(tin, a.box.centre.x + 1.5 * up.x, a.box.centre.y + 1.5 * up.y);
        const auto below =
            tin_height(tin, a.box.centre.x - 1.5 * up.x, a.box.centre.y - 1.5 * up.y);
        if (!above || !below) continue;  // at the TIN border
        ++checked;
        EXPECT_GT(*above, *below) << a.text << " at " << a.box.centre.x << " " << a.box.centre.y;
        EXPECT_NEAR(a.box.half_width * 2.0, 2.0 * static_cast<double>(a.text.size()) * 0.5, 1e-9);
        EXPECT_NEAR(a.box.half_height * 2.0, 1.5, 1e-9);
    }
    EXPECT_GT(checked, r.labels.size() * 3 / 4);
    for (std::size_t i = 0; i < r.labels.size(); ++i) {
        for (std::size_t j = i + 1; j < r.labels.size(); ++j) {
            EXPECT_FALSE(quads_overlap(r.labels[i].box.corners(), r.labels[j].box.corners()))
                << r.labels[i].text << " and " << r.labels[j].text;
        }
    }
    // With axis-aligned clearance even the labels' bounding boxes keep apart.
    o.axis_aligned_clearance = true;
    const ContourLabelResult aa = place_contour_labels(l.lines, l.texts, {}, o);
    ASSERT_GT(aa.labels.size(), 10U);
    for (std::size_t i = 0; i < aa.labels.size(); ++i) {
        const Box2 a = aa.labels[i].box.bounds();
        for (std::size_t j = i + 1; j < aa.labels.size(); ++j) {
            const Box2 b = aa.labels[j].box.bounds();
            EXPECT_TRUE(a.xmax <= b.xmin || b.xmax <= a.xmin || a.ymax <= b.ymin ||
                        b.ymax <= a.ymin);
        }
    }
    std::size_t with_text = 0;
    for (const LabelLine& line : l.lines) with_text += line.text != LabelLine::no_label;
    EXPECT_EQ(r.lines_labelled, with_text);
}

TEST(ContourLabels, StraightLineGetsEvenlySpacedLabelsWithTheirTopUphill) {
    // Walking east with higher ground on the right (south): the text's top faces south, so it
    // reads westwards (180 degrees), the Czech rule for a slope falling to the north.
    std::vector<Point3> pts;
    for (int i = 0; i <= 1000; ++i) pts.push_back({static_cast<double>(i), 0.0, 100.0});
    const std::vector<LabelLine> lines{{pts, false, 100.0, 0}};
    const std::vector<LabelText> texts{{"100", 6.0, 3.0}};
    ContourLabelOptions o;
    o.spacing_mm = 100.0;
    const ContourLabelResult r = place_contour_labels(lines, texts, {}, o);
    ASSERT_EQ(r.labels.size(), 10U);
    EXPECT_TRUE(r.failures.empty());
    for (std::size_t i = 0; i < r.labels.size(); ++i) {
        const ContourLabel& a = r.labels[i];
        EXPECT_NEAR(std::abs(a.angle_deg()), 180.0, 1e-9);
        EXPECT_NEAR(a.box.up().x, 0.0, 1e-12);
        EXPECT_NEAR(a.box.up().y, -1.0, 1e-12);
        EXPECT_NEAR(a.cut_end - a.cut_begin, 6.0 + 2 * o.gap_mm, 1e-9);
        if (i > 0) {
            EXPECT_NEAR(a.box.centre.x - r.labels[i - 1].box.centre.x, 98.6, 1e-6);
        }
    }
    // Reversed line: higher ground now north, text reads east.
    std::vector<Point3> rev(pts.rbegin(), pts.rend());
    const std::vector<LabelLine> back{{rev, false, 100.0, 0}};
    const ContourLabelResult rb = place_contour_labels(back, texts, {}, o);
    ASSERT_FALSE(rb.labels.empty());
    EXPECT_NEAR(rb.labels[0].angle_deg(), 0.0, 1e-9);
}

TEST(ContourLabels, ObstaclesAndFrameAreRespectedAndFailuresCounted) {
    std::vector<Point3> pts;
    for (int i = 0; i <= 200; ++i) pts.push_back({static_cast<double>(i), 0.0, 10.0});
    const std::vector<LabelLine> lines{{pts, false, 10.0, 0}};
    const std::vector<LabelText> texts{{"10", 4.0, 3.0}};
    ContourLabelOptions o;
    o.spacing_mm = 50.0;
    // An obstacle over the whole line: nothing fits, four wanted positions counted as crowded.
    const std::vector<LabelBox> wall{LabelBox::of({-10, -10, 210, 10})};
    const ContourLabelResult r = place_contour_labels(lines, texts, wall, o);
    EXPECT_TRUE(r.labels.empty());
    ASSERT_EQ(r.failures.size(), 4U);
    for (const LabelFailure& f : r.failures) {
        EXPECT_EQ(f.reason, LabelFailureReason::crowded);
        EXPECT_EQ(f.level, 10.0);
    }
    // An obstacle over the left half: labels only on the right half, clear of it.
    const std::vector<LabelBox> half{LabelBox::of({-10, -10, 100, 10})};
    const ContourLabelResult h = place_contour_labels(lines, texts, half, o);
    ASSERT_FALSE(h.labels.empty());
    for (const ContourLabel& a : h.labels) {
        EXPECT_FALSE(quads_overlap(a.box.corners(), half[0].corners()));
        EXPECT_GT(a.box.bounds().xmin, 100.0);
    }
    EXPECT_EQ(h.labels.size() + h.failures.size(), 4U);
    // A frame that only the middle of the line is inside.
    o.frame = Box2{80, -20, 120, 20};
    const ContourLabelResult f = place_contour_labels(lines, texts, {}, o);
    for (const ContourLabel& a : f.labels) {
        const Box2 b = a.box.bounds();
        EXPECT_GE(b.xmin, 80.0);
        EXPECT_LE(b.xmax, 120.0);
    }
    EXPECT_EQ(f.labels.size() + f.failures.size(), 4U);
    bool outside = false;
    for (const LabelFailure& x : f.failures) outside |= x.reason == LabelFailureReason::outside;
    EXPECT_TRUE(outside);
}

TEST(ContourLabels, CurvedShortAndCrossedLines) {
    // A zigzag with 1 mm teeth is never straight over a 6 mm label.
    std::vector<Point3> zig;
    for (int i = 0; i <= 100; ++i) zig.push_back({static_cast<double>(i), (i % 2) * 1.5, 5.0});
    // A ring smaller than its label.
    std::vector<Point3> ring;
    for (int i = 0; i <= 16; ++i) {
        const double a = 2 * 3.14159265358979 * i / 16;
        ring.push_back({300 + std::cos(a), std::sin(a), 5.0});
    }
    ring.back() = ring.front();
    const std::vector<LabelText> texts{{"5", 6.0, 3.0}};
    const std::vector<LabelLine> lines{{zig, false, 5.0, 0}, {ring, true, 5.0, 0}};
    const ContourLabelResult r = place_contour_labels(lines, texts, {}, {});
    EXPECT_TRUE(r.labels.empty());
    EXPECT_EQ(r.lines_labelled, 2U);
    EXPECT_EQ(r.lines_too_short, 1U);
    ASSERT_EQ(r.failures.size(), 1U);
    EXPECT_EQ(r.failures[0].reason, LabelFailureReason::curved);

    // A labelled line crossed every 2 mm by another labelled line: no free stretch.
    std::vector<Point3> base;
    for (int i = 0; i <= 60; ++i) base.push_back({static_cast<double>(i), 0.0, 1.0});
    std::vector<std::vector<Point3>> ticks;
    for (int i = 0; i <= 60; i += 2) {
        ticks.push_back({{static_cast<double>(i), -5.0, 2.0}, {static_cast<double>(i), 5.0, 2.0}});
    }
    std::vector<LabelLine> crossed{{base, false, 1.0, 0}};
    for (const auto& t : ticks) crossed.push_back({t, false, 2.0, 1});
    const std::vector<LabelText> two{{"1", 6.0, 3.0}, {"2", 30.0, 3.0}};
    const ContourLabelResult c = place_contour_labels(crossed, two, {}, {});
    EXPECT_TRUE(c.labels.empty());
    ASSERT_EQ(c.failures.size(), 1U);
    EXPECT_EQ(c.failures[0].reason, LabelFailureReason::crossed);
    // Unlabelled crossing lines: accepted as a fallback, flagged, or refused on request.
    for (std::size_t i = 1; i < crossed.size(); ++i) crossed[i].text = LabelLine::no_label;
    const ContourLabelResult u = place_contour_labels(crossed, two, {}, {});
    ASSERT_EQ(u.labels.size(), 1U);
    EXPECT_TRUE(u.labels[0].crosses_lines);
    ContourLabelOptions strict;
    strict.allow_crossing_unlabelled = false;
    EXPECT_TRUE(place_contour_labels(crossed, two, {}, strict).labels.empty());
    // Lines that may never be covered (breaklines): no fallback either.
    for (std::size_t i = 1; i < crossed.size(); ++i) crossed[i].passable = false;
    const ContourLabelResult hard = place_contour_labels(crossed, two, {}, {});
    EXPECT_TRUE(hard.labels.empty());
    ASSERT_EQ(hard.failures.size(), 1U);
    EXPECT_EQ(hard.failures[0].reason, LabelFailureReason::crossed);
}

TEST(ContourLabels, RejectsBadOptions) {
    ContourLabelOptions o;
    o.units_per_mm = 0.0;
    EXPECT_THROW((void)place_contour_labels({}, {}, {}, o), UsageError);
    std::vector<Point3> pts{{0, 0, 0}, {10, 0, 0}};
    const std::vector<LabelLine> lines{{pts, false, 0.0, 3}};
    EXPECT_THROW((void)place_contour_labels(lines, {}, {}, {}), UsageError);
}

TEST(LabelBox, OverlapAgreesWithQuadrilateralIntersection) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-5.0, 5.0);
    std::uniform_real_distribution<double> ang(0.0, 6.283185307179586);
    std::uniform_real_distribution<double> size(0.5, 4.0);
    int agree = 0;
    for (int i = 0; i < 5000; ++i) {
        const double a = ang(rng), b = ang(rng);
        const LabelBox p{{u(rng), u(rng)}, {std::cos(a), std::sin(a)}, size(rng), size(rng)};
        const LabelBox q{{u(rng), u(rng)}, {std::cos(b), std::sin(b)}, size(rng), size(rng)};
        EXPECT_EQ(overlaps(p, q), quads_overlap(p.corners(), q.corners()));
        agree += overlaps(p, q) ? 1 : 0;
    }
    EXPECT_GT(agree, 500);  // both outcomes exercised
    EXPECT_LT(agree, 4500);
    const LabelBox box{{0, 0}, {0.6, 0.8}, 2.0, 1.0};
    EXPECT_TRUE(crosses(box, {-5, 0}, {5, 0}));
    EXPECT_FALSE(crosses(box, {-5, 3}, {5, 3}));
    EXPECT_TRUE(crosses(box, {0.1, 0.1}, {0.1, 0.1}));   // a point inside
    EXPECT_FALSE(crosses(box, {4.0, 4.0}, {4.0, 4.0}));  // a point outside
}

}  // namespace
