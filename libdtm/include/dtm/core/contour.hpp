// SPDX-License-Identifier: MIT
/// @file
/// @brief A contour line: a polyline of 3-D points all at one elevation.
#pragma once

#include <cstddef>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm {

/// One contour level: its elevation, its number in the level sequence and whether it is an index
/// (thick, labelled) contour.
struct ContourLevel {
    double value = 0.0;
    long long number = 0;  ///< k in base + k * interval, or the position in a fixed list
    bool index = false;
};

/// A finished contour line. Every point has z == level.value. A closed ring repeats its first
/// point at the end. Higher ground is on the right when walking along the line.
struct Contour {
    ContourLevel level;
    std::vector<Point3> line;
    bool closed = false;
};

}  // namespace dtm
