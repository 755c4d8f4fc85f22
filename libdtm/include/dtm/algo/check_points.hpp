// SPDX-License-Identifier: MIT
/// @file
/// @brief Checking a surface against control points: the surface height at each point, the
/// residual, and the accuracy statistics surveyors report (mean, standard deviation, RMSE, the
/// NSSDA 95 % figure, largest residual, percentiles of the absolute residual).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "dtm/algo/surface_height.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"

namespace dtm {

/// One control point checked. residual = point z - surface z (positive: the point lies above
/// the surface, i.e. the surface is too low there).
struct CheckResult {
    bool inside = false;  ///< the surface exists at the point (else surface_z, residual unset)
    double surface_z = 0.0;
    double residual = 0.0;
};

struct CheckStatistics {
    std::size_t points = 0;   ///< control points given
    std::size_t inside = 0;   ///< on the surface (the statistics are over these)
    std::size_t outside = 0;  ///< outside the surface or in a hole: listed, not in the statistics
    double mean = 0.0;        ///< mean residual (bias)
    double std_dev = 0.0;     ///< sample standard deviation (n - 1)
    double rmse = 0.0;        ///< sqrt(mean of residual^2)
    double mean_abs = 0.0;
    double min = 0.0;  ///< most negative residual
    double max = 0.0;  ///< most positive residual
    double max_abs = 0.0;
    std::size_t max_abs_index = 0;  ///< index (into the points) of the largest |residual|
    double nssda_95 = 0.0;          ///< 1.96 x RMSE (FGDC NSSDA vertical accuracy at 95 %)
    /// Percentiles of |residual| (linear interpolation between order statistics, as numpy's
    /// default): 50, 68.27, 90, 95, 99.
    double p50 = 0.0;
    double p68 = 0.0;
    double p90 = 0.0;
    double p95 = 0.0;
    double p99 = 0.0;
};

/// The surface height and residual at every point, in parallel. @throws Cancelled
[[nodiscard]] std::vector<CheckResult> check_points(const SurfaceHeight& surface,
                                                    std::span<const Point3> points,
                                                    const Progress& progress = {});

/// Statistics over the inside results (compensated sums).
[[nodiscard]] CheckStatistics check_statistics(std::span<const CheckResult> results);

/// The @p q-th percentile (0..100) of sorted values by linear interpolation between order
/// statistics (numpy's default); 0 for no values.
[[nodiscard]] double percentile_sorted(std::span<const double> sorted, double q);

}  // namespace dtm
