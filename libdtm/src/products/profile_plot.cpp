// SPDX-License-Identifier: MIT
// Section plots: a frame, round ticks (io::draw::axis_ticks), height lines per surface (a new
// line after every gap), station labels along the bottom, the exaggeration stated in the title.
#include "dtm/products/profile_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "dtm/core/error.hpp"
#include "dtm/io/draw/chart.hpp"

namespace dtm::products {

using io::draw::Color;
using io::draw::HAlign;
using io::draw::Stroke;
using io::draw::TextStyle;
using io::draw::VAlign;

Color surface_color(std::size_t i) {
    static constexpr std::uint32_t cycle[] = {0x0072b2, 0xd55e00, 0x009e73, 0xcc79a7,
                                              0xe69f00, 0x56b4e9, 0x000000};
    return Color::rgb(cycle[i % (sizeof cycle / sizeof cycle[0])]);
}

std::string station_label(double chainage) {
    const double c = std::round(chainage * 100.0) / 100.0;
    const double km = std::floor(std::fabs(c) / 1000.0);
    const double m = std::fabs(c) - km * 1000.0;
    char text[48];
    std::snprintf(text, sizeof text, "%s%.0f+%06.2f", c < 0 ? "-" : "", km, m);
    return text;
}

void draw_profile(io::draw::Canvas& canvas,
                  const ProfilePlot& plot,
                  Point2 top_left,
                  double width,
                  double height) {
    double x_lo = 0.0;
    double x_hi = 0.0;
    double z_lo = std::numeric_limits<double>::infinity();
    double z_hi = -z_lo;
    for (const Profile& p : plot.profiles) {
        x_hi = std::max(x_hi, p.length);
        for (const ProfileRun& r : p.runs) {
            for (const ProfilePoint& q : r.points) {
                z_lo = std::min(z_lo, q.z);
                z_hi = std::max(z_hi, q.z);
            }
        }
    }
    if (!(z_lo <= z_hi) || !(x_hi > x_lo)) {
        throw UsageError("profile plot: no surface along the line");
    }
    const double pad = std::max((z_hi - z_lo) * 0.1, 0.5);
    z_lo -= pad;
    z_hi += pad;
    // Plot area inside margins for ticks and labels.
    const double left = top_left.x + 16.0;
    const double right = top_left.x + width - 4.0;
    const double top = top_left.y + 9.0;
    const double bottom = top_left.y + height - 14.0;
    double sx = (right - left) / (x_hi - x_lo);  // mm per metre along
    double sy = sx * plot.exaggeration;          // mm per metre up
    if (sy * (z_hi - z_lo) > bottom - top) {
        sy = (bottom - top) / (z_hi - z_lo);
        sx = sy / plot.exaggeration;
    } else {
        const double extra = (bottom - top) / sy - (z_hi - z_lo);  // centre the heights
        z_lo -= extra / 2.0;
        z_hi += extra / 2.0;
    }
    const auto page = [&](double c, double z) {
        return Point2{left + (c - x_lo) * sx, bottom - (z - z_lo) * sy};
    };
    const double plot_right = left + (x_hi - x_lo) * sx;
    const Stroke frame{Color::rgb(0x000000), 0.25, {}, false};
    const Stroke grid{Color::rgb(0xcccccc), 0.1, {}, false};
    TextStyle small;
    small.size_pt = 6.0;
    TextStyle title = small;
    title.size_pt = 8.0;
    title.bold = true;
    char heading[256];
    std::snprintf(heading, sizeof heading,
                  width < 120.0 ? "%s   (%gx)" : "%s   (vertical exaggeration %gx)",
                  plot.title.c_str(), plot.exaggeration);
    canvas.text({left, top_left.y + 5.0}, heading, title);
    // Height grid.
    small.h = HAlign::right;
    small.v = VAlign::middle;
    for (const double z : io::draw::axis_ticks(z_lo, z_hi, false, 5)) {
        if (z < z_lo || z > z_hi) continue;
        const Point2 a = page(x_lo, z);
        const std::vector<Point2> line{a, {plot_right, a.y}};
        canvas.polyline(line, grid);
        char t[32];
        std::snprintf(t, sizeof t, "%g", z);
        canvas.text({a.x - 1.0, a.y}, t, small);
    }
    // Stations.
    double interval = plot.station_interval;
    if (!(interval > 0.0)) {
        const std::vector<double> ticks = io::draw::axis_ticks(0.0, x_hi, false, 8);
        interval = ticks.size() > 1 ? ticks[1] - ticks[0] : x_hi;
    }
    small.h = HAlign::center;
    small.v = VAlign::top;
    const double first = std::ceil((x_lo + plot.chainage_offset) / interval) * interval;
    for (double s = first; s - plot.chainage_offset <= x_hi + 1e-9 * x_hi; s += interval) {
        const double c = s - plot.chainage_offset;
        const Point2 a = page(c, z_lo);
        const std::vector<Point2> line{{a.x, top}, {a.x, bottom}};
        canvas.polyline(line, grid);
        canvas.text({a.x, bottom + 1.0},
                    plot.chainage_offset != 0.0
                        ? (std::to_string(static_cast<long>(std::lround(s))))
                        : station_label(s),
                    small);
    }
    small.v = VAlign::bottom;
    canvas.text({(left + plot_right) / 2.0, top_left.y + height - 1.0}, plot.x_label, small);
    canvas.rectangle({left, top}, plot_right - left, bottom - top, nullptr, &frame);
    // The surfaces, and the legend.
    canvas.push_clip({left, top}, plot_right - left, bottom - top);
    for (std::size_t i = 0; i < plot.profiles.size(); ++i) {
        const Stroke s{surface_color(i), 0.35, {}, true};
        for (const ProfileRun& r : plot.profiles[i].runs) {
            std::vector<Point2> line;
            line.reserve(r.points.size());
            for (const ProfilePoint& q : r.points) {
                line.push_back(page(q.chainage, q.z));
            }
            canvas.polyline(line, s);
        }
    }
    canvas.pop_clip();
    TextStyle legend = small;
    legend.h = HAlign::left;
    legend.v = VAlign::middle;
    double lx = left + 2.0;
    for (std::size_t i = 0; i < plot.names.size() && i < plot.profiles.size(); ++i) {
        const Stroke s{surface_color(i), 0.6, {}, false};
        const std::vector<Point2> mark{{lx, top + 3.0}, {lx + 5.0, top + 3.0}};
        canvas.polyline(mark, s);
        canvas.text({lx + 6.0, top + 3.0}, plot.names[i], legend);
        lx += 10.0 + canvas.measure(plot.names[i], legend).width;
    }
}

}  // namespace dtm::products
