// SPDX-License-Identifier: MIT
//
// Segment against triangle, closed sets: by the separating axis theorem two convex sets are
// disjoint exactly when a line through an edge of one leaves the other strictly on its far side;
// with orient2d every such test is exact. The grid only narrows the candidates: its rounding is
// absorbed by a margin of one cell, and the exact test decides.
#include "dist/segment_touch.hpp"

#include <algorithm>
#include <cmath>

#include "dtm/geom/predicates.hpp"

namespace dtm::dist {
namespace {

int orient(XY a, XY b, XY c) { return geom::orient2d(a.x, a.y, b.x, b.y, c.x, c.y); }

bool lex_less(XY a, XY b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

}  // namespace

bool segment_touches(const TouchSegment& s, const std::array<XY, 3>& t, bool hull_edge) {
    if (hull_edge) {
        const XY u = t[0];
        const XY w = t[1];
        const int o1 = orient(u, w, s.p);
        const int o2 = orient(u, w, s.q);
        if (o1 * o2 > 0) return false;
        const int o3 = orient(s.p, s.q, u);
        const int o4 = orient(s.p, s.q, w);
        if (o3 * o4 > 0) return false;
        if (o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0) return true;
        // Collinear: the two intervals along the line overlap.
        const XY slo = lex_less(s.p, s.q) ? s.p : s.q;
        const XY shi = lex_less(s.p, s.q) ? s.q : s.p;
        const XY tlo = lex_less(u, w) ? u : w;
        const XY thi = lex_less(u, w) ? w : u;
        return !lex_less(shi, tlo) && !lex_less(thi, slo);
    }
    for (unsigned i = 0; i < 3; ++i) {
        const XY a = t[i];
        const XY b = t[(i + 1) % 3];
        if (orient(a, b, s.p) < 0 && orient(a, b, s.q) < 0) return false;
    }
    const int s0 = orient(s.p, s.q, t[0]);
    const int s1 = orient(s.p, s.q, t[1]);
    const int s2 = orient(s.p, s.q, t[2]);
    return !((s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0));
}

SegmentGrid::SegmentGrid(const std::vector<TouchSegment>& segments) : segments_(segments) {
    if (segments.empty()) return;
    double x1 = segments[0].p.x, y1 = segments[0].p.y;
    x0_ = x1;
    y0_ = y1;
    for (const TouchSegment& s : segments) {
        for (const XY p : {s.p, s.q}) {
            x0_ = std::min(x0_, p.x);
            y0_ = std::min(y0_, p.y);
            x1 = std::max(x1, p.x);
            y1 = std::max(y1, p.y);
        }
    }
    // Square cells about as long as the median segment (breaklines crowd along roads and
    // rivers: cells of the mean density would put hundreds of them in one cell), at most about
    // 16 cells per segment and 2^12 per side.
    std::vector<double> lengths;
    lengths.reserve(segments.size());
    for (const TouchSegment& s : segments) {
        lengths.push_back(std::max(std::abs(s.q.x - s.p.x), std::abs(s.q.y - s.p.y)));
    }
    std::nth_element(lengths.begin(),
                     lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2),
                     lengths.end());
    const double width = std::max(x1 - x0_, 0.0);
    const double height = std::max(y1 - y0_, 0.0);
    const double cap = 16.0 * static_cast<double>(segments.size());
    double cell = std::max(lengths[lengths.size() / 2], std::sqrt(width * height / cap));
    cell = std::max({cell, width / 4096.0, height / 4096.0});
    if (!(cell > 0.0)) cell = 1.0;
    w_ = h_ = cell;
    columns_ = static_cast<std::uint32_t>(std::clamp(std::ceil(width / cell), 1.0, 4096.0));
    rows_ = static_cast<std::uint32_t>(std::clamp(std::ceil(height / cell), 1.0, 4096.0));
    std::vector<std::uint64_t> count(std::size_t{columns_} * rows_ + 1, 0);
    for (const TouchSegment& s : segments) cells_of(s, [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
    offsets_ = count;
    ids_.resize(offsets_.back());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        cells_of(segments[i],
                 [&](std::size_t c) { ids_[count[c]++] = static_cast<std::uint32_t>(i); });
    }
}

std::uint32_t SegmentGrid::column(double x) const noexcept {
    const double c = std::floor((x - x0_) / w_);
    return static_cast<std::uint32_t>(std::clamp(c, 0.0, static_cast<double>(columns_ - 1)));
}

std::uint32_t SegmentGrid::row(double y) const noexcept {
    const double r = std::floor((y - y0_) / h_);
    return static_cast<std::uint32_t>(std::clamp(r, 0.0, static_cast<double>(rows_ - 1)));
}

template <class Visit>
void SegmentGrid::cells_of(const TouchSegment& s, Visit&& visit) const {
    const double dx = s.q.x - s.p.x;
    const double dy = s.q.y - s.p.y;
    const std::uint32_t c_lo = column(std::min(s.p.x, s.q.x));
    const std::uint32_t c_hi = column(std::max(s.p.x, s.q.x));
    const std::uint32_t r_lo = row(std::min(s.p.y, s.q.y));
    const std::uint32_t r_hi = row(std::max(s.p.y, s.q.y));
    for (std::uint32_t r = r_lo; r <= r_hi; ++r) {
        std::uint32_t lo = c_lo;
        std::uint32_t hi = c_hi;
        if (dy != 0.0 && r_lo != r_hi) {  // the strip's x-range in this row, one cell wider
            const double ya = y0_ + h_ * r;
            const double t0 = std::clamp((ya - s.p.y) / dy, 0.0, 1.0);
            const double t1 = std::clamp((ya + h_ - s.p.y) / dy, 0.0, 1.0);
            const double xa = s.p.x + t0 * dx;
            const double xb = s.p.x + t1 * dx;
            const std::uint32_t a = column(std::min(xa, xb));
            const std::uint32_t b = column(std::max(xa, xb));
            lo = std::max(c_lo, a > 0 ? a - 1 : 0);
            hi = std::min(c_hi, b + 1);
        }
        for (std::uint32_t c = lo; c <= hi; ++c) visit(std::size_t{r} * columns_ + c);
    }
}

void SegmentGrid::touching(const std::array<XY, 3>& t,
                           bool hull_edge,
                           std::vector<std::uint32_t>& out) const {
    if (segments_.empty()) return;
    const unsigned corners = hull_edge ? 2 : 3;
    double xl = t[0].x, xh = t[0].x, yl = t[0].y, yh = t[0].y;
    for (unsigned i = 1; i < corners; ++i) {
        xl = std::min(xl, t[i].x);
        xh = std::max(xh, t[i].x);
        yl = std::min(yl, t[i].y);
        yh = std::max(yh, t[i].y);
    }
    const std::size_t first = out.size();
    // A point of the segment in the triangle lies in one of these cells (row and column are
    // monotone in y and x; the segment's own cells carry the margin).
    const std::uint32_t c_lo = column(xl);
    const std::uint32_t c_hi = column(xh);
    const std::uint32_t r_lo = row(yl);
    const std::uint32_t r_hi = row(yh);
    for (std::uint32_t r = r_lo; r <= r_hi; ++r) {
        for (std::uint32_t c = c_lo; c <= c_hi; ++c) {
            const std::size_t cell = std::size_t{r} * columns_ + c;
            for (std::uint64_t k = offsets_[cell]; k < offsets_[cell + 1]; ++k) {
                const std::uint32_t id = ids_[k];
                if (segment_touches(segments_[id], t, hull_edge)) out.push_back(id);
            }
        }
    }
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
    out.erase(std::unique(out.begin() + static_cast<std::ptrdiff_t>(first), out.end()), out.end());
}

}  // namespace dtm::dist
