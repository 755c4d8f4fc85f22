// SPDX-License-Identifier: MIT
/// @file
/// @brief Synthetic raster DEMs (cells at their centres, row by row from the south) and the
/// independent check of a TIN against every cell: each triangle's cells by bounding box,
/// barycentric coordinates, the linear height (no dtm point location).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::test {

struct Dem {
    int cols = 0;
    int rows = 0;
    double x0 = 0.0;
    double y0 = 0.0;
    double cell = 1.0;
    std::vector<dtm::Point3> cells;  ///< row by row
};

inline Dem make_dem(int cols, int rows, const std::function<double(double, double)>& f) {
    Dem d;
    d.cols = cols;
    d.rows = rows;
    d.x0 = -750'000.0;
    d.y0 = -1'050'000.0;
    d.cell = 2.0;
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < cols; ++i) {
            const double x = i * d.cell;
            const double y = j * d.cell;
            d.cells.push_back({d.x0 + x, d.y0 + y, f(x, y)});
        }
    }
    return d;
}

/// Largest |TIN - cell| over every cell, from the TIN's triangles alone: each triangle's
/// bounding box of cells, barycentric coordinates, the linear height. Cells on no triangle: inf.
inline double worst_cell_error(const dtm::Tin& tin, const Dem& dem) {
    std::vector<double> error(dem.cells.size(), std::numeric_limits<double>::infinity());
    for (const dtm::Triangle& t : tin.triangles) {
        const dtm::Point3& a = tin.vertices[t.v[0]];
        const dtm::Point3& b = tin.vertices[t.v[1]];
        const dtm::Point3& c = tin.vertices[t.v[2]];
        const auto col = [&](double x) { return (x - dem.x0) / dem.cell; };
        const auto row = [&](double y) { return (y - dem.y0) / dem.cell; };
        const int i0 =
            std::max(0, static_cast<int>(std::floor(std::min({col(a.x), col(b.x), col(c.x)}))));
        const int i1 = std::min(
            dem.cols - 1, static_cast<int>(std::ceil(std::max({col(a.x), col(b.x), col(c.x)}))));
        const int j0 =
            std::max(0, static_cast<int>(std::floor(std::min({row(a.y), row(b.y), row(c.y)}))));
        const int j1 = std::min(
            dem.rows - 1, static_cast<int>(std::ceil(std::max({row(a.y), row(b.y), row(c.y)}))));
        const double d = (b.y - c.y) * (a.x - c.x) + (c.x - b.x) * (a.y - c.y);
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                const std::size_t k = static_cast<std::size_t>(j) * dem.cols + i;
                const dtm::Point3& p = dem.cells[k];
                const double l1 = ((b.y - c.y) * (p.x - c.x) + (c.x - b.x) * (p.y - c.y)) / d;
                const double l2 = ((c.y - a.y) * (p.x - c.x) + (a.x - c.x) * (p.y - c.y)) / d;
                const double l3 = 1.0 - l1 - l2;
                if (std::min({l1, l2, l3}) < -1e-9) continue;
                const double e = std::abs(l1 * a.z + l2 * b.z + l3 * c.z - p.z);
                error[k] = std::isinf(error[k]) ? e : std::max(error[k], e);
            }
        }
    }
    return *std::max_element(error.begin(), error.end());
}

/// The DEM as an ESRI ASCII grid (rows from the north, lower-left corner half a cell off the
/// first centre, heights to 1e-6).
inline std::string ascii_grid(const Dem& d) {
    std::string out = "ncols " + std::to_string(d.cols) + "\nnrows " + std::to_string(d.rows) +
                      "\nxllcorner " + std::to_string(d.x0 - d.cell / 2.0) + "\nyllcorner " +
                      std::to_string(d.y0 - d.cell / 2.0) + "\ncellsize " + std::to_string(d.cell) +
                      "\nNODATA_value -9999\n";
    for (int j = d.rows - 1; j >= 0; --j) {
        for (int i = 0; i < d.cols; ++i) {
            char z[32];
            std::snprintf(z, sizeof z, "%.6f ",
                          d.cells[static_cast<std::size_t>(j) * d.cols + i].z);
            out += z;
        }
        out += "\n";
    }
    return out;
}

}  // namespace dtm::test
