// SPDX-License-Identifier: MIT
/// @file
/// @brief What the triangulator takes: survey points, breaklines, boundary and holes.
#pragma once

#include <string>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm {

/// A polyline. Closed rings repeat the first vertex at the end, or set closed = true.
struct Polyline {
    std::vector<Point3> points;
    bool closed = false;
    std::string source;  ///< "file:line" or "file:feature N", for messages; may be empty
};

/// The whole input of one triangulation, in one planar CRS.
struct TerrainInput {
    std::vector<Point3> points;             ///< survey points (x, y, z)
    std::vector<Polyline> breaklines;       ///< hard 3-D breaklines: vertices become TIN vertices
    std::vector<Polyline> soft_breaklines;  ///< 2-D: segments become edges, z from the surface
    std::vector<Polyline> boundaries;       ///< closed outer boundaries: outside is removed
    std::vector<Polyline> holes;            ///< closed rings whose inside is removed
    std::vector<Point2> hole_seeds;         ///< Triangle-style hole seeds inside constrained rings
};

}  // namespace dtm
