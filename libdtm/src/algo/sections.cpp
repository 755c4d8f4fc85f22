// SPDX-License-Identifier: MIT
// Cross-sections along an alignment.
//
// Stations: chainage along the alignment's plan polyline. The section at station s runs across
// the direction of the segment holding s (at a vertex: across the bisector of its two segments),
// width / 2 to each side.
// Areas: the two profiles (algo/profile) are piecewise linear in the section's chainage; between
// the union of their breakpoints where both exist the difference d is linear, and its positive
// and negative parts integrate in closed form (split at the zero where d changes sign).
// Slab volumes: the corridor (section ends, left side forward then right side back) is
// triangulated with the section lines as constraints, so every triangle lies in one slab
// (the one whose two section lines it lies between, found by orientation tests on its centroid);
// the difference surface overlaid with it gives pieces tagged by slab, integrated as volume.cpp
// does. The average-end-area rule V = (A_k + A_k+1) / 2 x (s_k+1 - s_k) is exact only when the
// section varies linearly between stations (a prism or wedge); its difference from the slab's
// exact volume measures how far the ground departs from that between stations (curvature along
// the alignment, features between stations, and on curves the non-parallel sections).
#include "dtm/algo/sections.hpp"

#include <algorithm>
#include <cmath>

#include "algo/detail/compensated_sum.hpp"
#include "algo/detail/piece_integral.hpp"
#include "dtm/algo/overlay.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

Point2 unit(double x, double y) {
    const double l = std::hypot(x, y);
    return l > 0.0 ? Point2{x / l, y / l} : Point2{1.0, 0.0};
}

/// Integral of the positive part of a linear function with end values a, b over length h.
double positive_part(double a, double b, double h) {
    if (a >= 0.0 && b >= 0.0) {
        return 0.5 * (a + b) * h;
    }
    if (a <= 0.0 && b <= 0.0) {
        return 0.0;
    }
    const double p = a > 0.0 ? a : b;
    const double t = p / (std::fabs(a) + std::fabs(b));  // share of h where d > 0
    return 0.5 * p * t * h;
}

}  // namespace

std::vector<SectionLine> section_lines(std::span<const Point3> alignment,
                                       const SectionOptions& options) {
    if (!(options.interval > 0.0) || !(options.width > 0.0)) {
        throw UsageError("sections: the interval and the width must be positive");
    }
    std::vector<double> at{0.0};  // chainage of every vertex
    for (std::size_t i = 1; i < alignment.size(); ++i) {
        at.push_back(at.back() + std::hypot(alignment[i].x - alignment[i - 1].x,
                                            alignment[i].y - alignment[i - 1].y));
    }
    if (alignment.size() < 2 || !(at.back() > 0.0)) {
        throw UsageError("sections: the alignment needs two distinct points");
    }
    const double length = at.back();
    std::vector<double> stations;
    for (std::size_t k = 0; static_cast<double>(k) * options.interval <= length * (1 + 1e-12);
         ++k) {
        stations.push_back(std::min(static_cast<double>(k) * options.interval, length));
    }
    if (options.include_end && length - stations.back() > 1e-9 * length) {
        stations.push_back(length);
    }
    std::vector<SectionLine> out;
    const double half = options.width / 2.0;
    for (const double s : stations) {
        std::size_t i =
            static_cast<std::size_t>(std::upper_bound(at.begin(), at.end(), s) - at.begin());
        i = std::clamp<std::size_t>(i, 1, alignment.size() - 1);  // segment i-1 -> i holds s
        const Point3& a = alignment[i - 1];
        const Point3& b = alignment[i];
        Point2 dir = unit(b.x - a.x, b.y - a.y);
        const double span = at[i] - at[i - 1];
        const double t = span > 0.0 ? (s - at[i - 1]) / span : 0.0;
        const bool at_vertex_end = s == at[i] && i + 1 < alignment.size();
        const bool at_vertex_start = s == at[i - 1] && i >= 2;
        if (at_vertex_end || at_vertex_start) {
            const Point3& c = at_vertex_end ? alignment[i + 1] : alignment[i - 2];
            const Point2 other =
                at_vertex_end ? unit(c.x - b.x, c.y - b.y) : unit(a.x - c.x, a.y - c.y);
            dir = unit(dir.x + other.x, dir.y + other.y);
        }
        SectionLine line;
        line.station = s;
        line.centre = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        line.left = {line.centre.x - dir.y * half, line.centre.y + dir.x * half};
        line.right = {line.centre.x + dir.y * half, line.centre.y - dir.x * half};
        out.push_back(line);
    }
    return out;
}

SectionAreas section_areas(const Profile& top, const Profile& base) {
    std::vector<double> c;
    for (const Profile* p : {&top, &base}) {
        for (const ProfileRun& r : p->runs) {
            for (const ProfilePoint& q : r.points) {
                c.push_back(q.chainage);
            }
        }
    }
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    detail::CompensatedSum fill;
    detail::CompensatedSum cut;
    detail::CompensatedSum width;
    for (std::size_t i = 0; i + 1 < c.size(); ++i) {
        double t0 = 0.0;
        double t1 = 0.0;
        double b0 = 0.0;
        double b1 = 0.0;
        const double mid = 0.5 * (c[i] + c[i + 1]);
        double tm = 0.0;
        double bm = 0.0;
        if (!profile_height(top, mid, tm) || !profile_height(base, mid, bm) ||
            !profile_height(top, c[i], t0) || !profile_height(top, c[i + 1], t1) ||
            !profile_height(base, c[i], b0) || !profile_height(base, c[i + 1], b1)) {
            continue;  // a gap in one of them
        }
        const double h = c[i + 1] - c[i];
        fill.add(positive_part(t0 - b0, t1 - b1, h));
        cut.add(positive_part(b0 - t0, b1 - t1, h));
        width.add(h);
    }
    return {fill.value(), cut.value(), width.value()};
}

std::vector<SlabVolume> slab_volumes(const DifferenceSurface& difference,
                                     std::span<const SectionLine> sections,
                                     const Progress& progress) {
    std::vector<SlabVolume> out(sections.size() > 1 ? sections.size() - 1 : 0);
    if (out.empty()) {
        return out;
    }
    TerrainInput corridor;
    Polyline ring;
    for (const SectionLine& s : sections) {
        ring.points.push_back({s.left.x, s.left.y, 0.0});
    }
    for (auto it = sections.rbegin(); it != sections.rend(); ++it) {
        ring.points.push_back({it->right.x, it->right.y, 0.0});
    }
    corridor.points = ring.points;
    ring.points.push_back(ring.points.front());
    corridor.boundaries.push_back(ring);
    for (const SectionLine& s : sections) {
        corridor.breaklines.push_back(
            {{{s.left.x, s.left.y, 0.0}, {s.right.x, s.right.y, 0.0}}, false, {}});
    }
    const Tin slabs = triangulate(corridor, {}, progress.sub(0.0, 0.2)).tin;
    // The slab of every corridor triangle: between section k (on its forward side) and k + 1.
    std::vector<std::size_t> zone(slabs.triangles.size(), out.size());
    for (std::size_t t = 0; t < slabs.triangles.size(); ++t) {
        Point2 c{};
        for (const VertexIndex v : slabs.triangles[t].v) {
            c.x += slabs.vertices[v].x / 3.0;
            c.y += slabs.vertices[v].y / 3.0;
        }
        for (std::size_t k = 0; k + 1 < sections.size(); ++k) {
            if (geom::orient2d(sections[k].left, sections[k].right, c) >= 0 &&
                geom::orient2d(sections[k + 1].left, sections[k + 1].right, c) <= 0) {
                zone[t] = k;
                break;
            }
        }
    }
    const TinOverlay overlay(difference.tin, slabs);
    std::vector<std::vector<std::array<detail::CompensatedSum, 3>>> chunks(overlay.chunk_count());
    overlay.run(
        [&](std::size_t chunk, std::span<const OverlayPiece> pieces) {
            auto& sums = chunks[chunk];
            sums.resize(out.size());
            for (const OverlayPiece& piece : pieces) {
                const std::size_t k = zone[piece.base_triangle];
                if (k >= out.size()) {
                    continue;
                }
                // The difference surface's height is d (the base is the flat slab TIN).
                std::array<detail::LinearCorner, 12> v;  // NOLINT: filled below
                const OverlayCorner& o = piece.corners[0];
                for (std::size_t i = 0; i < piece.corners.size(); ++i) {
                    const OverlayCorner& c = piece.corners[i];
                    v[i] = {c.x - o.x, c.y - o.y, c.z_top};
                }
                const detail::SignedParts parts =
                    detail::split_polygon(v.data(), piece.corners.size());
                sums[k][0].add(parts.fill.integral);
                sums[k][1].add(parts.cut.integral);
                sums[k][2].add(parts.fill.area + parts.cut.area + parts.unchanged_area);
            }
        },
        progress.sub(0.2, 1.0));
    for (std::size_t k = 0; k < out.size(); ++k) {
        std::array<detail::CompensatedSum, 3> total;
        for (const auto& c : chunks) {
            if (k < c.size()) {
                for (std::size_t j = 0; j < 3; ++j) {
                    total[j].add(c[k][j]);
                }
            }
        }
        out[k] = {total[0].value(), total[1].value(), total[2].value()};
    }
    return out;
}

}  // namespace dtm
