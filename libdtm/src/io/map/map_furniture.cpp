// SPDX-License-Identifier: MIT
// The map's furniture: title block, legend, scale bar and north arrow, stacked in one column
// (arrow and scale bar, legend, title block) in the page corner the surface covers least, or
// side by side when the column is taller than the page. The panels are opaque: what they cover
// of the map is hidden, and labels keep clear of them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "dtm/core/error.hpp"
#include "io/map/map_detail.hpp"

namespace dtm::io::map::detail {
namespace {

std::string number(double v, int decimals = -1) {
    char buf[64];
    if (decimals < 0) {
        std::snprintf(buf, sizeof buf, "%g", v);
    } else {
        std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    }
    return buf;
}

std::string unit_name(const PageFrame& page) { return page.unit_m == 1.0 ? " m" : " units"; }

std::string extent_text(const MapData& data, const PageFrame& page) {
    const Box2& e = page.extent;
    if (data.sjtsk) {  // Y = -E, X = -N: the western edge has the largest Y
        return "Y " + grouped(-e.xmax) + " \u2013 " + grouped(-e.xmin) + ", X " + grouped(-e.ymax) +
               " \u2013 " + grouped(-e.ymin);
    }
    return "E " + grouped(e.xmin) + " \u2013 " + grouped(e.xmax) + ", N " + grouped(e.ymin) +
           " \u2013 " + grouped(e.ymax);
}

draw::Rect stack_rect(double x, double y, double w, double h) { return {x, y, w, h}; }

}  // namespace

draw::TextStyle MapStyle::label_text() const {
    draw::TextStyle t;
    t.family = family;
    t.size_pt = label_pt;
    t.color = contour;
    t.h = draw::HAlign::center;
    t.v = draw::VAlign::middle;
    t.halo_mm = 0.15;
    return t;
}

draw::TextStyle MapStyle::spot_text() const {
    draw::TextStyle t;
    t.family = family;
    t.size_pt = spot_pt;
    t.color = ink;
    t.h = draw::HAlign::center;
    t.v = draw::VAlign::middle;
    t.halo_mm = 0.2;
    return t;
}

draw::Stroke MapStyle::stroke_of(ConstraintKind kind) const {
    switch (kind) {
        case ConstraintKind::breakline:
            return {breakline, breakline_mm, {}, true};
        case ConstraintKind::soft_breakline:
            return {breakline, soft_breakline_mm, {1.6, 0.8}, false};
        case ConstraintKind::boundary:
            return {ink, boundary_mm, {4.0, 1.0, 0.6, 1.0}, false};
        case ConstraintKind::hole:
            return {ink, hole_mm, {}, true};
    }
    return draw::Stroke::solid(ink, 0.25);
}

draw::Rect Furniture::bounds() const {
    const double x0 = std::min({north.x, scale_bar.x, legend.x, title.x});
    const double y0 = std::min({north.y, scale_bar.y, legend.y, title.y});
    const double x1 = std::max({north.right(), scale_bar.right(), legend.right(), title.right()});
    const double y1 =
        std::max({north.bottom(), scale_bar.bottom(), legend.bottom(), title.bottom()});
    return {x0, y0, x1 - x0, y1 - y0};
}

draw::TitleBlock title_block(const MapData& data,
                             const PageFrame& page,
                             const std::string& sheet_text) {
    const MapOptions& o = data.options;
    draw::TitleBlock b;
    b.title = o.title.empty() ? "Contour map" : o.title;
    b.fields.emplace_back("Scale", "1 : " + number(page.scale));
    if (!sheet_text.empty()) b.fields.emplace_back("Sheet", sheet_text);
    b.fields.emplace_back("Coordinates", data.crs_name.empty() ? "no CRS given" : data.crs_name);
    b.fields.emplace_back("Heights", o.vertical_datum.empty()
                                         ? "in" + unit_name(page) + ", datum not given"
                                         : o.vertical_datum + " (in" + unit_name(page) + ")");
    b.fields.emplace_back(
        "Contours",
        "interval " + number(data.interval) + unit_name(page) + ", index contours every " +
            number(data.interval * static_cast<double>(data.index_every)) + unit_name(page));
    b.fields.emplace_back("Extent", extent_text(data, page));
    std::string sources;
    for (const std::string& s : o.sources) sources += (sources.empty() ? "" : ", ") + s;
    b.fields.emplace_back("Sources", sources.empty() ? "\u2013" : sources);
    b.fields.emplace_back("Date", data.date);
    b.fields.emplace_back("Software", std::string("dtm ") + DTM_VERSION);
    return b;
}

std::vector<draw::LegendEntry> legend_entries(const MapData& data) {
    const MapStyle& s = data.style;
    using Kind = draw::LegendEntry::Kind;
    std::vector<draw::LegendEntry> e;
    const std::string& unit = data.unit;
    e.push_back({Kind::line,
                 {s.contour, s.index_mm, {}, true},
                 {},
                 0.6,
                 "Index contour, every " +
                     number(data.interval * static_cast<double>(data.index_every)) + unit});
    e.push_back({Kind::line,
                 {s.contour, s.contour_mm, {}, true},
                 {},
                 0.6,
                 "Contour, interval " + number(data.interval) + unit});
    if (data.options.spots != SpotMode::none) {
        e.push_back({Kind::marker, {}, s.ink, s.spot_dot_mm, "Spot height"});
    }
    bool kinds[4] = {false, false, false, false};
    for (const ConstraintLine& l : data.constraints) kinds[static_cast<int>(l.kind)] = true;
    const char* names[4] = {"Breakline", "Soft breakline", "Survey boundary", "Hole (no surface)"};
    for (int k = 0; k < 4; ++k) {
        if (!kinds[k]) continue;
        const auto kind = static_cast<ConstraintKind>(k);
        if (kind == ConstraintKind::hole) {
            e.push_back({Kind::fill, s.stroke_of(kind), s.hole_fill, 0.6, names[k]});
        } else {
            e.push_back({Kind::line, s.stroke_of(kind), {}, 0.6, names[k]});
        }
    }
    if (data.options.hillshade) {
        e.push_back({Kind::fill, draw::Stroke::solid(s.ink, 0.1), draw::Color::rgb(0x9a9a9a), 0.6,
                     "Hillshade"});
    }
    return e;
}

FurnitureSize furniture_size(const MapData& data,
                             const PageFrame& page,
                             const draw::TitleBlock& block) {
    FurnitureSize z;
    z.title_w = std::min(88.0, std::max(60.0, page.width_mm * 0.42));
    z.title_h = draw::title_block_height(block, z.title_w);
    std::tie(z.legend_w, z.legend_h) = draw::legend_size(legend_entries(data));
    z.bar_h = draw::scale_bar_area({0, 0}, z.title_w).height;
    z.top_h = std::max(z.arrow + 3.0, z.bar_h);
    z.column_w = std::max(z.title_w, z.legend_w);
    z.column_h = z.top_h + z.gap + z.legend_h + z.gap + z.title_h;
    z.row_w = z.legend_w + z.gap + z.title_w;
    z.row_h = std::max(z.legend_h, z.top_h + z.gap + z.title_h);
    return z;
}

Furniture plan_furniture(const MapData& data,
                         const PageFrame& page,
                         const draw::TitleBlock& block,
                         const CoverageFn& coverage) {
    const double inset = data.style.furniture_inset_mm;
    const FurnitureSize z = furniture_size(data, page, block);
    const double free_w = page.width_mm - 2.0 * inset;
    const double free_h = page.height_mm - 2.0 * inset;
    // Arrangements (column first) x corners (lower right first, as ISO 7200, then lower left,
    // upper right, upper left): the least covered wins, earlier ones on near ties.
    int best_arrangement = -1;
    double bx = 0.0;
    double by = 0.0;
    double best_cover = 2.0;
    for (int arrangement = 0; arrangement < 2; ++arrangement) {
        const double w = arrangement == 0 ? z.column_w : z.row_w;
        const double h = arrangement == 0 ? z.column_h : z.row_h;
        if (w > free_w || h > free_h) continue;
        const double xs[4] = {page.width_mm - inset - w, inset, page.width_mm - inset - w, inset};
        const double ys[4] = {page.height_mm - inset - h, page.height_mm - inset - h, inset, inset};
        for (int c = 0; c < 4; ++c) {
            const double cover = coverage({xs[c], ys[c], w, h});
            if (cover < best_cover - 0.02) {
                best_arrangement = arrangement;
                bx = xs[c];
                by = ys[c];
                best_cover = cover;
            }
        }
    }
    if (best_arrangement < 0) {
        throw UsageError("map: the page (" + number(page.width_mm, 0) + " x " +
                         number(page.height_mm, 0) +
                         " mm) is too small for the title block and legend; use a larger extent, "
                         "a larger scale or `paper`");
    }
    Furniture f;
    if (best_arrangement == 0) {
        const double right = bx + z.column_w;
        f.north = stack_rect(right - z.title_w, by, z.arrow, z.top_h);
        f.scale_bar = stack_rect(right - z.title_w + z.arrow + 4.0, by + (z.top_h - z.bar_h) / 2.0,
                                 z.title_w - z.arrow - 4.0, z.bar_h);
        f.legend = stack_rect(right - z.legend_w, by + z.top_h + z.gap, z.legend_w, z.legend_h);
        f.title = stack_rect(right - z.title_w, by + z.top_h + z.gap + z.legend_h + z.gap,
                             z.title_w, z.title_h);
    } else {
        f.legend = stack_rect(bx, by + z.row_h - z.legend_h, z.legend_w, z.legend_h);
        const double tx = bx + z.legend_w + z.gap;
        f.north = stack_rect(tx, by + z.row_h - z.title_h - z.gap - z.top_h, z.arrow, z.top_h);
        f.scale_bar = stack_rect(tx + z.arrow + 4.0, f.north.y + (z.top_h - z.bar_h) / 2.0,
                                 z.title_w - z.arrow - 4.0, z.bar_h);
        f.title = stack_rect(tx, by + z.row_h - z.title_h, z.title_w, z.title_h);
    }
    f.cover = best_cover;
    return f;
}

void draw_furniture(draw::Canvas& canvas,
                    const MapData& data,
                    const PageFrame& page,
                    const Furniture& f,
                    const draw::TitleBlock& block) {
    const draw::Color white = draw::Color::rgb(0xffffff);
    const draw::Rect top{f.north.x, f.north.y, f.scale_bar.right() - f.north.x,
                         std::max(f.north.height, f.scale_bar.height)};
    canvas.rectangle({top.x - 1.0, top.y - 1.0}, top.width + 2.0, top.height + 2.0, &white,
                     nullptr);
    draw::draw_north_arrow(canvas, {f.north.x + f.north.width / 2.0, f.north.y + 3.0 + 5.0}, 10.0,
                           data.north_known ? data.north_deg : 0.0, "N");
    draw::draw_scale_bar(canvas, {f.scale_bar.x, f.scale_bar.y}, f.scale_bar.width, page.scale,
                         page.unit_m);
    draw::draw_legend(canvas, legend_entries(data), {f.legend.x, f.legend.y});
    draw::draw_title_block(canvas, block, f.title);
}

std::string level_text(double v) {
    for (int d = 0; d <= 6; ++d) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*f", d, v);
        if (std::abs(std::strtod(buf, nullptr) - v) < 1e-9) {
            std::string s = buf;
            return s == "-0" ? "0" : s;
        }
    }
    return number(v);
}

std::string grouped(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f", std::abs(v));
    std::string digits = buf;
    std::string out;
    const std::size_t n = digits.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0 && (n - i) % 3 == 0) out += "\u202f";  // narrow no-break space
        out += digits[i];
    }
    return (v < 0 && std::lround(v) != 0 ? "-" : "") + out;
}

}  // namespace dtm::io::map::detail
