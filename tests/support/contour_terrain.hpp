// SPDX-License-Identifier: MIT
/// @file
/// @brief Test fixture: contour lines of an analytic terrain (two summits, a spur, a valley),
/// traced by dtm on a fine TIN of the terrain and thinned to a few metres between vertices like
/// a digitised contour map; the truth is the terrain function.
#pragma once

#include <cmath>
#include <vector>

#include "dtm/algo/contour.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/terrain.hpp"

namespace dtm::test {

inline double contour_terrain_z(double x, double y) {
    return 200.0 + 40.0 * std::exp(-((x - 30) * (x - 30) + (y - 62) * (y - 62)) / 420.0) +
           26.0 * std::exp(-((x - 72) * (x - 72) + (y - 34) * (y - 34)) / 260.0) + 0.12 * y +
           3.0 * std::sin(x / 9.0);
}

/// Contours of contour_terrain_z over [0, size]^2 every @p interval as breaklines (one height
/// per line), vertices about @p spacing apart.
inline TerrainInput contour_terrain_input(double interval = 5.0,
                                          double spacing = 2.0,
                                          double size = 100.0) {
    TerrainInput fine;
    const int n = 201;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            // a slightly jittered lattice, so that the fine TIN is not degenerate
            const double x = size * i / (n - 1) + (i % 2 == 0 ? 0.0 : 1e-3 * ((j * 7) % 5));
            const double y = size * j / (n - 1) + (j % 2 == 0 ? 0.0 : 1e-3 * ((i * 3) % 5));
            fine.points.push_back({x, y, contour_terrain_z(x, y)});
        }
    }
    const Tin tin = triangulate(fine).tin;
    ContourOptions options;
    options.interval = interval;
    TerrainInput out;
    for (const Contour& c : contour(tin, options)) {
        Polyline line;
        double since = spacing;
        for (std::size_t i = 0; i < c.line.size(); ++i) {
            const bool last = i + 1 == c.line.size();
            if (i > 0) {
                since += std::hypot(c.line[i].x - c.line[i - 1].x, c.line[i].y - c.line[i - 1].y);
            }
            if (since >= spacing || last) {
                line.points.push_back(c.line[i]);
                since = 0.0;
            }
        }
        if (c.closed && line.points.size() >= 4) {
            line.closed = true;
        } else if (c.closed) {
            continue;  // a ring too small to keep
        }
        if (line.points.size() >= 2) {
            out.breaklines.push_back(std::move(line));
        }
    }
    return out;
}

}  // namespace dtm::test
