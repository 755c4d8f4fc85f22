// SPDX-License-Identifier: MIT
/// @file
/// @brief Plain point and box value types. x, y are planar CRS coordinates; z is elevation.
#pragma once

#include <algorithm>
#include <limits>

namespace dtm {

struct Point2 {
    double x = 0.0;
    double y = 0.0;
    friend bool operator==(const Point2&, const Point2&) = default;
};

struct Point3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
    [[nodiscard]] Point2 xy() const noexcept { return {x, y}; }
    friend bool operator==(const Point3&, const Point3&) = default;
};

/// Axis-aligned box in xy. Empty until the first point is added.
struct Box2 {
    double xmin = std::numeric_limits<double>::infinity();
    double ymin = std::numeric_limits<double>::infinity();
    double xmax = -std::numeric_limits<double>::infinity();
    double ymax = -std::numeric_limits<double>::infinity();

    [[nodiscard]] bool empty() const noexcept { return xmin > xmax || ymin > ymax; }
    void add(double x, double y) noexcept {
        xmin = std::min(xmin, x);
        ymin = std::min(ymin, y);
        xmax = std::max(xmax, x);
        ymax = std::max(ymax, y);
    }
    template <class P>
    void add(const P& p) noexcept {
        add(p.x, p.y);
    }
};

}  // namespace dtm
