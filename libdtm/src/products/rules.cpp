// SPDX-License-Identifier: MIT
// The default DEM cell and contour interval (see rules.hpp; docs/products.md states them).
#include "dtm/products/rules.hpp"

#include <algorithm>
#include <cmath>

namespace dtm::products {

double nice_floor(double value) {
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    const double mantissa = value / power;
    for (const double step : {5.0, 2.5, 2.0}) {
        if (mantissa >= step) return step * power;
    }
    return power;
}

double nice_next(double value) {
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    for (const double step : {2.0, 2.5, 5.0, 10.0}) {
        if (step * power > value * (1.0 + 1e-12)) return step * power;
    }
    return 10.0 * power;
}

double default_cell(const SurfaceStats& surface) {
    const double spacing =
        std::sqrt(surface.planimetric_area /
                  static_cast<double>(std::max<std::size_t>(surface.vertex_count, 1)));
    double cell = nice_floor(std::max(spacing / 2.0, 1e-3));
    const double width = surface.extent.xmax - surface.extent.xmin;
    const double height = surface.extent.ymax - surface.extent.ymin;
    while ((width / cell + 1.0) * (height / cell + 1.0) > 50e6) cell = nice_next(cell);
    return cell;
}

double default_interval(const SurfaceStats& surface) {
    const double range = surface.z_max - surface.z_min;
    return range > 0.0 ? nice_floor(range / 20.0) : 1.0;
}

}  // namespace dtm::products
