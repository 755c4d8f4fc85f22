// SPDX-License-Identifier: MIT
/// @file
/// @brief Line charts and histograms on a Canvas: linear or logarithmic axes with round ticks,
/// series of points, bars, a legend. Used by `dtm methods compare` and the profile plots.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/io/draw/canvas.hpp"

namespace dtm::io::draw {

struct Axis {
    std::string label;
    bool log = false;           ///< base-10 logarithmic (every value must be > 0)
    std::optional<double> min;  ///< default: from the data
    std::optional<double> max;
};

struct Series {
    std::string name;            ///< legend entry (empty: none)
    std::vector<Point2> points;  ///< in data units; a NaN y breaks the line (a gap)
    Color color = Color::rgb(0x1f77b4);
    bool line = true;
    bool markers = true;
    std::vector<double> dash_mm;  ///< dashed line
};

/// A histogram: counts[i] over [edges[i], edges[i + 1]).
struct Bars {
    std::string name;
    std::vector<double> edges;
    std::vector<double> counts;
    Color color = Color::rgb(0x1f77b4, 0.6);
};

struct Chart {
    std::string title;
    Axis x;
    Axis y;
    std::vector<Series> series;
    std::vector<Bars> bars;
    /// Units of y per unit of x on the page (profiles: vertical exaggeration applies on top);
    /// 0: fill the plot area.
    double aspect = 0.0;
};

/// Draws @p chart into the rectangle of @p canvas at @p top_left, @p width x @p height mm.
/// @throws UsageError for a log axis with a value <= 0 or a chart without data.
void draw_chart(Canvas& canvas, const Chart& chart, Point2 top_left, double width, double height);

/// One chart on its own page (.pdf, .svg or .png by extension), written atomically.
void write_chart(const Chart& chart,
                 const std::filesystem::path& path,
                 double width_mm = 160.0,
                 double height_mm = 100.0);

/// Round tick positions covering [lo, hi]: 1, 2, 5 x 10^k steps (linear, about @p target ticks)
/// or powers of ten (log). Exposed for tests.
[[nodiscard]] std::vector<double> axis_ticks(double lo, double hi, bool log, int target = 6);

}  // namespace dtm::io::draw
