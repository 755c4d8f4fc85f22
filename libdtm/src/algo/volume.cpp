// SPDX-License-Identifier: MIT
// Exact volumes between piecewise-linear surfaces.
//
// Over every overlay piece (overlay.cpp: a convex polygon inside one top and one base triangle)
// the difference d = z_top - z_base is a linear function. The piece is cut at d = 0 into the part
// where d >= 0 and the part where d <= 0 and each is integrated in closed form
// (detail/piece_integral.hpp: fan triangles, area x mean of the corner values, exact for degree 1).
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
#include "algo/detail/piece_integral.hpp"
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

void add_piece(const OverlayPiece& piece, Totals& totals) {
    const std::size_t n = piece.corners.size();
    std::array<detail::LinearCorner, 12> v;  // NOLINT: filled below
    const OverlayCorner& origin = piece.corners[0];
    for (std::size_t i = 0; i < n; ++i) {
        const OverlayCorner& c = piece.corners[i];
        v[i] = {c.x - origin.x, c.y - origin.y, c.z_top - c.z_base};
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
    const detail::SignedParts parts = detail::split_polygon(v.data(), n);
    if (parts.unchanged_area > 0.0) {
        totals.unchanged_area.add(parts.unchanged_area);
    }
    if (parts.fill.area != 0.0) {
        totals.fill.add(parts.fill.integral);
        totals.fill_area.add(parts.fill.area);
        totals.fill_top_3d.add(parts.fill.area * top_factor);
        totals.fill_base_3d.add(parts.fill.area * base_factor);
    }
    if (parts.cut.area != 0.0) {
        totals.cut.add(parts.cut.integral);
        totals.cut_area.add(parts.cut.area);
        totals.cut_top_3d.add(parts.cut.area * top_factor);
        totals.cut_base_3d.add(parts.cut.area * base_factor);
    }
}

}  // namespace

double only_area(double whole, double overlap) {
    const double rest = whole - overlap;
    return std::fabs(rest) <= 1e-12 * std::max(whole, 1e-300) ? 0.0 : std::max(rest, 0.0);
}

VolumeResult volume(const TinOverlay& overlay,
                    const Tin& top,
                    const Tin* base,
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
    r.top_only_area = only_area(r.top_area, r.overlap_area);
    r.base_is_plane = base == nullptr;
    if (base != nullptr) {
        r.base_area = tin_area(*base);
        r.base_only_area = only_area(r.base_area, r.overlap_area);
    }
    return r;
}

VolumeResult volume(const Tin& top,
                    const Tin& base,
                    const VolumeOptions& options,
                    const Progress& progress) {
    const TinOverlay overlay(top, base, {.threads = options.threads});
    return volume(overlay, top, &base, progress);
}

VolumeResult volume(const Tin& top,
                    double base_z,
                    const VolumeOptions& options,
                    const Progress& progress) {
    const TinOverlay overlay(top, base_z, {.threads = options.threads});
    return volume(overlay, top, nullptr, progress);
}

}  // namespace dtm
