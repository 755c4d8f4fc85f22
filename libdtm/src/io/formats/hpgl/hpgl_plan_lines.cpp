// SPDX-License-Identifier: MIT
// Lines of an HP-GL height plan by pen role, with heights from the spot heights.
//
// Each polyline drawn with a pen named in HpglOptions::pens becomes a breakline, soft breakline,
// boundary or hole; lines on other pens are ignored and counted. A polyline whose last vertex is
// its first is a closed ring (the repeated vertex is dropped and closed is set); boundaries and
// holes are closed when they are not, with a warning. A vertex within the marker radius of a
// spot height takes that height (the nearest one); the others are interpolated linearly in
// distance along the line between such vertices (around the ring for closed lines) and keep the
// nearest end's height beyond the first or last one. A breakline with no such vertex becomes a
// soft breakline. Soft lines, and boundaries or holes without any height, carry z = NaN, the
// project's "no height" (io::load_inputs gives such rings the height of the surface of the other
// inputs; the triangulator computes soft breakline heights).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

#include "io/formats/hpgl/hpgl_grid.hpp"
#include "io/formats/hpgl/hpgl_plan.hpp"

namespace dtm::io::hpgl {
namespace {

constexpr double closing_tolerance = 0.01;  // plotter units
const double unknown = std::numeric_limits<double>::quiet_NaN();

/// The spot height nearest to a point within a radius.
class NearestSpot {
public:
    explicit NearestSpot(const std::vector<SpotHeight>& spots, double cell)
        : places_(positions(spots)), grid_(places_, cell) {}

    /// Index of the spot height within @p radius of @p p that is nearest, or -1.
    [[nodiscard]] long within(Point2 p, double radius) const {
        long best = -1;
        double best_d = std::numeric_limits<double>::infinity();
        grid_.near(p, radius, [&](std::uint32_t i, double d) {
            if (d < best_d || (d == best_d && (best < 0 || i < best))) {
                best_d = d;
                best = static_cast<long>(i);
            }
        });
        return best;
    }

private:
    static std::vector<Point2> positions(const std::vector<SpotHeight>& spots) {
        std::vector<Point2> out;
        for (const SpotHeight& s : spots) out.push_back(s.at);
        return out;
    }

    std::vector<Point2> places_;
    PointGrid grid_;
};

/// Fills unknown z by linear interpolation along the line (cyclic when closed).
void interpolate(std::vector<Point3>& pts, bool closed) {
    const std::size_t n = pts.size();
    std::vector<std::size_t> known;
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isnan(pts[i].z)) known.push_back(i);
    }
    if (known.empty()) return;
    const auto step = [&](std::size_t i) {
        const Point3& a = pts[i % n];
        const Point3& b = pts[(i + 1) % n];
        return distance({a.x, a.y}, {b.x, b.y});
    };
    const auto fill = [&](std::size_t from, std::size_t to) {  // from < to, indices modulo n
        double total = 0.0;
        for (std::size_t i = from; i < to; ++i) total += step(i);
        const double za = pts[from % n].z, zb = pts[to % n].z;
        double run = 0.0;
        for (std::size_t i = from + 1; i < to; ++i) {
            run += step(i - 1);
            pts[i % n].z = total > 0.0 ? za + (zb - za) * run / total : za;
        }
    };
    for (std::size_t k = 0; k + 1 < known.size(); ++k) fill(known[k], known[k + 1]);
    if (closed) {
        fill(known.back(), known.front() + n);
        return;
    }
    for (std::size_t i = 0; i < known.front(); ++i) pts[i].z = pts[known.front()].z;
    for (std::size_t i = known.back() + 1; i < n; ++i) pts[i].z = pts[known.back()].z;
}

std::string describe(const RoleLine& line) {
    return std::string(pen_role_name(line.role)) + " at byte " + std::to_string(line.offset) +
           " (pen " + std::to_string(line.pen) + ")";
}

}  // namespace

void assign_line_roles(const Plot& plot,
                       const HpglOptions& options,
                       double radius,
                       TerrainPlan& plan) {
    const NearestSpot spots(plan.spots, radius);
    std::map<int, std::size_t> ignored_by_pen;
    std::size_t made_soft = 0;
    for (const PlotLine& line : plot.lines) {
        const auto found = options.pens.find(line.pen);
        const PenRole role = found == options.pens.end() ? PenRole::ignore : found->second;
        if (role == PenRole::points) continue;
        if (role == PenRole::ignore || line.points.size() < 2) {
            if (line.points.size() >= 2) {
                ++ignored_by_pen[line.pen];
                ++plan.ignored_lines;
            }
            continue;
        }
        RoleLine out{role, line.pen, {}, false, line.offset, 0};
        for (const Point2& p : line.points) out.points.push_back({p.x, p.y, unknown});
        if (out.points.size() >= 3 &&
            distance(line.points.front(), line.points.back()) <= closing_tolerance) {
            out.points.pop_back();
            out.closed = true;
        }
        if ((role == PenRole::boundary || role == PenRole::hole) && !out.closed) {
            out.closed = true;
            plan.warnings.push_back(describe(out) + " is not a closed ring: closed it");
        }
        if (role != PenRole::soft_breakline) {
            for (Point3& p : out.points) {
                const long s = spots.within({p.x, p.y}, radius);
                if (s >= 0) {
                    p.z = plan.spots[static_cast<std::size_t>(s)].z;
                    ++out.height_vertices;
                }
            }
            interpolate(out.points, out.closed);
        }
        if (out.height_vertices == 0) {
            if (role == PenRole::breakline) {
                out.role = PenRole::soft_breakline;
                ++made_soft;
            } else if (role != PenRole::soft_breakline) {
                plan.warnings.push_back(
                    describe(out) +
                    " has no spot height on its vertices: heights left to the surface");
            }
        }
        plan.lines.push_back(std::move(out));
    }
    if (made_soft > 0) {
        plan.warnings.push_back(
            std::to_string(made_soft) +
            " breaklines have no spot height within the marker radius of a vertex: made soft");
    }
    if (!ignored_by_pen.empty()) {
        std::string pens;
        for (const auto& [pen, count] : ignored_by_pen)
            pens += " " + std::to_string(pen) + ":" + std::to_string(count);
        plan.warnings.push_back(std::to_string(plan.ignored_lines) +
                                " lines on pens without a role ignored (pen:lines" + pens +
                                "); see `hpgl.pens`");
    }
}

}  // namespace dtm::io::hpgl
