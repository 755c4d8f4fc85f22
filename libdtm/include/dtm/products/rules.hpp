// SPDX-License-Identifier: MIT
/// @file
/// @brief The automatic choices of products::build(): the DEM cell size and the contour
/// interval, from the surface.
#pragma once

#include "dtm/algo/surface_stats.hpp"

namespace dtm::products {

/// Largest of 1, 2, 2.5, 5 x 10^k not above @p value (value > 0).
[[nodiscard]] double nice_floor(double value);
/// Smallest of 1, 2, 2.5, 5 x 10^k above @p value (value > 0).
[[nodiscard]] double nice_next(double value);

/// Half the mean point spacing sqrt(planimetric area / vertices), rounded down by nice_floor (at
/// least two cells between neighbouring points, so the DEM keeps the detail of the survey), at
/// least 1 mm, enlarged (nice_next) while the DEM over the extent would pass 50 million cells.
[[nodiscard]] double default_cell(const SurfaceStats& surface);
inline constexpr const char* default_cell_rule =
    "half the mean point spacing, rounded down to 1, 2, 2.5 or 5 x 10^k";

/// The z range divided by 20, rounded down by nice_floor (about 20 contour levels); 1 for a
/// flat surface.
[[nodiscard]] double default_interval(const SurfaceStats& surface);
inline constexpr const char* default_interval_rule =
    "z range / 20, rounded down to 1, 2, 2.5 or 5 x 10^k";

}  // namespace dtm::products
