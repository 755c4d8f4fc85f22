// SPDX-License-Identifier: MIT
// The coordinate grid of the map: crosses at round coordinates (every 100 mm of paper, rounded,
// as on Czech large-scale maps: 50 m at 1:500), ticks at the neat line, and coordinate labels
// along the four edges inside it. In S-JTSK (EPSG:5514 is Krovak East-North with E = -Y and
// N = -X) the labels give the positive Y (along the top and bottom, for the vertical lines) and
// X (left and right, for the horizontal lines), digits grouped by thousands, as Czech maps do.
#include <cmath>

#include "io/map/map_detail.hpp"

namespace dtm::io::map::detail {
namespace {

double nice_near(double v) {
    const double power = std::pow(10.0, std::floor(std::log10(v)));
    double best = power;
    for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
        if (std::abs(m * power - v) < std::abs(best - v)) best = m * power;
    }
    return best;
}

double nice_below(double v) {
    const double power = std::pow(10.0, std::floor(std::log10(v)));
    for (const double m : {5.0, 2.5, 2.0, 1.0}) {
        if (m * power < v * (1.0 - 1e-9)) return m * power;
    }
    return power / 2.0;
}

/// Grid coordinates strictly inside (lo, hi).
std::vector<double> lines_in(double lo, double hi, double step) {
    std::vector<double> out;
    for (double k = std::floor(lo / step) + 1.0; k * step < hi; k += 1.0) {
        if (k * step > lo) out.push_back(k * step);
    }
    return out;
}

bool overlaps(const draw::Rect& a, const draw::Rect& b) {
    return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom();
}

bool under_furniture(const Furniture& f, const draw::Rect& r) {
    for (const draw::Rect& p : f.panels()) {
        const draw::Rect grown{p.x - 1.0, p.y - 1.0, p.width + 2.0, p.height + 2.0};
        if (overlaps(grown, r)) return true;
    }
    return false;
}

draw::TextStyle grid_text(const MapData& data) {
    draw::TextStyle t;
    t.family = data.style.family;
    t.size_pt = data.style.grid_label_pt;
    t.color = data.style.ink;
    t.h = draw::HAlign::center;
    t.v = draw::VAlign::middle;
    t.halo_mm = 0.3;
    return t;
}

}  // namespace

double grid_step(const PageFrame& page) {
    double step = nice_near(100.0 * page.units_per_mm());
    const double w = page.extent.xmax - page.extent.xmin;
    const double h = page.extent.ymax - page.extent.ymin;
    while (step > 0.0 &&
           (lines_in(page.extent.xmin, page.extent.xmax, step).size() < 2 ||
            lines_in(page.extent.ymin, page.extent.ymax, step).size() < 2) &&
           step > std::min(w, h) / 50.0) {
        step = nice_below(step);
    }
    return step;
}

std::vector<GridLabel> grid_labels(const MapData& data, const PageFrame& page, const Furniture& f) {
    const double step = grid_step(page);
    const draw::TextStyle style = grid_text(data);
    const double edge = 2.3;  // text centre from the page edge
    std::vector<GridLabel> out;
    const auto add = [&](Point2 at, std::string text, double angle) {
        const draw::TextSize size = draw::measure_text(text, style);
        const double w = size.width;
        const double h = size.ascent + size.descent;
        const bool vertical = std::abs(angle) > 45.0;
        draw::Rect box = vertical ? draw::Rect{at.x - h / 2.0, at.y - w / 2.0, h, w}
                                  : draw::Rect{at.x - w / 2.0, at.y - h / 2.0, w, h};
        if (under_furniture(f, box)) return;
        if (box.x < 0.0 || box.y < 0.0 || box.right() > page.width_mm ||
            box.bottom() > page.height_mm) {
            return;
        }
        out.push_back({at, std::move(text), angle, box});
    };
    for (const double x : lines_in(page.extent.xmin, page.extent.xmax, step)) {
        const std::string text = data.sjtsk ? "Y " + grouped(-x) : "E " + grouped(x);
        const double px = page.to_page({x, page.extent.ymax}).x;
        const double w = draw::measure_text(text, style).width;
        add({px + 1.0 + w / 2.0, edge}, text, 0.0);
        add({px + 1.0 + w / 2.0, page.height_mm - edge}, text, 0.0);
    }
    for (const double y : lines_in(page.extent.ymin, page.extent.ymax, step)) {
        const std::string text = data.sjtsk ? "X " + grouped(-y) : "N " + grouped(y);
        const double py = page.to_page({page.extent.xmin, y}).y;
        const double w = draw::measure_text(text, style).width;
        add({edge, py - 1.0 - w / 2.0}, text, 90.0);
        add({page.width_mm - edge, py - 1.0 - w / 2.0}, text, 90.0);
    }
    return out;
}

void draw_grid(draw::Canvas& canvas,
               const MapData& data,
               const PageFrame& page,
               const std::vector<GridLabel>& labels) {
    const double step = grid_step(page);
    const draw::Stroke stroke = draw::Stroke::solid(data.style.ink, data.style.grid_mm);
    const double arm = data.style.grid_arm_mm;
    const double tick = 2.0;
    const auto xs = lines_in(page.extent.xmin, page.extent.xmax, step);
    const auto ys = lines_in(page.extent.ymin, page.extent.ymax, step);
    for (const double x : xs) {
        for (const double y : ys) {
            const Point2 c = page.to_page({x, y});
            const std::vector<Point2> h{{c.x - arm, c.y}, {c.x + arm, c.y}};
            const std::vector<Point2> v{{c.x, c.y - arm}, {c.x, c.y + arm}};
            canvas.polyline(h, stroke);
            canvas.polyline(v, stroke);
        }
        const double px = page.to_page({x, 0.0}).x;
        const std::vector<Point2> top{{px, 0.0}, {px, tick}};
        const std::vector<Point2> bottom{{px, page.height_mm - tick}, {px, page.height_mm}};
        canvas.polyline(top, stroke);
        canvas.polyline(bottom, stroke);
    }
    for (const double y : ys) {
        const double py = page.to_page({0.0, y}).y;
        const std::vector<Point2> left{{0.0, py}, {tick, py}};
        const std::vector<Point2> right{{page.width_mm - tick, py}, {page.width_mm, py}};
        canvas.polyline(left, stroke);
        canvas.polyline(right, stroke);
    }
    const draw::TextStyle style = grid_text(data);
    for (const GridLabel& l : labels) canvas.text(l.at, l.text, style, l.angle_deg);
}

}  // namespace dtm::io::map::detail
