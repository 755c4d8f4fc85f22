// SPDX-License-Identifier: MIT
// Charts on a Canvas. Ticks: linear axes step by 1, 2 or 5 x 10^k chosen for about six ticks
// (Heckbert, "Nice numbers for graph labels", Graphics Gems 1990); log axes tick at powers of
// ten (with 2 and 5 between them when the range is under three decades).
#include "dtm/io/draw/chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "dtm/core/error.hpp"

namespace dtm::io::draw {
namespace {

struct Range {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    void add(double v) {
        if (!std::isfinite(v)) return;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    [[nodiscard]] bool empty() const { return lo > hi; }
};

double nice_step(double span, int target) {
    const double raw = span / std::max(target, 1);
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0}) {
        if (m * power >= raw) return m * power;
    }
    return 10.0 * power;
}

std::string tick_label(double v, bool log) {
    char buffer[32];
    if (log) {
        const double e = std::log10(v);
        if (std::abs(e - std::round(e)) < 1e-9 && (std::abs(e) >= 3.0)) {
            std::snprintf(buffer, sizeof buffer, "1e%d", static_cast<int>(std::round(e)));
            return buffer;
        }
    }
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

/// Data -> page mapping of one axis.
struct Scale {
    double lo, hi, page_lo, page_hi;
    bool log;
    [[nodiscard]] double operator()(double v) const {
        const double t = log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                             : (v - lo) / (hi - lo);
        return page_lo + t * (page_hi - page_lo);
    }
};

Range data_range(const Chart& chart, bool x_axis, bool log) {
    Range r;
    for (const Series& s : chart.series) {
        for (const Point2& p : s.points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
            r.add(x_axis ? p.x : p.y);
        }
    }
    for (const Bars& b : chart.bars) {
        if (x_axis) {
            for (double e : b.edges) r.add(e);
        } else {
            if (!log) r.add(0.0);
            for (double c : b.counts) {
                if (!log || c > 0.0) r.add(c);
            }
        }
    }
    return r;
}

Range axis_range(const Chart& chart, const Axis& axis, bool x_axis) {
    Range r = data_range(chart, x_axis, axis.log);
    if (axis.min) r.lo = *axis.min;
    if (axis.max) r.hi = *axis.max;
    if (r.empty()) throw UsageError("chart '" + chart.title + "' has no data");
    if (axis.log) {
        if (!(r.lo > 0.0)) {
            throw UsageError("chart '" + chart.title + "': the logarithmic axis '" + axis.label +
                             "' needs values above 0");
        }
        if (!axis.min) r.lo = std::pow(10.0, std::floor(std::log10(r.lo) + 1e-12));
        if (!axis.max) r.hi = std::pow(10.0, std::ceil(std::log10(r.hi) - 1e-12));
        if (r.hi <= r.lo) r.hi = r.lo * 10.0;
        return r;
    }
    if (r.hi <= r.lo) {
        const double pad = r.lo == 0.0 ? 1.0 : std::abs(r.lo) * 0.1;
        r.lo -= pad;
        r.hi += pad;
    }
    const double step = nice_step(r.hi - r.lo, 6);
    if (!axis.min) r.lo = std::floor(r.lo / step + 1e-9) * step;
    if (!axis.max) r.hi = std::ceil(r.hi / step - 1e-9) * step;
    return r;
}

}  // namespace

std::vector<double> axis_ticks(double lo, double hi, bool log, int target) {
    std::vector<double> ticks;
    if (!(hi > lo)) return {lo};
    if (log) {
        const int e0 = static_cast<int>(std::floor(std::log10(lo) + 1e-12));
        const int e1 = static_cast<int>(std::ceil(std::log10(hi) - 1e-12));
        const bool minor = e1 - e0 < 3;
        for (int e = e0; e <= e1; ++e) {
            const double p = std::pow(10.0, e);
            for (const double m : {1.0, 2.0, 5.0}) {
                if (m != 1.0 && !minor) continue;
                const double v = m * p;
                if (v >= lo * (1 - 1e-12) && v <= hi * (1 + 1e-12)) ticks.push_back(v);
            }
        }
        return ticks;
    }
    const double step = nice_step(hi - lo, target);
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) {
        ticks.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
    }
    return ticks;
}

void draw_chart(Canvas& canvas, const Chart& chart, Point2 top_left, double width, double height) {
    const Range xr = axis_range(chart, chart.x, true);
    const Range yr = axis_range(chart, chart.y, false);
    TextStyle small;
    small.size_pt = 7.0;
    TextStyle title = small;
    title.size_pt = 9.0;
    title.bold = true;
    title.h = HAlign::center;
    title.v = VAlign::top;

    // Plot area inside the margins for tick labels, axis labels and the title.
    const double left = top_left.x + 16.0;
    const double right = top_left.x + width - 4.0;
    const double top = top_left.y + (chart.title.empty() ? 4.0 : 9.0);
    double bottom = top_left.y + height - 12.0;
    double plot_right = right;
    if (chart.aspect > 0.0) {
        // Keep data units in proportion: shrink one side of the area.
        const double sx = (right - left) / (xr.hi - xr.lo);
        const double sy = (bottom - top) / (yr.hi - yr.lo);
        const double want = sx * chart.aspect;  // page mm per y unit
        if (want < sy) {
            bottom = top + want * (yr.hi - yr.lo);
        } else {
            plot_right = left + (sy / chart.aspect) * (xr.hi - xr.lo);
        }
    }
    const Scale sx{xr.lo, xr.hi, left, plot_right, chart.x.log};
    const Scale sy{yr.lo, yr.hi, bottom, top, chart.y.log};

    if (!chart.title.empty()) {
        canvas.text({top_left.x + width / 2.0, top_left.y + 1.0}, chart.title, title);
    }
    const Stroke grid{Color::rgb(0xdddddd), 0.15, {}, false};
    const Stroke frame{Color::rgb(0x333333), 0.3, {}, false};
    TextStyle xt = small;
    xt.h = HAlign::center;
    xt.v = VAlign::top;
    for (const double t : axis_ticks(xr.lo, xr.hi, chart.x.log)) {
        const double px = sx(t);
        const std::vector<Point2> line{{px, top}, {px, bottom}};
        canvas.polyline(line, grid);
        canvas.text({px, bottom + 1.2}, tick_label(t, chart.x.log), xt);
    }
    TextStyle yt = small;
    yt.h = HAlign::right;
    yt.v = VAlign::middle;
    for (const double t : axis_ticks(yr.lo, yr.hi, chart.y.log)) {
        const double py = sy(t);
        const std::vector<Point2> line{{left, py}, {plot_right, py}};
        canvas.polyline(line, grid);
        canvas.text({left - 1.2, py}, tick_label(t, chart.y.log), yt);
    }
    TextStyle xl = small;
    xl.h = HAlign::center;
    xl.v = VAlign::bottom;
    canvas.text({(left + plot_right) / 2.0, top_left.y + height - 0.5}, chart.x.label, xl);
    TextStyle yl = small;
    yl.h = HAlign::center;
    yl.v = VAlign::top;
    canvas.text({top_left.x + 0.5, (top + bottom) / 2.0}, chart.y.label, yl, 90.0);

    canvas.push_clip({left, top}, plot_right - left, bottom - top);
    for (const Bars& b : chart.bars) {
        for (std::size_t i = 0; i + 1 < b.edges.size() && i < b.counts.size(); ++i) {
            const double x0 = sx(b.edges[i]);
            const double x1 = sx(b.edges[i + 1]);
            const double y0 = sy(chart.y.log ? yr.lo : 0.0);
            const double y1 = sy(chart.y.log ? std::max(b.counts[i], yr.lo) : b.counts[i]);
            canvas.rectangle({x0, y1}, x1 - x0, y0 - y1, &b.color, nullptr);
        }
    }
    for (const Series& s : chart.series) {
        std::vector<Point2> run;
        const Stroke stroke{s.color, 0.35, s.dash_mm, true};
        const auto flush = [&] {
            if (s.line && run.size() > 1) canvas.polyline(run, stroke);
            run.clear();
        };
        for (const Point2& p : s.points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || (chart.x.log && p.x <= 0) ||
                (chart.y.log && p.y <= 0)) {
                flush();
                continue;
            }
            run.push_back({sx(p.x), sy(p.y)});
            if (s.markers) canvas.circle(run.back(), 0.6, &s.color, nullptr);
        }
        flush();
    }
    canvas.pop_clip();
    const std::vector<Point2> box{
        {left, top}, {plot_right, top}, {plot_right, bottom}, {left, bottom}};
    canvas.polyline(box, frame, true);

    // Legend, top-left inside the plot.
    double ly = top + 2.5;
    TextStyle lt = small;
    lt.v = VAlign::middle;
    const Color white = Color::rgb(0xffffff, 0.8);
    std::size_t entries = 0;
    double legend_width = 0.0;
    for (const Series& s : chart.series) {
        if (s.name.empty()) continue;
        ++entries;
        legend_width = std::max(legend_width, canvas.measure(s.name, lt).width);
    }
    for (const Bars& b : chart.bars) {
        if (b.name.empty()) continue;
        ++entries;
        legend_width = std::max(legend_width, canvas.measure(b.name, lt).width);
    }
    if (entries == 0) return;
    canvas.rectangle({left + 1.0, top + 1.0}, legend_width + 10.0,
                     3.2 * static_cast<double>(entries) + 0.6, &white, nullptr);
    for (const Series& s : chart.series) {
        if (s.name.empty()) continue;
        const std::vector<Point2> sample{{left + 2.0, ly}, {left + 7.0, ly}};
        canvas.polyline(sample, Stroke{s.color, 0.35, s.dash_mm, true});
        canvas.text({left + 8.5, ly}, s.name, lt);
        ly += 3.2;
    }
    for (const Bars& b : chart.bars) {
        if (b.name.empty()) continue;
        canvas.rectangle({left + 2.0, ly - 1.0}, 5.0, 2.0, &b.color, nullptr);
        canvas.text({left + 8.5, ly}, b.name, lt);
        ly += 3.2;
    }
}

void write_chart(const Chart& chart,
                 const std::filesystem::path& path,
                 double width_mm,
                 double height_mm) {
    Canvas canvas(path, width_mm, height_mm, 200.0);
    draw_chart(canvas, chart, {0.0, 0.0}, width_mm, height_mm);
    canvas.finish();
}

}  // namespace dtm::io::draw
