// SPDX-License-Identifier: MIT
/// @file
/// @brief A north-up raster (DEM) value type: geometry of the cells, plus a Float32 value array.
///
///   (xmin, ymax) +-----+-----+-----+       row 0 is the northern row, col 0 the western column;
///                | 0,0 | 0,1 | 0,2 |       cell (r, c) covers [xmin + c*cell, xmin + (c+1)*cell] x
///                +-----+-----+-----+       [ymax - (r+1)*cell, ymax - r*cell] and is sampled at
///                its | 1,0 |  x  | 1,2 |       centre x (GDAL's "pixel is area" convention: the
///                extent
///                +-----+-----+-----+       is the raster's outer edges).
///                                 (xmax, ymin)
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm {

/// Placement and size of a north-up raster with square cells.
struct GridSpec {
    double xmin = 0.0;     ///< western outer edge
    double ymax = 0.0;     ///< northern outer edge
    double cell = 1.0;     ///< cell size in CRS units (> 0)
    std::size_t cols = 0;  ///< number of columns (x)
    std::size_t rows = 0;  ///< number of rows (y, north to south)

    [[nodiscard]] double xmax() const noexcept { return xmin + static_cast<double>(cols) * cell; }
    [[nodiscard]] double ymin() const noexcept { return ymax - static_cast<double>(rows) * cell; }
    /// x of the centre of column @p col.
    [[nodiscard]] double center_x(std::size_t col) const noexcept {
        return xmin + (static_cast<double>(col) + 0.5) * cell;
    }
    /// y of the centre of row @p row.
    [[nodiscard]] double center_y(std::size_t row) const noexcept {
        return ymax - (static_cast<double>(row) + 0.5) * cell;
    }
    [[nodiscard]] std::size_t cell_count() const noexcept { return cols * rows; }
    friend bool operator==(const GridSpec&, const GridSpec&) = default;
};

/// A DEM in memory: spec.rows x spec.cols Float32 values, row-major from the north-west corner.
struct Grid {
    GridSpec spec;
    float nodata = -9999.0F;
    std::vector<float> values;  ///< size spec.cell_count()

    [[nodiscard]] float at(std::size_t row, std::size_t col) const {
        return values[row * spec.cols + col];
    }
    [[nodiscard]] bool is_nodata(std::size_t row, std::size_t col) const {
        const float v = at(row, col);
        return v == nodata || (std::isnan(v) && std::isnan(nodata));
    }
};

/// The grid covering @p box with cells of size @p cell, its edges snapped outwards to multiples
/// of @p cell (at least one cell in each direction). @pre cell > 0, !box.empty()
[[nodiscard]] GridSpec snapped_grid_spec(const Box2& box, double cell);

/// The grid whose outer edges are the given extent. When the extent is not a whole number of
/// cells, the eastern and southern edges move outwards to the next whole cell.
/// @pre cell > 0, xmax > xmin, ymax > ymin
[[nodiscard]] GridSpec extent_grid_spec(const Box2& extent, double cell);

}  // namespace dtm
