// SPDX-License-Identifier: MIT
// Exact volumes between piecewise-linear surfaces.
//
// Over every overlay piece (overlay.cpp: a convex polygon inside one top and one base triangle)
// the difference d = z_top - z_base is a linear function. The piece is cut at d = 0 into the part
// where d >= 0 and the part where d <= 0 (each convex: a half-plane of a convex polygon); over a
// convex polygon a linear function integrates exactly as the sum over the fan triangles
// (q0, qi, qi+1) of area x mean of the three corner values (the value at the centroid). The zero
// crossing on an edge with corner values of opposite sign is at t = d_i / (d_i - d_j).
// Coordinates are taken relative to the piece's first corner (large S-JTSK offsets cancel
// exactly), and every total is a Neumaier compensated sum, kept per chunk and combined in chunk
// order, so results do not depend on the thread count.
//
// 3-D areas: over a region of plan area A a plane z = c + gx x + gy y has area A sqrt(1 + gx^2 +
// gy^2); the pieces carry each triangle's slope.
//
// References: the prismoidal and TIN volume methods of survey practice (e.g. Civil 3D "TIN
// volume surface"; Atlas DMT, OBJEM) compute the same quantity; the closed form for a linear
// function over a triangle is the centroid rule, exact for degree 1.
#include "dtm/algo/volume.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "algo/detail/compensated_sum.hpp"
#include "dtm/algo/validate.hpp"

namespace dtm {
namespace {

using detail::CompensatedSum;

struct Totals {
    CompensatedSum fill, cut, fill_area, cut_area, unchanged_area;
    CompensatedSum fill_top_3d, fill_base_3d, cut_top_3d, cut_base_3d;
    double max_fill = 0.0;
    Point2 max_fill_at{};
    double max_cut = 0.0;
    Point2 max_cut_at{};
    std::size_t pieces = 0;

    void add(const Totals& o) {
        fill.add(o.fill);
        cut.add(o.cut);
        fill_area.add(o.fill_area);
        cut_area.add(o.cut_area);
        unchanged_area.add(o.unchanged_area);
        fill_top_3d.add(o.fill_top_3d);
        fill_base_3d.add(o.fill_base_3d);
        cut_top_3d.add(o.cut_top_3d);
        cut_base_3d.add(o.cut_base_3d);
        if (o.max_fill > max_fill) {
            max_fill = o.max_fill;
            max_fill_at = o.max_fill_at;
        }
        if (o.max_cut > max_cut) {
            max_cut = o.max_cut;
            max_cut_at = o.max_cut_at;
        }
        pieces += o.pieces;
    }
};

struct Vertex {
    double x;
    double y;
    double d;
};

/// Area and integral of d over the convex polygon @p p (counter-clockwise).
struct AreaIntegral {
    double area = 0.0;
    double integral = 0.0;
};

AreaIntegral integrate(const Vertex* p, std::size_t n) {
    AreaIntegral r;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        const double a = 0.5 * ((p[i].x - p[0].x) * (p[i + 1].y - p[0].y) -
                                (p[i].y - p[0].y) * (p[i + 1].x - p[0].x));
        r.area += a;
        r.integral += a * (p[0].d + p[i].d + p[i + 1].d) / 3.0;
    }
    return r;
}

/// The part of polygon @p p where sign * d >= 0, into @p out; returns its corner count.
std::size_t half(const Vertex* p, std::size_t n, double sign, Vertex* out) {
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vertex& a = p[i];
        const Vertex& b = p[i + 1 == n ? 0 : i + 1];
        const double da = sign * a.d;
        const double db = sign * b.d;
        if (da >= 0.0) {
            out[m++] = a;
        }
        if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) {
            const double t = da / (da - db);
            out[m++] = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), 0.0};
        }
    }
    return m;
}

void add_piece(const OverlayPiece& piece, Totals& totals) {
    const std::size_t n = piece.corners.size();
    std::array<Vertex, 12> v;  // NOLINT: filled below
    const OverlayCorner& origin = piece.corners[0];
    bool any_positive = false;
    bool any_negative = false;
    for (std::size_t i = 0; i < n; ++i) {
        const OverlayCorner& c = piece.corners[i];
        v[i] = {c.x - origin.x, c.y - origin.y, c.z_top - c.z_base};
        any_positive = any_positive || v[i].d > 0.0;
        any_negative = any_negative || v[i].d < 0.0;
        if (v[i].d > totals.max_fill) {
            totals.max_fill = v[i].d;
            totals.max_fill_at = {c.x, c.y};
        }
        if (-v[i].d > totals.max_cut) {
            totals.max_cut = -v[i].d;
            totals.max_cut_at = {c.x, c.y};
        }
    }
    const double top_factor = std::sqrt(1.0 + piece.top_slope[0] * piece.top_slope[0] +
                                        piece.top_slope[1] * piece.top_slope[1]);
    const double base_factor = std::sqrt(1.0 + piece.base_slope[0] * piece.base_slope[0] +
                                         piece.base_slope[1] * piece.base_slope[1]);
    ++totals.pieces;
    if (!any_positive && !any_negative) {
        totals.unchanged_area.add(integrate(v.data(), n).area);
        return;
    }
    std::array<Vertex, 16> part;  // NOLINT: filled by half()
    if (any_positive) {
        const std::size_t m = any_negative ? half(v.data(), n, 1.0, part.data()) : n;
        const AreaIntegral r = integrate(any_negative ? part.data() : v.data(), m);
        totals.fill.add(r.integral);
        totals.fill_area.add(r.area);
        totals.fill_top_3d.add(r.area * top_factor);
        totals.fill_base_3d.add(r.area * base_factor);
    }
    if (any_negative) {
        const std::size_t m = any_positive ? half(v.data(), n, -1.0, part.data()) : n;
        const AreaIntegral r = integrate(any_positive ? part.data() : v.data(), m);
        totals.cut.add(-r.integral);
        totals.cut_area.add(r.area);
        totals.cut_top_3d.add(r.area * top_factor);
        totals.cut_base_3d.add(r.area * base_factor);
    }
}

}  // namespace

VolumeResult volume(const TinOverlay& overlay, const Tin& top, const Tin* base,
                    const Progress& progress) {
    std::vector<Totals> chunks(overlay.chunk_count());
    overlay.run(
        [&](std::size_t chunk, std::span<const OverlayPiece> pieces) {
            Totals& t = chunks[chunk];
            for (const OverlayPiece& piece : pieces) {
                add_piece(piece, t);
            }
        },
        progress);
    Totals all;
    for (const Totals& t : chunks) {
        all.add(t);
    }
    VolumeResult r;
    r.fill = all.fill.value();
    r.cut = all.cut.value();
    r.fill_area = all.fill_area.value();
    r.cut_area = all.cut_area.value();
    r.unchanged_area = all.unchanged_area.value();
    CompensatedSum overlap;
    overlap.add(all.fill_area);
    overlap.add(all.cut_area);
    overlap.add(all.unchanged_area);
    r.overlap_area = overlap.value();
    r.fill_area_top_3d = all.fill_top_3d.value();
    r.fill_area_base_3d = all.fill_base_3d.value();
    r.cut_area_top_3d = all.cut_top_3d.value();
    r.cut_area_base_3d = all.cut_base_3d.value();
    r.max_fill = all.max_fill;
    r.max_fill_at = all.max_fill_at;
    r.max_cut = all.max_cut;
    r.max_cut_at = all.max_cut_at;
    r.pieces = all.pieces;
    r.top_area = tin_area(top);
    // Differences of compensated sums of the same pieces: exact up to a few ulps of the area,
    // which is snapped to 0 (a surface that lies wholly inside the other has no "only" area).
    const auto only = [&](double whole) {
        const double rest = whole - r.overlap_area;
        return std::fabs(rest) <= 1e-12 * std::max(whole, 1e-300) ? 0.0 : std::max(rest, 0.0);
    };
    r.top_only_area = only(r.top_area);
    r.base_is_plane = base == nullptr;
    if (base != nullptr) {
        r.base_area = tin_area(*base);
        r.base_only_area = only(r.base_area);
    }
    return r;
}

VolumeResult volume(const Tin& top, const Tin& base, const VolumeOptions& options,
                    const Progress& progress) {
    const TinOverlay overlay(top, base, {.threads = options.threads});
    return volume(overlay, top, &base, progress);
}

VolumeResult volume(const Tin& top, double base_z, const VolumeOptions& options,
                    const Progress& progress) {
    const TinOverlay overlay(top, base_z, {.threads = options.threads});
    return volume(overlay, top, nullptr, progress);
}

}  // namespace dtm
