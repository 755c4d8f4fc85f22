// SPDX-License-Identifier: MIT
/// @file
/// @brief The oriented rectangle a map label (or a marker) occupies, in CRS units, and the
/// separating-axis overlap test used by contour and spot-height label placement.
#pragma once

#include <array>
#include <cmath>

#include "dtm/core/point.hpp"

namespace dtm {

/// A rectangle centred on @p centre whose width runs along the unit vector @p axis (the text's
/// baseline direction) and whose height runs along the text's up vector (axis turned 90 degrees
/// counter-clockwise).
struct LabelBox {
    Point2 centre;
    Point2 axis{1.0, 0.0};  ///< unit baseline direction
    double half_width = 0.0;
    double half_height = 0.0;

    /// The up vector: @p axis turned 90 degrees counter-clockwise.
    [[nodiscard]] Point2 up() const noexcept { return {-axis.y, axis.x}; }
    /// Corners counter-clockwise from bottom-left (as read).
    [[nodiscard]] std::array<Point2, 4> corners() const noexcept;
    /// The axis-aligned box around the corners.
    [[nodiscard]] Box2 bounds() const noexcept;
    /// The same box grown by @p margin on every side.
    [[nodiscard]] LabelBox grown(double margin) const noexcept {
        return {centre, axis, half_width + margin, half_height + margin};
    }
    /// An axis-aligned box (a marker, a furniture panel).
    [[nodiscard]] static LabelBox of(const Box2& box) noexcept {
        return {{(box.xmin + box.xmax) / 2.0, (box.ymin + box.ymax) / 2.0},
                {1.0, 0.0},
                (box.xmax - box.xmin) / 2.0,
                (box.ymax - box.ymin) / 2.0};
    }
};

/// True when the interiors of @p a and @p b intersect (touching edges do not count).
[[nodiscard]] bool overlaps(const LabelBox& a, const LabelBox& b) noexcept;

/// True when the segment @p p - @p q passes through the interior of @p box.
[[nodiscard]] bool crosses(const LabelBox& box, Point2 p, Point2 q) noexcept;

/// True when every corner of @p box lies inside @p frame (edges included).
[[nodiscard]] bool inside(const LabelBox& box, const Box2& frame) noexcept;

}  // namespace dtm
