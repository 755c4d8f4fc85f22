// SPDX-License-Identifier: MIT
// The grids a DEM is computed on: snapped outwards to whole cells, or fitted to a given extent.
#include "dtm/core/grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace dtm {

GridSpec snapped_grid_spec(const Box2& box, double cell) {
    GridSpec spec;
    spec.cell = cell;
    // Multiples of the cell size, moved out by one more cell if rounding put them inside the box.
    spec.xmin = std::floor(box.xmin / cell) * cell;
    spec.ymax = std::ceil(box.ymax / cell) * cell;
    if (spec.xmin > box.xmin) {
        spec.xmin -= cell;
    }
    if (spec.ymax < box.ymax) {
        spec.ymax += cell;
    }
    const auto count = [cell](double from, double to) {  // whole cells covering [from, to]
        auto n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil((to - from) / cell)));
        while (from + static_cast<double>(n) * cell < to) {
            ++n;
        }
        return n;
    };
    spec.cols = count(spec.xmin, box.xmax);
    spec.rows = count(box.ymin, spec.ymax);
    while (spec.ymin() > box.ymin) {
        ++spec.rows;
    }
    return spec;
}

GridSpec extent_grid_spec(const Box2& extent, double cell) {
    GridSpec spec;
    spec.cell = cell;
    spec.xmin = extent.xmin;
    spec.ymax = extent.ymax;
    const auto whole = [cell](double length) {
        const double n = length / cell;
        const double r = std::round(n);
        return static_cast<std::size_t>(
            std::max(1.0, std::abs(n - r) < 1e-9 * std::max(1.0, n) ? r : std::ceil(n)));
    };
    spec.cols = whole(extent.xmax - extent.xmin);
    spec.rows = whole(extent.ymax - extent.ymin);
    return spec;
}

}  // namespace dtm
