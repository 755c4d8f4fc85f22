// SPDX-License-Identifier: MIT
/// @file
/// @brief Summary measures of a TIN surface: planimetric and 3-D area, extent and z range.
#pragma once

#include <cstddef>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct SurfaceStats {
    std::size_t vertex_count = 0;
    std::size_t triangle_count = 0;
    std::size_t constraint_count = 0;
    /// Extent of the vertices that some triangle uses (unused vertices are not part of the
    /// surface).
    Box2 extent;
    double z_min = 0.0;  ///< over the used vertices; 0 when the TIN has no triangle
    double z_max = 0.0;
    double planimetric_area = 0.0;  ///< sum of triangle areas projected on the xy plane
    double surface_area = 0.0;      ///< sum of the true 3-D triangle areas (>= planimetric_area)
};

/// Measures @p tin. Areas use compensated (Kahan-Neumaier) summation and coordinates taken
/// relative to the first vertex, so large projected offsets (S-JTSK, UTM) cost no precision.
[[nodiscard]] SurfaceStats surface_stats(const Tin& tin);

}  // namespace dtm
