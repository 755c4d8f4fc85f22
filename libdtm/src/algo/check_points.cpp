// SPDX-License-Identifier: MIT
// Check points: residuals of control points against a surface, and their statistics.
//
// residual = z_point - z_surface. Mean, RMSE and mean |r| use compensated sums; the standard
// deviation is the two-pass sample formula sqrt(sum (r - mean)^2 / (n - 1)). Percentiles of |r|
// interpolate linearly between order statistics: for q in [0, 100], h = (n - 1) q / 100 and
// P = x[floor h] + (h - floor h) (x[floor h + 1] - x[floor h]) (Hyndman and Fan 1996, method 7,
// numpy's default). NSSDA: FGDC-STD-007.3-1998, vertical accuracy at 95 % = 1.9600 RMSE_z.
#include "dtm/algo/check_points.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "algo/detail/compensated_sum.hpp"

namespace dtm {

std::vector<CheckResult> check_points(const SurfaceHeight& surface,
                                      std::span<const Point3> points,
                                      const Progress& progress) {
    std::vector<CheckResult> out(points.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          progress.check();
                          for (std::size_t i = r.begin(); i != r.end(); ++i) {
                              CheckResult& c = out[i];
                              c.inside = surface.height(points[i].x, points[i].y, c.surface_z);
                              if (c.inside) {
                                  c.residual = points[i].z - c.surface_z;
                              }
                          }
                      });
    progress.report(1.0, "checking points");
    return out;
}

double percentile_sorted(std::span<const double> sorted, double q) {
    if (sorted.empty()) {
        return 0.0;
    }
    const double h = static_cast<double>(sorted.size() - 1) * std::clamp(q, 0.0, 100.0) / 100.0;
    const auto lo = static_cast<std::size_t>(std::floor(h));
    const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (h - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

CheckStatistics check_statistics(std::span<const CheckResult> results) {
    CheckStatistics s;
    s.points = results.size();
    detail::CompensatedSum sum;
    detail::CompensatedSum squares;
    detail::CompensatedSum absolute;
    std::vector<double> abs_values;
    bool first = true;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const CheckResult& c = results[i];
        if (!c.inside) {
            continue;
        }
        const double r = c.residual;
        sum.add(r);
        squares.add(r * r);
        absolute.add(std::fabs(r));
        abs_values.push_back(std::fabs(r));
        if (first || r < s.min) {
            s.min = r;
        }
        if (first || r > s.max) {
            s.max = r;
        }
        if (first || std::fabs(r) > s.max_abs) {
            s.max_abs = std::fabs(r);
            s.max_abs_index = i;
        }
        first = false;
    }
    s.inside = abs_values.size();
    s.outside = s.points - s.inside;
    if (s.inside == 0) {
        return s;
    }
    const auto n = static_cast<double>(s.inside);
    s.mean = sum.value() / n;
    s.rmse = std::sqrt(squares.value() / n);
    s.mean_abs = absolute.value() / n;
    if (s.inside > 1) {
        detail::CompensatedSum deviations;
        for (const CheckResult& c : results) {
            if (c.inside) {
                deviations.add((c.residual - s.mean) * (c.residual - s.mean));
            }
        }
        s.std_dev = std::sqrt(deviations.value() / (n - 1.0));
    }
    s.nssda_95 = 1.96 * s.rmse;
    std::sort(abs_values.begin(), abs_values.end());
    s.p50 = percentile_sorted(abs_values, 50.0);
    s.p68 = percentile_sorted(abs_values, 68.27);
    s.p90 = percentile_sorted(abs_values, 90.0);
    s.p95 = percentile_sorted(abs_values, 95.0);
    s.p99 = percentile_sorted(abs_values, 99.0);
    return s;
}

}  // namespace dtm
