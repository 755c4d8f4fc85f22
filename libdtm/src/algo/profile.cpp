// SPDX-License-Identifier: MIT
// Sections of a TIN along polylines.
//
// For each segment p -> q of the line:
// 1. Candidates: the triangles listed in the bucket-grid cells (detail/triangle_grid) along the
//    segment, found box by box over pieces about one cell long (no quadratic box of a long
//    diagonal segment).
// 2. Exact decision: the segment's relative interior meets a triangle's interior unless a
//    separating line exists among the triangle's edge lines (both ends on its closed outer side)
//    and the segment's own line (all three corners on one closed side): the separating axis
//    theorem, decided by orient2d. A segment running along an edge (two corners on its line, the
//    ends overlapping the edge) belongs to the triangle on its left, or on its right when the
//    edge is on the surface's border.
// 3. Interval: each edge's line bounds the parameter t in [0, 1] from one side; the bound
//    t = A_p / (A_p - A_q), with A the floating-point orientation determinant of the edge taken
//    from its smaller vertex index, has the same bits in both triangles of the edge. Heights at
//    the ends come from interpolation along the bounding edge (a breakpoint on an edge), from the
//    vertex itself when the segment passes through it (exact test), or from the triangle's plane
//    at a line vertex inside it.
// 4. Runs: intervals sorted by their middle; consecutive ones join when they meet (same bits, or
//    within 1e-9 of the segment where two triangles that share a corner meet near it); a gap
//    elsewhere. Runs continue across the line's vertices where the surface does.
//
// References: O. Devillers, S. Pion, M. Teillaud, "Walking in a triangulation", 2002 (exact
// segment-triangle decisions); the separating axis theorem (Gottschalk 1996).
#include "dtm/algo/profile.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include "algo/detail/triangle_grid.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

using detail::edge_height;
using detail::height_at;
using detail::PackedTriangle;

inline double det(double ax, double ay, double bx, double by, double cx, double cy) {
    return (ax - cx) * (by - cy) - (ay - cy) * (bx - cx);
}

struct Interval {
    double t0 = 0.0;
    double t1 = 0.0;
    double z0 = 0.0;
    double z1 = 0.0;
    TriangleIndex triangle = no_triangle;
};

struct Segment {
    double px, py, qx, qy;
};

/// Parameter of the projection of (x, y) on the segment.
double project(const Segment& g, double x, double y) {
    const double dx = g.qx - g.px;
    const double dy = g.qy - g.py;
    const double len2 = dx * dx + dy * dy;
    return len2 > 0.0 ? ((x - g.px) * dx + (y - g.py) * dy) / len2 : 0.0;
}

/// One end of the interval: the bound from edge k (corner k to k + 1) at parameter t.
struct Bound {
    double t = 0.0;
    int edge = -1;  ///< -1: the segment's own end
};

/// The interval of segment @p g inside triangle @p t, if their intersection has positive length.
bool clip_segment(const PackedTriangle& t,
                  const std::array<TriangleIndex, 3>& neighbours,
                  const Segment& g,
                  Interval& out) {
    std::array<int, 3> sp{};
    std::array<int, 3> sq{};
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t k1 = (k + 1) % 3;
        sp[k] = geom::orient2d(t.x[k], t.y[k], t.x[k1], t.y[k1], g.px, g.py);
        sq[k] = geom::orient2d(t.x[k], t.y[k], t.x[k1], t.y[k1], g.qx, g.qy);
        if (sp[k] < 0 && sq[k] < 0) {
            return false;
        }
    }
    std::array<int, 3> o{};
    for (std::size_t k = 0; k < 3; ++k) {
        o[k] = geom::orient2d(g.px, g.py, g.qx, g.qy, t.x[k], t.y[k]);
    }
    const bool all_left = o[0] >= 0 && o[1] >= 0 && o[2] >= 0;
    const bool all_right = o[0] <= 0 && o[1] <= 0 && o[2] <= 0;
    bool along_edge = false;
    for (std::size_t k = 0; k < 3 && !along_edge; ++k) {
        if (sp[k] <= 0 && sq[k] <= 0 && !(sp[k] == 0 && sq[k] == 0)) {
            return false;  // both ends on the closed outer side of edge k, not along it
        }
    }
    if (all_left || all_right) {
        // Touching the line only: along an edge, or not at all.
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t k1 = (k + 1) % 3;
            const std::size_t third = (k + 2) % 3;
            if (o[k] != 0 || o[k1] != 0) {
                continue;
            }
            // The edge's neighbour is n[third] (the neighbour across the edge opposite corner
            // `third`).
            if (!(o[third] > 0 || neighbours[third] == no_triangle)) {
                return false;
            }
            along_edge = true;
        }
        if (!along_edge) {
            return false;
        }
    }
    // Parameter bounds from each edge's line.
    Bound lo{0.0, -1};
    Bound hi{1.0, -1};
    for (std::size_t k = 0; k < 3; ++k) {
        if (sp[k] >= 0 && sq[k] >= 0) {
            continue;
        }
        std::size_t a = k;
        std::size_t b = (k + 1) % 3;
        if (t.v[b] < t.v[a]) {
            std::swap(a, b);
        }
        const double ap = det(t.x[a], t.y[a], t.x[b], t.y[b], g.px, g.py);
        const double aq = det(t.x[a], t.y[a], t.x[b], t.y[b], g.qx, g.qy);
        const double bound = ap - aq != 0.0 ? std::clamp(ap / (ap - aq), 0.0, 1.0) : 0.0;
        if (sp[k] < 0) {
            if (bound > lo.t || lo.edge < 0) {
                lo = {std::max(bound, lo.t), static_cast<int>(k)};
            }
        } else if (bound < hi.t || hi.edge < 0) {
            hi = {std::min(bound, hi.t), static_cast<int>(k)};
        }
    }
    if (!(hi.t > lo.t)) {
        return false;
    }
    const auto end_height = [&](const Bound& b, double& x, double& y, double& z, double& param) {
        if (b.edge < 0) {
            const bool start = &b == &lo;
            x = start ? g.px : g.qx;
            y = start ? g.py : g.qy;
            z = height_at(t, start ? sp : sq, x, y);
            return;
        }
        const auto k = static_cast<std::size_t>(b.edge);
        const std::size_t k1 = (k + 1) % 3;
        // Through a corner of the edge exactly: the corner is the breakpoint.
        // (The edge is not along the segment's line, so its line meets it at that corner.)
        for (const std::size_t c : {k, k1}) {
            if (o[c] == 0) {
                x = t.x[c];
                y = t.y[c];
                z = t.z[c];
                param = std::clamp(project(g, x, y), 0.0, 1.0);
                return;
            }
        }
        x = g.px + b.t * (g.qx - g.px);
        y = g.py + b.t * (g.qy - g.py);
        z = edge_height(t, k, k1, x, y);
    };
    double x = 0.0;
    double y = 0.0;
    out.t0 = lo.t;
    out.t1 = hi.t;
    end_height(lo, x, y, out.z0, out.t0);
    end_height(hi, x, y, out.z1, out.t1);
    return out.t1 > out.t0;
}

}  // namespace

bool profile_height(const Profile& profile, double chainage, double& z) {
    for (const ProfileRun& run : profile.runs) {
        if (run.points.empty() || chainage < run.points.front().chainage ||
            chainage > run.points.back().chainage) {
            continue;
        }
        const auto it =
            std::lower_bound(run.points.begin(), run.points.end(), chainage,
                             [](const ProfilePoint& p, double c) { return p.chainage < c; });
        if (it == run.points.begin()) {
            z = it->z;
            return true;
        }
        const ProfilePoint& b = *it;
        const ProfilePoint& a = *(it - 1);
        const double span = b.chainage - a.chainage;
        z = span > 0.0 ? a.z + (chainage - a.chainage) / span * (b.z - a.z) : b.z;
        return true;
    }
    return false;
}

struct TinSection::Impl {
    const Tin* tin = nullptr;
    detail::TriangleGrid grid;
    double cell = 1.0;

    /// Triangles near segment @p g, each once.
    void candidates(const Segment& g, std::vector<TriangleIndex>& out) const {
        out.clear();
        const double len = std::hypot(g.qx - g.px, g.qy - g.py);
        const auto pieces = static_cast<std::size_t>(std::min(1e6, std::ceil(len / cell))) + 1;
        for (std::size_t i = 0; i < pieces; ++i) {
            const double a = static_cast<double>(i) / static_cast<double>(pieces);
            const double b = static_cast<double>(i + 1) / static_cast<double>(pieces);
            Box2 box;
            box.add(g.px + a * (g.qx - g.px), g.py + a * (g.qy - g.py));
            box.add(g.px + b * (g.qx - g.px), g.py + b * (g.qy - g.py));
            // Widen by a rounding margin: the pieces' ends are computed.
            const double margin = 1e-9 * (std::fabs(box.xmax) + std::fabs(box.ymax) + len) + 1e-300;
            box.xmin -= margin;
            box.ymin -= margin;
            box.xmax += margin;
            box.ymax += margin;
            grid.for_each_candidate(box, [&](TriangleIndex t) { out.push_back(t); });
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

    static bool share_corner(const PackedTriangle& a, const PackedTriangle& b) {
        for (const VertexIndex u : a.v) {
            for (const VertexIndex w : b.v) {
                if (u == w) {
                    return true;
                }
            }
        }
        return false;
    }

    Profile cut(std::span<const Point3> line) const {
        Profile profile;
        std::vector<TriangleIndex> near;
        std::vector<Interval> intervals;
        ProfileRun run;
        bool open = false;  // the run goes on at the current place
        double last_t = 0.0;
        TriangleIndex last_triangle = no_triangle;
        double chainage = 0.0;
        const auto close_run = [&] {
            if (run.points.size() >= 2) {
                profile.runs.push_back(std::move(run));
            }
            run = ProfileRun{};
            open = false;
        };
        for (std::size_t s = 0; s + 1 < line.size(); ++s) {
            const Segment g{line[s].x, line[s].y, line[s + 1].x, line[s + 1].y};
            const double len = std::hypot(g.qx - g.px, g.qy - g.py);
            if (len == 0.0) {
                continue;
            }
            intervals.clear();
            candidates(g, near);
            for (const TriangleIndex t : near) {
                Interval iv;
                if (clip_segment(grid.triangle(t), tin->triangles[t].n, g, iv)) {
                    iv.triangle = t;
                    intervals.push_back(iv);
                }
            }
            std::sort(intervals.begin(), intervals.end(), [](const Interval& a, const Interval& b) {
                return a.t0 + a.t1 < b.t0 + b.t1;
            });
            const auto point = [&](double t, double z) {
                return ProfilePoint{chainage + t * len, g.px + t * (g.qx - g.px),
                                    g.py + t * (g.qy - g.py), z};
            };
            bool first = true;
            for (const Interval& iv : intervals) {
                const bool joins =
                    open &&
                    (first ? iv.t0 == 0.0
                           : (iv.t0 == last_t || (std::fabs(iv.t0 - last_t) <= 1e-9 &&
                                                  share_corner(grid.triangle(last_triangle),
                                                               grid.triangle(iv.triangle)))));
                if (!joins) {
                    close_run();
                    run.points.push_back(point(iv.t0, iv.z0));
                }
                run.points.push_back(point(iv.t1, iv.z1));
                last_t = iv.t1;
                last_triangle = iv.triangle;
                open = true;
                first = false;
            }
            if (!open || intervals.empty() || last_t != 1.0) {
                close_run();
            }
            chainage += len;
        }
        close_run();
        profile.length = chainage;
        return profile;
    }
};

TinSection::TinSection(const Tin& tin) : impl_(std::make_unique<Impl>()) {
    impl_->tin = &tin;
    impl_->grid = detail::TriangleGrid(tin, 0.5);
    const Box2& b = impl_->grid.bounds();
    const double cols = static_cast<double>(std::max<std::size_t>(impl_->grid.cols(), 1));
    impl_->cell = std::max((b.xmax - b.xmin) / cols, 1e-9);
}

TinSection::~TinSection() = default;

Profile TinSection::cut(std::span<const Point3> line) const { return impl_->cut(line); }

std::vector<Profile> TinSection::cut_all(std::span<const std::vector<Point3>> lines,
                                         unsigned threads,
                                         const Progress& progress) const {
    std::vector<Profile> out(lines.size());
    std::atomic<std::size_t> done{0};
    const auto body = [&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, lines.size(), 8),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t i = r.begin(); i != r.end(); ++i) {
                                  progress.check();
                                  out[i] = impl_->cut(lines[i]);
                              }
                              const std::size_t finished = done.fetch_add(r.size()) + r.size();
                              progress.report(
                                  static_cast<double>(finished) / static_cast<double>(lines.size()),
                                  "cutting sections");
                          });
    };
    if (threads > 0) {
        tbb::task_arena arena(static_cast<int>(threads));
        arena.execute(body);
    } else {
        body();
    }
    return out;
}

}  // namespace dtm
