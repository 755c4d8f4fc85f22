// SPDX-License-Identifier: MIT
// Spot heights of an HP-GL height plan.
//
// A height plan marks each surveyed point with a small symbol and writes its height next to it.
// The symbol is one of: a character plotted by SM (symbol mode), a small CI circle, a small
// cross (two short perpendicular strokes crossing near their middles, or three or more short
// arms drawn out from the centre), a pen-down dot, or any vertex drawn with a "points" pen. A label
// is a height when its whole text is a decimal number ("312.45", "312,45"); integer labels (parcel
// numbers) only on HpglOptions::height_pens. Every height label is matched to the nearest free
// marker within the marker radius (pairs taken in increasing distance, so a marker serves one
// label); when most labels sit at one offset from their marker (a plan's house style), a second
// pass ranks the pairs by the distance from where that offset puts the marker, which resolves
// crowded places; without a marker, the label's own position is used and counted in a warning.
// Grids keyed by the radius keep every step linear in the plot size.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>

#include "io/formats/hpgl/hpgl_grid.hpp"
#include "io/formats/hpgl/hpgl_plan.hpp"

namespace dtm::io::hpgl {

void assign_line_roles(const Plot& plot,
                       const HpglOptions& options,
                       double radius,
                       TerrainPlan& plan);

namespace {

constexpr double perpendicular_cosine = 0.1;  // |cos| of the stroke angle, about 84..96 degrees

struct Stroke {
    std::size_t line;
    std::size_t segment;  ///< index of the segment's first vertex in its line
    Point2 a, b;
};

/// Parameters along both strokes of their crossing; false when parallel.
bool crossing(const Stroke& s, const Stroke& t, double& u, double& v) {
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const double ex = t.b.x - t.a.x, ey = t.b.y - t.a.y;
    const double det = dx * ey - dy * ex;
    if (det == 0.0) return false;
    const double fx = t.a.x - s.a.x, fy = t.a.y - s.a.y;
    u = (fx * ey - fy * ex) / det;
    v = (fx * dy - fy * dx) / det;
    return true;
}

bool perpendicular(Point2 a0, Point2 a1, Point2 b0, Point2 b1) {
    const double dot = (a1.x - a0.x) * (b1.x - b0.x) + (a1.y - a0.y) * (b1.y - b0.y);
    return std::abs(dot) <= perpendicular_cosine * distance(a0, a1) * distance(b0, b1);
}

/// Pairs short perpendicular strokes crossing near their middles into cross markers.
std::size_t pair_crossing_strokes(Plot& plot,
                                  const std::vector<Stroke>& strokes,
                                  double radius,
                                  std::vector<bool>& used) {
    std::vector<Point2> middles;
    for (const Stroke& s : strokes) middles.push_back({(s.a.x + s.b.x) / 2, (s.a.y + s.b.y) / 2});
    const PointGrid grid(middles, radius);
    std::size_t found = 0;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
        if (used[i]) continue;
        const Stroke& s = strokes[i];
        std::size_t best = strokes.size();
        double best_score = 1.0, best_u = 0.0;
        grid.near(middles[i], radius, [&](std::uint32_t j, double) {
            if (j == i || used[j]) return;
            const Stroke& t = strokes[j];
            double u = 0.0, v = 0.0;
            if (!perpendicular(s.a, s.b, t.a, t.b) || !crossing(s, t, u, v)) return;
            const double score = std::max(std::abs(u - 0.5), std::abs(v - 0.5));
            if (score <= 0.2 && (score < best_score || (score == best_score && j < best))) {
                best = j;
                best_score = score;
                best_u = u;
            }
        });
        if (best == strokes.size()) continue;
        used[i] = used[best] = true;
        const Point2 centre{s.a.x + best_u * (s.b.x - s.a.x), s.a.y + best_u * (s.b.y - s.a.y)};
        plot.markers.push_back(
            {centre, MarkerKind::cross, plot.lines[s.line].pen, plot.lines[s.line].offset});
        ++found;
    }
    return found;
}

/// Crosses drawn as arms from their centre: 3 to 8 short strokes sharing one end exactly, two
/// of them perpendicular.
std::size_t star_crosses(Plot& plot, const std::vector<Stroke>& strokes, std::vector<bool>& used) {
    struct End {
        Point2 at, other;
        std::size_t stroke;
    };
    std::vector<End> ends;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
        if (used[i]) continue;
        ends.push_back({strokes[i].a, strokes[i].b, i});
        ends.push_back({strokes[i].b, strokes[i].a, i});
    }
    std::sort(ends.begin(), ends.end(), [](const End& l, const End& r) {
        return std::tie(l.at.x, l.at.y, l.stroke) < std::tie(r.at.x, r.at.y, r.stroke);
    });
    std::size_t found = 0;
    for (std::size_t k = 0, m = 0; k < ends.size(); k = m) {
        for (m = k + 1; m < ends.size() && ends[m].at == ends[k].at;) ++m;
        if (m - k < 3 || m - k > 8) continue;
        bool square = false;
        for (std::size_t p = k; p < m; ++p) {
            for (std::size_t q = p + 1; q < m; ++q)
                square =
                    square || perpendicular(ends[p].at, ends[p].other, ends[q].at, ends[q].other);
        }
        if (!square) continue;
        for (std::size_t p = k; p < m; ++p) used[ends[p].stroke] = true;
        const PlotLine& line = plot.lines[strokes[ends[k].stroke].line];
        plot.markers.push_back({ends[k].at, MarkerKind::cross, line.pen, line.offset});
        ++found;
    }
    return found;
}

bool is_terrain_line(const HpglOptions& options, int pen) {
    const auto found = options.pens.find(pen);
    return found != options.pens.end() && found->second != PenRole::points &&
           found->second != PenRole::ignore;
}

/// Removes the segments used by crosses; a line loses the vertices no kept segment reaches.
void remove_segments(Plot& plot, std::vector<std::pair<std::size_t, std::size_t>>& removed) {
    std::sort(removed.begin(), removed.end());
    std::vector<PlotLine> kept;
    std::size_t r = 0;
    for (std::size_t i = 0; i < plot.lines.size(); ++i) {
        PlotLine& line = plot.lines[i];
        if (r >= removed.size() || removed[r].first != i) {
            kept.push_back(std::move(line));
            continue;
        }
        PlotLine piece{line.pen, {}, line.offset};
        for (std::size_t k = 0; k + 1 < line.points.size(); ++k) {
            const bool gone = r < removed.size() && removed[r] == std::pair{i, k};
            if (gone) ++r;
            if (!gone) {
                if (piece.points.empty()) piece.points.push_back(line.points[k]);
                piece.points.push_back(line.points[k + 1]);
            } else if (!piece.points.empty()) {
                kept.push_back(std::move(piece));
                piece = PlotLine{line.pen, {}, line.offset};
            }
        }
        if (!piece.points.empty()) kept.push_back(std::move(piece));
    }
    plot.lines = std::move(kept);
}

/// Finds cross markers among short strokes and removes their strokes from the lines. Lines of
/// terrain pens (breakline, boundary, hole) take part only as whole two-point lines; on other
/// pens every short segment does, so a cross whose stroke the next move extended (the pen stays
/// down after a PE ending in a draw) is still found.
std::size_t find_crosses(Plot& plot, const HpglOptions& options, double radius) {
    std::vector<Stroke> strokes;
    for (std::size_t i = 0; i < plot.lines.size(); ++i) {
        const auto& pts = plot.lines[i].points;
        const bool terrain = is_terrain_line(options, plot.lines[i].pen);
        if (terrain && pts.size() != 2) continue;
        for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
            if (distance(pts[k], pts[k + 1]) <= 2.0 * radius)
                strokes.push_back({i, k, pts[k], pts[k + 1]});
        }
    }
    std::vector<bool> used(strokes.size(), false);
    const std::size_t found =
        pair_crossing_strokes(plot, strokes, radius, used) + star_crosses(plot, strokes, used);
    if (found == 0) return 0;
    std::vector<std::pair<std::size_t, std::size_t>> removed;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
        if (used[i]) removed.emplace_back(strokes[i].line, strokes[i].segment);
    }
    remove_segments(plot, removed);
    return found;
}

/// Dots (pen-down without movement) and vertices drawn with a "points" pen become markers.
void add_point_markers(const Plot& plot,
                       const HpglOptions& options,
                       std::vector<PlotMarker>& markers) {
    for (const PlotLine& line : plot.lines) {
        const auto role = options.pens.find(line.pen);
        if (role != options.pens.end() && role->second == PenRole::points) {
            for (const Point2& p : line.points)
                markers.push_back({p, MarkerKind::pen_vertex, line.pen, line.offset});
        } else if (line.points.size() == 1) {
            markers.push_back({line.points[0], MarkerKind::dot, line.pen, line.offset});
        }
    }
}

using Pair = std::tuple<double, double, std::size_t, std::size_t>;  // key, distance, spot, marker

/// Greedy matching in increasing key: each spot height and each marker used once.
void assign_pairs(std::vector<Pair>& pairs,
                  const std::vector<PlotMarker>& markers,
                  std::vector<SpotHeight>& spots,
                  std::vector<std::size_t>& marker_of) {
    std::sort(pairs.begin(), pairs.end());
    std::vector<bool> taken(markers.size(), false);
    marker_of.assign(spots.size(), markers.size());
    for (const auto& [key, d, spot, m] : pairs) {
        if (marker_of[spot] != markers.size() || taken[m]) continue;
        marker_of[spot] = m;
        taken[m] = true;
    }
}

/// The label-to-marker offset most labels share, if two thirds of them (at least 3) agree within
/// 10 % of the radius (plans place height labels consistently, e.g. 1 mm right and 0.5 mm up).
std::optional<Point2> common_offset(const std::vector<SpotHeight>& spots,
                                    const std::vector<PlotMarker>& markers,
                                    const std::vector<std::size_t>& marker_of,
                                    double radius) {
    std::vector<double> dx, dy;
    for (std::size_t s = 0; s < spots.size(); ++s) {
        if (marker_of[s] == markers.size()) continue;
        dx.push_back(spots[s].at.x - markers[marker_of[s]].at.x);
        dy.push_back(spots[s].at.y - markers[marker_of[s]].at.y);
    }
    if (dx.size() < 3) return std::nullopt;
    const auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
        return v[v.size() / 2];
    };
    const Point2 offset{median(dx), median(dy)};
    std::size_t agree = 0;
    for (std::size_t i = 0; i < dx.size(); ++i)
        agree += distance({dx[i], dy[i]}, offset) <= 0.1 * radius ? 1 : 0;
    if (agree < 3 || agree * 3 < dx.size() * 2) return std::nullopt;
    return offset;
}

void match_labels(const Plot& plot, const HpglOptions& options, double radius, TerrainPlan& plan) {
    const auto& markers = plot.markers;
    std::vector<Point2> places;
    for (const PlotMarker& m : markers) places.push_back(m.at);
    const PointGrid grid(places, radius);
    std::vector<Pair> pairs;
    for (std::size_t i = 0; i < plot.labels.size(); ++i) {
        const PlotLabel& label = plot.labels[i];
        const bool integers = std::find(options.height_pens.begin(), options.height_pens.end(),
                                        label.pen) != options.height_pens.end();
        const auto z = parse_height_label(label.text, integers);
        if (!z) continue;
        const std::size_t spot = plan.spots.size();
        plan.spots.push_back({label.at, *z, i, false});
        grid.near(label.at, radius,
                  [&](std::uint32_t m, double d) { pairs.emplace_back(d, d, spot, m); });
    }
    // Pass 1: nearest first. Pass 2, when the plan has a house style: nearest to where that
    // style puts the marker, so a neighbour's marker closer to a label does not steal it.
    std::vector<std::size_t> marker_of;
    assign_pairs(pairs, markers, plan.spots, marker_of);
    if (const auto offset = common_offset(plan.spots, markers, marker_of, radius)) {
        for (auto& [key, d, spot, m] : pairs) {
            const Point2 expected{plan.spots[spot].at.x - offset->x,
                                  plan.spots[spot].at.y - offset->y};
            key = distance(expected, markers[m].at);
        }
        assign_pairs(pairs, markers, plan.spots, marker_of);
    }
    for (std::size_t s = 0; s < plan.spots.size(); ++s) {
        if (marker_of[s] == markers.size()) continue;
        plan.spots[s].at = markers[marker_of[s]].at;
        plan.spots[s].on_marker = true;
    }
    plan.height_labels = plan.spots.size();
    std::string first;
    for (const SpotHeight& s : plan.spots) {
        if (s.on_marker) continue;
        if (plan.labels_without_marker++ < 5)
            first += " " + std::to_string(plot.labels[s.label].offset);
    }
    if (plan.labels_without_marker > 0) {
        plan.warnings.push_back(std::to_string(plan.labels_without_marker) +
                                " height labels have no marker within " +
                                std::to_string(options.marker_radius_mm) +
                                " mm: the label position was used (labels at bytes" + first + ")");
    }
}

}  // namespace

std::optional<double> parse_height_label(std::string_view text, bool allow_integer) {
    const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!text.empty() && blank(text.front())) text.remove_prefix(1);
    while (!text.empty() && blank(text.back())) text.remove_suffix(1);
    std::size_t i = 0;
    bool negative = false;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) negative = text[i++] == '-';
    std::uint64_t mantissa = 0;
    int digits = 0, decimals = 0;
    bool separator = false;
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c >= '0' && c <= '9') {
            if (++digits > 17) return std::nullopt;
            mantissa = mantissa * 10 + static_cast<unsigned>(c - '0');
            if (separator) ++decimals;
        } else if ((c == '.' || c == ',') && !separator) {
            separator = true;
        } else {
            return std::nullopt;
        }
    }
    if (digits == 0 || (!separator && !allow_integer)) return std::nullopt;
    // Exact integer divided by an exact power of ten: the correctly rounded decimal value.
    static constexpr double powers[] = {1e0, 1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,
                                        1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17};
    const double value = static_cast<double>(mantissa) / powers[decimals];
    return negative ? -value : value;
}

TerrainPlan build_terrain_plan(Plot& plot, const HpglOptions& options) {
    TerrainPlan plan;
    const double radius = options.marker_radius_mm * units_per_mm;
    plan.crosses = find_crosses(plot, options, radius);
    add_point_markers(plot, options, plot.markers);
    plan.markers = plot.markers.size();
    match_labels(plot, options, radius, plan);
    assign_line_roles(plot, options, radius, plan);
    return plan;
}

}  // namespace dtm::io::hpgl
