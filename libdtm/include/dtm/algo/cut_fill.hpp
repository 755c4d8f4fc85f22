// SPDX-License-Identifier: MIT
/// @file
/// @brief The cut/fill map of a difference surface: the regions where the top lies above (fill)
/// or below (cut) the base as polygons with holes, each with its area and volume, and the zero
/// lines where the two surfaces meet (3-D polylines on the top surface).
#pragma once

#include <vector>

#include "dtm/algo/difference_surface.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"

namespace dtm {

/// One connected region of fill or cut.
struct CutFillRegion {
    bool fill = true;  ///< true: top above base; false: cut
    /// rings[0] is the outer ring (counter-clockwise), the others are holes (clockwise); each ring
    /// is closed (its last point repeats the first).
    std::vector<std::vector<Point2>> rings;
    double area = 0.0;       ///< plan area
    double volume = 0.0;     ///< volume of fill or cut (positive)
    double max_depth = 0.0;  ///< largest |top - base| at a vertex of the region
};

/// A zero line: where the top surface meets the base inside the overlap (between cut and fill,
/// or around the area where the surfaces coincide), not along the overlap's outer edge.
struct ZeroLine {
    std::vector<Point3> points;  ///< x, y and the height of both surfaces there
    bool closed = false;         ///< a closed ring repeats its first point last
};

struct CutFillMap {
    std::vector<CutFillRegion> regions;
    std::vector<ZeroLine> zero_lines;
};

/// Traces the regions and zero lines of @p surface. Connectivity follows the TIN's topology
/// (regions that touch only at a point are separate); a zero line splits where three or more
/// meet. @throws Cancelled
[[nodiscard]] CutFillMap cut_fill_map(const DifferenceSurface& surface,
                                      const Progress& progress = {});

}  // namespace dtm
