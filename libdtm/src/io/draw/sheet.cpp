// SPDX-License-Identifier: MIT
// Sheet furniture on a Canvas. Paper sizes are ISO 216 (A0 = 841 x 1189 mm, each next size half
// of the previous, rounded down to whole millimetres). The title block follows the spirit of
// ISO 7200 (lower right corner of the frame; title, identifying fields, responsibility): the
// fields are the caller's, the signature row is left blank for the surveyor. The scale bar
// lengths are 1, 2, 2.5 or 5 x 10^k ground units, as on survey plans.
#include "dtm/io/draw/sheet.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "dtm/core/error.hpp"

namespace dtm::io::draw {
namespace {

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

TextStyle text_style(const SheetStyle& s, double pt, bool bold = false) {
    TextStyle t;
    t.family = s.family;
    t.size_pt = pt;
    t.bold = bold;
    t.color = s.ink;
    return t;
}

double line_height(const SheetStyle& s, double pt) {
    const TextSize m = measure_text("Ág", text_style(s, pt));
    return (m.ascent + m.descent) * 1.25;
}

/// Splits @p text into lines no wider than @p width (at spaces and after commas; a word longer
/// than the width stays whole).
std::vector<std::string> wrap(const std::string& text, double width, const TextStyle& style) {
    std::vector<std::string> lines;
    std::string line;
    std::string word;
    const auto flush_word = [&]() {
        if (word.empty()) return;
        const std::string candidate = line.empty() ? word : line + " " + word;
        if (!line.empty() && measure_text(candidate, style).width > width) {
            lines.push_back(line);
            line = word;
        } else {
            line = candidate;
        }
        word.clear();
    };
    for (const char c : text) {
        if (c == ' ') {
            flush_word();
        } else {
            word += c;
        }
    }
    flush_word();
    if (!line.empty() || lines.empty()) lines.push_back(line);
    return lines;
}

struct BlockMetrics {
    double pad = 1.5;
    double label_width = 0.0;
    double title_height = 0.0;
    double row = 0.0;
    double signature = 0.0;
};

BlockMetrics block_metrics(const TitleBlock& block, double width, const SheetStyle& s) {
    BlockMetrics m;
    m.title_height = line_height(s, s.title_pt) + 2.0 * m.pad;
    m.row = line_height(s, s.text_pt);
    m.signature = block.signature ? 3.0 * m.row + 2.0 * m.pad : 0.0;
    for (const auto& field : block.fields) {
        m.label_width =
            std::max(m.label_width, measure_text(field.first, text_style(s, s.small_pt)).width);
    }
    m.label_width = std::min(m.label_width + 2.0 * m.pad, width * 0.4);
    return m;
}

double nice_down(double value) {
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    for (const double m : {5.0, 2.5, 2.0, 1.0}) {
        if (m * power <= value * (1.0 + 1e-12)) return m * power;
    }
    return power;
}

std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

std::vector<Paper> standard_papers() {
    return {
        {"A4", 210, 297}, {"A3", 297, 420}, {"A2", 420, 594}, {"A1", 594, 841}, {"A0", 841, 1189}};
}

Paper paper_named(std::string_view name) {
    const std::string n = lower(name);
    for (const Paper& p : standard_papers()) {
        if (lower(p.name) == n) return p;
    }
    double w = 0.0;
    double h = 0.0;
    char unit[8] = {0};
    const int read = std::sscanf(n.c_str(), "%lfx%lf%7s", &w, &h, unit);
    const std::string u = read == 3 ? unit : "mm";
    if (read >= 2 && u == "mm" && w > 0.0 && h > 0.0 && std::isfinite(w) && std::isfinite(h)) {
        return {std::string(name), std::min(w, h), std::max(w, h)};
    }
    throw UsageError("unknown paper '" + std::string(name) +
                     "': give A4, A3, A2, A1, A0 or WIDTHxHEIGHTmm (e.g. 500x700mm)");
}

Orientation orientation_named(std::string_view name) {
    const std::string n = lower(name);
    if (n == "auto") return Orientation::automatic;
    if (n == "portrait") return Orientation::portrait;
    if (n == "landscape") return Orientation::landscape;
    throw UsageError("unknown orientation '" + std::string(name) +
                     "': give auto, portrait or landscape");
}

std::pair<double, double> page_size(const Paper& paper, Orientation orientation) {
    if (orientation == Orientation::landscape) return {paper.height_mm, paper.width_mm};
    return {paper.width_mm, paper.height_mm};
}

double title_block_height(const TitleBlock& block, double width, const SheetStyle& s) {
    const BlockMetrics m = block_metrics(block, width, s);
    const TextStyle value = text_style(s, s.text_pt);
    double h = m.title_height;
    for (const auto& field : block.fields) {
        const auto lines = wrap(field.second, width - m.label_width - 2.0 * m.pad, value);
        h += static_cast<double>(lines.size()) * m.row + m.pad;
    }
    return h + m.signature;
}

void draw_title_block(Canvas& canvas,
                      const TitleBlock& block,
                      const Rect& area,
                      const SheetStyle& s) {
    const BlockMetrics m = block_metrics(block, area.width, s);
    const Color white = Color::rgb(0xffffff);
    const Stroke frame = Stroke::solid(s.ink, s.frame_mm * 0.7);
    const Stroke rule = Stroke::solid(s.ink, s.rule_mm);
    canvas.rectangle({area.x, area.y}, area.width, area.height, &white, &frame);
    TextStyle title = text_style(s, s.title_pt, true);
    title.v = VAlign::middle;
    canvas.text({area.x + m.pad, area.y + m.title_height / 2.0}, block.title, title);
    double y = area.y + m.title_height;
    const TextStyle label = text_style(s, s.small_pt);
    const TextStyle value = text_style(s, s.text_pt);
    const double value_x = area.x + m.label_width + m.pad;
    for (const auto& field : block.fields) {
        const std::vector<Point2> line{{area.x, y}, {area.right(), y}};
        canvas.polyline(line, rule);
        const auto lines = wrap(field.second, area.right() - value_x - m.pad, value);
        const double row_top = y;
        for (const std::string& text : lines) {
            y += m.row;
            canvas.text({value_x, y - m.row * 0.25}, text, value);
        }
        canvas.text({area.x + m.pad, row_top + m.row * 0.75}, field.first, label);
        y += m.pad;
    }
    const std::vector<Point2> divider{{value_x - m.pad, area.y + m.title_height},
                                      {value_x - m.pad, y}};
    canvas.polyline(divider, rule);
    if (block.signature) {
        const std::vector<Point2> line{{area.x, y}, {area.right(), y}};
        canvas.polyline(line, rule);
        const double half = area.width / 2.0;
        canvas.text({area.x + m.pad, y + m.row}, "Surveyor", label);
        canvas.text({area.x + half + m.pad, y + m.row}, "Signature", label);
        const std::vector<Point2> mid{{area.x + half, y}, {area.x + half, area.bottom()}};
        canvas.polyline(mid, rule);
    }
}

Rect scale_bar_area(Point2 at, double max_width_mm, const SheetStyle& s) {
    return {at.x, at.y, max_width_mm, line_height(s, s.text_pt) * 2.0 + 2.0};
}

Rect draw_scale_bar(Canvas& canvas,
                    Point2 at,
                    double max_width_mm,
                    double scale,
                    double unit_m,
                    const SheetStyle& s) {
    const Rect area = scale_bar_area(at, max_width_mm, s);
    const double mm_per_unit = 1000.0 * unit_m / scale;  // page mm per ground unit
    const double usable = max_width_mm - 8.0;            // room for the unit after the last label
    const double total = nice_down(usable / mm_per_unit);
    const double mantissa = total / std::pow(10.0, std::floor(std::log10(total)));
    const int parts = std::abs(mantissa - 2.0) < 1e-9 ? 4 : 5;
    const double step = total / parts;
    const double row = line_height(s, s.text_pt);
    TextStyle head = text_style(s, s.text_pt, true);
    canvas.text({at.x, at.y + row * 0.8}, "1 : " + number_text(scale), head);
    const double bar_y = at.y + row + 0.5;
    const double bar_h = 1.4;
    const Color black = s.ink;
    const Color white = Color::rgb(0xffffff);
    const Stroke edge = Stroke::solid(s.ink, 0.15);
    TextStyle tick = text_style(s, s.small_pt);
    tick.h = HAlign::center;
    tick.v = VAlign::top;
    for (int i = 0; i < parts; ++i) {
        const double x = at.x + static_cast<double>(i) * step * mm_per_unit;
        canvas.rectangle({x, bar_y}, step * mm_per_unit, bar_h, i % 2 == 0 ? &black : &white,
                         &edge);
    }
    // Labels under the segment ends, centred; one that would touch its left neighbour or the
    // last label (with the unit) is left out, so short bars at small scales stay legible.
    const auto label = [&](int i) {
        std::string text = number_text(step * i);
        if (i == parts) text += unit_m == 1.0 ? " m" : "";
        return text;
    };
    const auto x_of = [&](int i) { return at.x + static_cast<double>(i) * step * mm_per_unit; };
    const double gap = 0.8;
    const double last_left = x_of(parts) - measure_text(label(parts), tick).width / 2.0;
    double drawn_right = -1e300;
    for (int i = 0; i <= parts; ++i) {
        const std::string text = label(i);
        const double half = measure_text(text, tick).width / 2.0;
        if (i > 0 && i < parts &&
            (x_of(i) - half < drawn_right + gap || x_of(i) + half > last_left - gap)) {
            continue;
        }
        canvas.text({x_of(i), bar_y + bar_h + 0.6}, text, tick);
        drawn_right = x_of(i) + half;
    }
    return area;
}

void draw_north_arrow(Canvas& canvas,
                      Point2 centre,
                      double height_mm,
                      double angle_deg,
                      std::string_view letter,
                      const SheetStyle& s) {
    const double a = angle_deg * 3.14159265358979323846 / 180.0;
    const auto rot = [&](double x, double y) {  // (x right, y up) rotated, to page coordinates
        return Point2{centre.x + x * std::cos(a) - y * std::sin(a),
                      centre.y - (x * std::sin(a) + y * std::cos(a))};
    };
    const double h = height_mm / 2.0;
    const double w = height_mm * 0.18;
    const std::vector<std::vector<Point2>> left{{rot(0, h), rot(-w, -h), rot(0, -h * 0.55)}};
    const std::vector<std::vector<Point2>> right{{rot(0, h), rot(w, -h), rot(0, -h * 0.55)}};
    const Stroke outline = Stroke::solid(s.ink, 0.18);
    canvas.polygon(left, s.ink, &outline);
    canvas.polygon(right, Color::rgb(0xffffff), &outline);
    TextStyle t = text_style(s, s.title_pt, true);
    t.h = HAlign::center;
    t.v = VAlign::bottom;
    canvas.text(rot(0, h + 0.8), letter, t);
}

std::pair<double, double> legend_size(const std::vector<LegendEntry>& entries,
                                      const SheetStyle& s) {
    const double row = line_height(s, s.text_pt) * 1.15;
    double width = measure_text("Legend", text_style(s, s.text_pt, true)).width;
    for (const LegendEntry& e : entries) {
        width = std::max(width, 12.0 + measure_text(e.text, text_style(s, s.text_pt)).width);
    }
    return {width + 4.0, row * static_cast<double>(entries.size() + 1) + 3.0};
}

void draw_legend(Canvas& canvas,
                 const std::vector<LegendEntry>& entries,
                 Point2 top_left,
                 const SheetStyle& s) {
    const auto [w, h] = legend_size(entries, s);
    const double row = line_height(s, s.text_pt) * 1.15;
    const Color white = Color::rgb(0xffffff);
    const Stroke frame = Stroke::solid(s.ink, s.frame_mm * 0.7);
    canvas.rectangle(top_left, w, h, &white, &frame);
    TextStyle title = text_style(s, s.text_pt, true);
    title.v = VAlign::middle;
    canvas.text({top_left.x + 2.0, top_left.y + 1.5 + row / 2.0}, "Legend", title);
    TextStyle text = text_style(s, s.text_pt);
    text.v = VAlign::middle;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const LegendEntry& e = entries[i];
        const double y = top_left.y + 1.5 + row * (static_cast<double>(i) + 1.5);
        const double x = top_left.x + 2.0;
        switch (e.kind) {
            case LegendEntry::Kind::line: {
                const std::vector<Point2> sample{{x, y}, {x + 8.0, y}};
                canvas.polyline(sample, e.stroke);
                break;
            }
            case LegendEntry::Kind::fill:
                canvas.rectangle({x, y - row * 0.3}, 8.0, row * 0.6, &e.fill, &e.stroke);
                break;
            case LegendEntry::Kind::marker:
                canvas.circle({x + 4.0, y}, e.marker_mm / 2.0, &e.fill, nullptr);
                break;
        }
        canvas.text({x + 10.0, y}, e.text, text);
    }
}

SheetLayout sheet_layout(const Paper& paper,
                         Orientation orientation,
                         const TitleBlock& block,
                         double margin_mm,
                         double title_width_mm,
                         const SheetStyle& s) {
    SheetLayout l;
    std::tie(l.width_mm, l.height_mm) = page_size(paper, orientation);
    l.frame = {margin_mm, margin_mm, l.width_mm - 2.0 * margin_mm, l.height_mm - 2.0 * margin_mm};
    const double tw = std::min(title_width_mm, l.frame.width);
    const double th = title_block_height(block, tw, s);
    if (l.frame.width <= 0.0 || th >= l.frame.height * 0.8) {
        throw UsageError("the paper " + paper.name + " is too small for the sheet's title block");
    }
    l.title_block = {l.frame.right() - tw, l.frame.bottom() - th, tw, th};
    l.content = {l.frame.x + 5.0, l.frame.y + 5.0, l.frame.width - 10.0,
                 l.frame.height - th - 10.0};
    return l;
}

void draw_sheet(Canvas& canvas,
                const SheetLayout& layout,
                const TitleBlock& block,
                const SheetStyle& s) {
    const Stroke frame = Stroke::solid(s.ink, s.frame_mm);
    canvas.rectangle({layout.frame.x, layout.frame.y}, layout.frame.width, layout.frame.height,
                     nullptr, &frame);
    draw_title_block(canvas, block, layout.title_block, s);
}

}  // namespace dtm::io::draw
