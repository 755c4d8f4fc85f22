// SPDX-License-Identifier: MIT
/// @file
/// @brief Computed (rounded) constructions, never decisions: the circumcentre of three points.
/// Decisions go through the exact predicates (predicates.hpp, bisector_predicates.hpp).
#pragma once

#include "dtm/core/point.hpp"

namespace dtm::geom {

/// Which corner (0, 1, 2) of triangle a, b, c has the angle nearest a right angle (the corner
/// differences are taken from in Sugihara and Iri's method 2, thesis 000 §3.6.3).
[[nodiscard]] int nearest_right_angle(const Point2& a, const Point2& b, const Point2& c) noexcept;

/// Circumcentre of a, b, c (not collinear), computed relative to the vertex whose angle is
/// nearest a right angle, where the triangle's area is best conditioned (Sugihara and Iri's
/// method 2, thesis 000 §3.6.3 eq. 7-11). The result depends on the order of the arguments only
/// in the last bits; pass them in a fixed order where two callers must agree to the bit.
[[nodiscard]] Point2 circumcentre(const Point2& a, const Point2& b, const Point2& c) noexcept;

}  // namespace dtm::geom
