// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: one triangle's planimetric and 3-D area as surface_stats() sums them, with
/// coordinates taken relative to @p origin (the first triangle's first corner), so that a
/// distributed run adds the very same terms.
#pragma once

#include <cmath>

#include "dtm/core/point.hpp"

namespace dtm::detail {

struct AreaTerms {
    double planimetric = 0.0;
    double surface = 0.0;
};

[[nodiscard]] inline AreaTerms area_terms(const Point3& origin,
                                          const Point3& p0,
                                          const Point3& p1,
                                          const Point3& p2) noexcept {
    const double ux = (p1.x - origin.x) - (p0.x - origin.x);
    const double uy = (p1.y - origin.y) - (p0.y - origin.y);
    const double uz = p1.z - p0.z;
    const double vx = (p2.x - origin.x) - (p0.x - origin.x);
    const double vy = (p2.y - origin.y) - (p0.y - origin.y);
    const double vz = p2.z - p0.z;
    const double cx = uy * vz - uz * vy;
    const double cy = uz * vx - ux * vz;
    const double cz = ux * vy - uy * vx;
    return {0.5 * std::fabs(cz), 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz)};
}

}  // namespace dtm::detail
