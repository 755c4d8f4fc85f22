// SPDX-License-Identifier: MIT
// Map sheet layout. The page and the ground are related by the scale alone (page mm = ground
// metres x 1000 / scale), so the whole page is georeferenced and its edge is the neat line.
// Tiled sheets are paper-sized pages in a grid centred on the area asked for, numbered row by
// row from the north-west corner, as map sheet series are.
#include "dtm/io/map/map_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dtm/core/error.hpp"

namespace dtm::io::map {
namespace {

std::string mm_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
}

std::string ground_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

/// A coordinate as written in survey lists: fixed point, at most millimetres, no trailing zeros.
std::string coordinate_text(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    std::string t = buf;
    while (t.back() == '0') t.pop_back();
    if (t.back() == '.') t.pop_back();
    return t;
}

bool fits(double w, double h, double max_w, double max_h) {
    const double tolerance = 1e-6;
    return (w <= max_w + tolerance && h <= max_h + tolerance) ||
           (w <= max_h + tolerance && h <= max_w + tolerance);
}

Box2 centred(Point2 centre, double w, double h) {
    return {centre.x - w / 2.0, centre.y - h / 2.0, centre.x + w / 2.0, centre.y + h / 2.0};
}

PageFrame frame_of(const Box2& extent, const LayoutRequest& r) {
    PageFrame p;
    p.extent = extent;
    p.scale = r.scale;
    p.unit_m = r.unit_m;
    p.width_mm = (extent.xmax - extent.xmin) * p.mm_per_unit();
    p.height_mm = (extent.ymax - extent.ymin) * p.mm_per_unit();
    return p;
}

std::string scale_hint(double w,
                       double h,
                       const LayoutRequest& r,
                       double max_w,
                       double max_h,
                       const std::string& paper) {
    const double s = largest_fitting_scale(w, h, r.unit_m, max_w, max_h);
    std::string hint = s > 0.0 ? "a scale of 1:" + ground_text(s) + " fits " + paper
                               : "no usual scale fits " + paper;
    return hint;
}

MapLayout tiled(const Box2& area, const LayoutRequest& r, const draw::Paper& paper) {
    const double mm = 1000.0 * r.unit_m / r.scale;
    const double aw = (area.xmax - area.xmin) * mm;
    const double ah = (area.ymax - area.ymin) * mm;
    const auto count = [&](double pw, double ph) {
        return std::max(1.0, std::ceil(aw / pw - 1e-9)) * std::max(1.0, std::ceil(ah / ph - 1e-9));
    };
    auto [pw, ph] = draw::page_size(paper, draw::Orientation::portrait);
    if (r.orientation == draw::Orientation::landscape ||
        (r.orientation == draw::Orientation::automatic && count(ph, pw) <= count(pw, ph))) {
        std::swap(pw, ph);
    }
    MapLayout layout;
    layout.paper = paper.name;
    layout.cols = static_cast<int>(std::max(1.0, std::ceil(aw / pw - 1e-9)));
    layout.rows = static_cast<int>(std::max(1.0, std::ceil(ah / ph - 1e-9)));
    const double gw = pw / mm;
    const double gh = ph / mm;
    const Point2 c{(area.xmin + area.xmax) / 2.0, (area.ymin + area.ymax) / 2.0};
    const double x0 = c.x - gw * layout.cols / 2.0;
    const double y1 = c.y + gh * layout.rows / 2.0;
    for (int row = 0; row < layout.rows; ++row) {
        for (int col = 0; col < layout.cols; ++col) {
            const Box2 e{x0 + gw * col, y1 - gh * (row + 1), x0 + gw * (col + 1), y1 - gh * row};
            PageFrame p = frame_of(e, r);
            p.width_mm = pw;  // exactly the paper, free of rounding
            p.height_mm = ph;
            p.row = row;
            p.col = col;
            p.name = std::to_string(row * layout.cols + col + 1);
            layout.pages.push_back(p);
            layout.covered.add(e.xmin, e.ymin);
            layout.covered.add(e.xmax, e.ymax);
        }
    }
    return layout;
}

}  // namespace

Box2 PageFrame::ground_box(const draw::Rect& r) const noexcept {
    const Point2 a = to_ground({r.x, r.y});
    const Point2 b = to_ground({r.right(), r.bottom()});
    Box2 box;
    box.add(a);
    box.add(b);
    return box;
}

double largest_fitting_scale(
    double width, double height, double unit_m, double max_w, double max_h) {
    static const double scales[] = {100,  200,   250,   500,   1000,  2000,  2500,
                                    5000, 10000, 20000, 25000, 50000, 100000};
    for (const double s : scales) {
        const double mm = 1000.0 * unit_m / s;
        if (fits(width * mm, height * mm, max_w, max_h)) return s;
    }
    return 0.0;
}

MapLayout layout_map(const LayoutRequest& r) {
    if (!(r.scale > 0.0) || !std::isfinite(r.scale)) {
        throw UsageError("map: the scale must be a positive number (1:500 is `scale` 500)");
    }
    if (!(r.unit_m > 0.0)) throw UsageError("map: the CRS has no usable linear unit");
    const Box2 area = r.extent ? *r.extent : r.data;
    if (area.empty() || !(area.xmax > area.xmin) || !(area.ymax > area.ymin)) {
        throw UsageError(r.extent ? "map: the extent is empty (give xmin,ymin,xmax,ymax with "
                                    "xmin < xmax and ymin < ymax)"
                                  : "map: the surface has no extent to draw");
    }
    if (r.extent && !r.data.empty() &&
        (r.extent->xmax < r.data.xmin || r.extent->xmin > r.data.xmax ||
         r.extent->ymax < r.data.ymin || r.extent->ymin > r.data.ymax)) {
        throw UsageError("map: the extent does not overlap the surface (" +
                         coordinate_text(r.data.xmin) + ", " + coordinate_text(r.data.ymin) +
                         " .. " + coordinate_text(r.data.xmax) + ", " +
                         coordinate_text(r.data.ymax) + ")");
    }
    const double mm = 1000.0 * r.unit_m / r.scale;
    const double aw = (area.xmax - area.xmin) * mm;
    const double ah = (area.ymax - area.ymin) * mm;
    const draw::Paper a0 = draw::standard_papers().back();
    if (r.sheets) return tiled(area, r, r.paper ? *r.paper : draw::paper_named("A3"));
    MapLayout layout;
    if (!r.paper) {
        if (!fits(aw, ah, a0.width_mm, a0.height_mm)) {
            throw UsageError("map: at 1:" + ground_text(r.scale) + " the extent (" +
                             ground_text(area.xmax - area.xmin) + " x " +
                             ground_text(area.ymax - area.ymin) + ") needs a page of " +
                             mm_text(aw) + " x " + mm_text(ah) +
                             " mm, larger than A0 (841 x 1189 mm): " +
                             scale_hint(area.xmax - area.xmin, area.ymax - area.ymin, r,
                                        a0.width_mm, a0.height_mm, "A0") +
                             "; or split it with `sheets` and `paper`");
        }
        layout.paper = "extent";
        layout.pages.push_back(frame_of(area, r));
        layout.covered = area;
        return layout;
    }
    const draw::Paper& paper = *r.paper;
    auto [pw, ph] = draw::page_size(paper, draw::Orientation::portrait);
    const bool landscape = r.orientation == draw::Orientation::landscape ||
                           (r.orientation == draw::Orientation::automatic && aw > ah);
    if (landscape) std::swap(pw, ph);
    if (aw > pw + 1e-6 || ah > ph + 1e-6) {
        throw UsageError(
            "map: at 1:" + ground_text(r.scale) + " the " +
            (r.extent ? std::string("extent") : std::string("site")) + " needs " + mm_text(aw) +
            " x " + mm_text(ah) + " mm, more than " + paper.name +
            (landscape ? " landscape (" : " portrait (") + mm_text(pw) + " x " + mm_text(ph) +
            " mm): " +
            scale_hint(area.xmax - area.xmin, area.ymax - area.ymin, r, pw, ph, paper.name) +
            ", or use `sheets`, a larger `paper` or a smaller `extent`");
    }
    const Point2 c{(area.xmin + area.xmax) / 2.0, (area.ymin + area.ymax) / 2.0};
    PageFrame p = frame_of(centred(c, pw / mm, ph / mm), r);
    p.width_mm = pw;
    p.height_mm = ph;
    layout.paper = paper.name;
    layout.pages.push_back(p);
    layout.covered = p.extent;
    return layout;
}

}  // namespace dtm::io::map
