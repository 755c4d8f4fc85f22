// SPDX-License-Identifier: MIT
// Oriented label rectangles. Overlap is the separating-axis test of two rectangles (the four
// edge normals are the only candidate axes; Gottschalk, Lin, Manocha, "OBBTree", SIGGRAPH 1996);
// a segment crosses a box when its Liang-Barsky clip against the box, in the box's own frame,
// keeps a piece of positive length.
#include "dtm/algo/label_box.hpp"

#include <algorithm>

namespace dtm {
namespace {

double dot(Point2 a, Point2 b) noexcept { return a.x * b.x + a.y * b.y; }

/// Half the extent of @p box projected on the unit vector @p dir.
double projected_radius(const LabelBox& box, Point2 dir) noexcept {
    return box.half_width * std::abs(dot(box.axis, dir)) +
           box.half_height * std::abs(dot(box.up(), dir));
}

}  // namespace

std::array<Point2, 4> LabelBox::corners() const noexcept {
    const Point2 u = up();
    const Point2 w{axis.x * half_width, axis.y * half_width};
    const Point2 h{u.x * half_height, u.y * half_height};
    return {{{centre.x - w.x - h.x, centre.y - w.y - h.y},
             {centre.x + w.x - h.x, centre.y + w.y - h.y},
             {centre.x + w.x + h.x, centre.y + w.y + h.y},
             {centre.x - w.x + h.x, centre.y - w.y + h.y}}};
}

Box2 LabelBox::bounds() const noexcept {
    Box2 box;
    for (const Point2& c : corners()) box.add(c);
    return box;
}

bool overlaps(const LabelBox& a, const LabelBox& b) noexcept {
    const Point2 d{b.centre.x - a.centre.x, b.centre.y - a.centre.y};
    for (const Point2 dir : {a.axis, a.up(), b.axis, b.up()}) {
        if (std::abs(dot(d, dir)) >= projected_radius(a, dir) + projected_radius(b, dir)) {
            return false;
        }
    }
    return true;
}

bool crosses(const LabelBox& box, Point2 p, Point2 q) noexcept {
    const Point2 u = box.up();
    const Point2 rp{p.x - box.centre.x, p.y - box.centre.y};
    const Point2 rq{q.x - box.centre.x, q.y - box.centre.y};
    // The segment in box coordinates: s(t) = a + t (b - a), t in [0, 1].
    const Point2 a{dot(rp, box.axis), dot(rp, u)};
    const Point2 b{dot(rq, box.axis), dot(rq, u)};
    double t0 = 0.0;
    double t1 = 1.0;
    const auto clip = [&](double start, double delta, double limit) {
        // keeps -limit < start + t delta < limit
        if (delta == 0.0) return std::abs(start) < limit;
        double ta = (-limit - start) / delta;
        double tb = (limit - start) / delta;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        return t0 < t1;
    };
    return clip(a.x, b.x - a.x, box.half_width) && clip(a.y, b.y - a.y, box.half_height);
}

bool inside(const LabelBox& box, const Box2& frame) noexcept {
    const Box2 b = box.bounds();
    return b.xmin >= frame.xmin && b.xmax <= frame.xmax && b.ymin >= frame.ymin &&
           b.ymax <= frame.ymax;
}

}  // namespace dtm
