// SPDX-License-Identifier: MIT
// One map page: place the furniture, the grid labels, the spot heights (beside their markers)
// and then the contour labels around them all, and draw in cartographic order: hillshade,
// holes, contours (interrupted under their labels and spot heights by a clip), breaklines and
// boundary, spot heights, contour numbers, grid, furniture, neat line. Placement works in CRS units
// with the page's scale; drawing converts to page millimetres.
#include <algorithm>
#include <cmath>
#include <map>

#include "dtm/algo/contour_labels.hpp"
#include "dtm/algo/spot_heights.hpp"
#include "io/map/map_detail.hpp"

namespace dtm::io::map::detail {
namespace {

bool intersects(const Box2& a, const Box2& b) {
    return a.xmin <= b.xmax && b.xmin <= a.xmax && a.ymin <= b.ymax && b.ymin <= a.ymax;
}

Box2 line_bounds(std::span<const Point3> pts) {
    Box2 b;
    for (const Point3& p : pts) b.add(p);
    return b;
}

Box2 inset(const Box2& b, double d) { return {b.xmin + d, b.ymin + d, b.xmax - d, b.ymax - d}; }

/// Page polyline with points closer than @p tolerance mm to the last kept one dropped.
std::vector<Point2> to_page(const PageFrame& page, std::span<const Point3> pts, double tolerance) {
    std::vector<Point2> out;
    out.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const Point2 p = page.to_page(pts[i].xy());
        if (!out.empty() && i + 1 < pts.size() &&
            std::abs(p.x - out.back().x) + std::abs(p.y - out.back().y) < tolerance) {
            continue;
        }
        out.push_back(p);
    }
    return out;
}

std::vector<Point2> page_corners(const PageFrame& page, const LabelBox& box) {
    std::vector<Point2> out;
    for (const Point2& c : box.corners()) out.push_back(page.to_page(c));
    return out;
}

struct PagePlan {
    Furniture furniture;
    draw::TitleBlock block;
    std::vector<GridLabel> grid;
    std::vector<LabelBox> obstacles;  ///< CRS units
    Box2 label_frame;
};

PagePlan plan_page(const MapData& data, const PageFrame& page, const std::string& sheet_text) {
    PagePlan plan;
    plan.block = title_block(data, page, sheet_text);
    plan.furniture = plan_furniture(data, page, plan.block, surface_coverage(data, page));
    plan.grid = grid_labels(data, page, plan.furniture);
    for (const draw::Rect& r : plan.furniture.panels()) {
        plan.obstacles.push_back(
            LabelBox::of(page.ground_box({r.x - 1.0, r.y - 1.0, r.width + 2.0, r.height + 2.0})));
    }
    for (const GridLabel& g : plan.grid)
        plan.obstacles.push_back(LabelBox::of(page.ground_box(g.box)));
    plan.label_frame = inset(page.extent, data.style.edge_band_mm * page.units_per_mm());
    return plan;
}

struct Placed {
    std::vector<LabelLine> lines;
    std::vector<const Contour*> contour_of;  ///< per contour line (they come first in lines)
    ContourLabelResult contour_labels;
    std::vector<const SpotHeight*> spots;
    PointLabelResult spot_labels;
};

Placed place(const MapData& data,
             const PageFrame& page,
             const PagePlan& plan,
             const Progress& progress) {
    Placed p;
    const Box2 reach = inset(page.extent, -5.0 * page.units_per_mm());
    const draw::TextStyle label_style = data.style.label_text();
    std::vector<LabelText> texts;
    std::map<double, std::size_t> text_of;
    for (const Contour& c : data.contours) {
        if (!intersects(line_bounds(c.line), reach)) continue;
        LabelLine line{c.line, c.closed, c.level.value, LabelLine::no_label};
        if (c.level.index) {
            const auto [it, fresh] = text_of.try_emplace(c.level.value, texts.size());
            if (fresh) {
                const std::string t = level_text(c.level.value);
                const draw::TextSize size = draw::measure_text(t, label_style);
                texts.push_back({t, size.width, size.ascent + size.descent});
            }
            line.text = it->second;
        }
        p.lines.push_back(line);
        p.contour_of.push_back(&c);
    }
    // breaklines, boundary and holes: never under a label
    for (const ConstraintLine& l : data.constraints) {
        if (!intersects(line_bounds(l.points), reach)) continue;
        LabelLine line{l.points, l.closed, 0.0, LabelLine::no_label};
        line.passable = false;
        p.lines.push_back(line);
    }
    // spot heights first: their markers and heights are obstacles for the contour numbers
    const draw::TextStyle spot_style = data.style.spot_text();
    std::vector<PointLabelRequest> requests;
    for (const SpotHeight& s : data.spots) {
        const Point2 xy = s.point.xy();
        if (xy.x < plan.label_frame.xmin || xy.x > plan.label_frame.xmax ||
            xy.y < plan.label_frame.ymin || xy.y > plan.label_frame.ymax) {
            continue;
        }
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*f", data.spot_decimals, s.point.z);
        const draw::TextSize size = draw::measure_text(buf, spot_style);
        requests.push_back(
            {xy, data.style.spot_dot_mm / 2.0 + 0.1, size.width, size.ascent + size.descent});
        p.spots.push_back(&s);
    }
    PointLabelOptions po;
    po.units_per_mm = page.units_per_mm();
    po.frame = plan.label_frame;
    p.spot_labels = place_point_labels(requests, p.lines, plan.obstacles, po);
    std::vector<LabelBox> obstacles = plan.obstacles;
    for (const PointLabel& l : p.spot_labels.labels) {
        obstacles.push_back(l.box);
        obstacles.push_back(p.spot_labels.markers[l.request]);
    }
    ContourLabelOptions co;
    co.units_per_mm = page.units_per_mm();
    co.spacing_mm = data.options.label_spacing_mm;
    co.frame = plan.label_frame;
    co.axis_aligned_clearance = true;
    co.padding_mm = 1.0;
    co.gap_mm = 0.4;
    p.contour_labels = place_contour_labels(p.lines, texts, obstacles, co, progress);
    return p;
}

void draw_lines(draw::Canvas& canvas, const MapData& data, const PageFrame& page, const Placed& p) {
    const MapStyle& s = data.style;
    // holes first (filled), so contours and lines stay on top
    std::vector<std::vector<Point2>> holes;
    for (const ConstraintLine& l : data.constraints) {
        if (l.kind == ConstraintKind::hole && l.closed)
            holes.push_back(to_page(page, l.points, 0.0));
    }
    if (!holes.empty()) canvas.polygon(holes, s.hole_fill);
    std::vector<std::vector<Point2>> cuts;
    for (const ContourLabel& l : p.contour_labels.labels) {
        cuts.push_back(page_corners(page, l.box.grown(0.4 * page.units_per_mm())));
    }
    for (const PointLabel& l : p.spot_labels.labels) {  // contours stop short of spot heights
        cuts.push_back(page_corners(page, l.box.grown(0.3 * page.units_per_mm())));
    }
    canvas.push_clip_excluding(cuts);
    const draw::Stroke basic{s.contour, s.contour_mm, {}, true};
    const draw::Stroke index{s.contour, s.index_mm, {}, true};
    for (const bool pass_index : {false, true}) {
        for (std::size_t i = 0; i < p.contour_of.size(); ++i) {
            const Contour& c = *p.contour_of[i];
            if (c.level.index != pass_index) continue;
            canvas.polyline(to_page(page, c.line, 0.05), pass_index ? index : basic);
        }
    }
    canvas.pop_clip();
    for (const ConstraintKind kind : {ConstraintKind::hole, ConstraintKind::boundary,
                                      ConstraintKind::soft_breakline, ConstraintKind::breakline}) {
        const draw::Stroke stroke = s.stroke_of(kind);
        for (const ConstraintLine& l : data.constraints) {
            if (l.kind == kind) canvas.polyline(to_page(page, l.points, 0.05), stroke, l.closed);
        }
    }
}

void draw_labels(draw::Canvas& canvas,
                 const MapData& data,
                 const PageFrame& page,
                 const Placed& p) {
    const MapStyle& s = data.style;
    const draw::TextStyle spot_style = s.spot_text();
    for (const PointLabel& l : p.spot_labels.labels) {
        const SpotHeight& spot = *p.spots[l.request];
        canvas.circle(page.to_page(spot.point.xy()), s.spot_dot_mm / 2.0, &s.ink, nullptr);
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*f", data.spot_decimals, spot.point.z);
        canvas.text(page.to_page(l.box.centre), buf, spot_style);
    }
    const draw::TextStyle label_style = s.label_text();
    for (const ContourLabel& l : p.contour_labels.labels) {
        canvas.text(page.to_page(l.box.centre), l.text, label_style, l.angle_deg());
    }
}

PageResult records(const PageFrame& page, const Placed& p) {
    PageResult r;
    for (const ContourLabel& l : p.contour_labels.labels) {
        LabelRecord rec;
        rec.page = page.name;
        rec.text = l.text;
        rec.level = l.level;
        rec.centre = l.box.centre;
        rec.angle_deg = l.angle_deg();
        const std::vector<Point2> corners = page_corners(page, l.box);
        std::copy(corners.begin(), corners.end(), rec.box.begin());
        rec.crosses_lines = l.crosses_lines;
        r.labels.push_back(rec);
    }
    for (const LabelFailure& f : p.contour_labels.failures) {
        r.failures.push_back({page.name, f.level, f.where, f.reason});
    }
    r.lines_too_short = p.contour_labels.lines_too_short;
    r.spots_drawn = p.spot_labels.labels.size();
    r.spot_labels_failed = p.spot_labels.failed.size();
    return r;
}

void draw_hillshade(draw::Canvas& canvas,
                    const MapData& data,
                    const PageFrame& page,
                    const Progress& progress) {
    const double max_pixels = 6e6;
    const double px = std::max(0.25, std::sqrt(page.width_mm * page.height_mm / max_pixels));
    const int cols = std::max(1, static_cast<int>(std::ceil(page.width_mm / px)));
    const double cell_mm = page.width_mm / cols;
    const int rows = std::max(1, static_cast<int>(std::ceil(page.height_mm / cell_mm)));
    const std::vector<std::uint8_t> rgba = hillshade_rgba(*data.tin, page, cols, rows, progress);
    canvas.image(rgba, cols, rows, {0.0, 0.0}, cols * cell_mm, rows * cell_mm);
}

}  // namespace

PageResult draw_page(draw::Canvas& canvas,
                     const MapData& data,
                     const PageFrame& page,
                     const std::string& sheet_text,
                     const Progress& progress) {
    const PagePlan plan = plan_page(data, page, sheet_text);
    progress.report(0.05, "placing labels");
    const Placed placed = place(data, page, plan, progress.sub(0.05, 0.5));
    if (data.options.hillshade) draw_hillshade(canvas, data, page, progress.sub(0.5, 0.7));
    progress.report(0.7, "drawing");
    draw_lines(canvas, data, page, placed);
    draw_labels(canvas, data, page, placed);
    draw_grid(canvas, data, page, plan.grid);
    draw_furniture(canvas, data, page, plan.furniture, plan.block);
    const draw::Stroke frame = draw::Stroke::solid(data.style.ink, 0.7);
    canvas.rectangle({0.0, 0.0}, page.width_mm, page.height_mm, nullptr, &frame);
    progress.report(1.0, "drawing");
    PageResult result = records(page, placed);
    const Furniture& f = plan.furniture;
    result.furniture = {page.name, f.title,    f.legend,       f.scale_bar,
                        f.north,   plan.block, grid_step(page)};
    return result;
}

void draw_index_page(draw::Canvas& canvas,
                     const MapData& data,
                     const MapLayout& layout,
                     const PageFrame& index) {
    const draw::TitleBlock block =
        title_block(data, index, "index of " + std::to_string(layout.pages.size()) + " sheets");
    const Furniture f = plan_furniture(data, index, block, surface_coverage(data, index));
    const draw::Stroke contour{data.style.contour, 0.18, {}, true};
    for (const Contour& c : data.contours) {
        if (c.level.index) canvas.polyline(to_page(index, c.line, 0.2), contour);
    }
    for (const ConstraintLine& l : data.constraints) {
        if (l.kind == ConstraintKind::boundary || l.kind == ConstraintKind::hole) {
            canvas.polyline(to_page(index, l.points, 0.2), data.style.stroke_of(l.kind), l.closed);
        }
    }
    const draw::Stroke sheet = draw::Stroke::solid(data.style.ink, 0.5);
    draw::TextStyle number;
    number.size_pt = 16.0;
    number.bold = true;
    number.h = draw::HAlign::center;
    number.v = draw::VAlign::middle;
    number.halo_mm = 0.5;
    for (const PageFrame& p : layout.pages) {
        const Point2 a = index.to_page({p.extent.xmin, p.extent.ymax});
        const Point2 b = index.to_page({p.extent.xmax, p.extent.ymin});
        canvas.rectangle(a, b.x - a.x, b.y - a.y, nullptr, &sheet);
        canvas.text({(a.x + b.x) / 2.0, (a.y + b.y) / 2.0}, "Sheet " + p.name, number);
    }
    draw_furniture(canvas, data, index, f, block);
    const draw::Stroke frame = draw::Stroke::solid(data.style.ink, 0.7);
    canvas.rectangle({0.0, 0.0}, index.width_mm, index.height_mm, nullptr, &frame);
}

}  // namespace dtm::io::map::detail
