// SPDX-License-Identifier: MIT
/// @file
/// @brief Cross-sections along an alignment: the section lines at a station interval, the cut and
/// fill areas between two surfaces on a section (exact for the two piecewise-linear profiles),
/// the average-end-area volumes between stations, and the exact volume of every slab between two
/// sections for comparison.
#pragma once

#include <span>
#include <vector>

#include "dtm/algo/difference_surface.hpp"
#include "dtm/algo/profile.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct SectionOptions {
    double interval = 20.0;   ///< distance between stations along the alignment (> 0)
    double width = 40.0;      ///< total width: width / 2 to the left and to the right
    bool include_end = true;  ///< a last section at the alignment's end
};

/// One cross-section line, perpendicular to the alignment, from left to right (facing along the
/// alignment), through the alignment at station `station`.
struct SectionLine {
    double station = 0.0;
    Point2 centre;
    Point2 left;
    Point2 right;
};

/// The section lines at stations 0, interval, 2 interval, ... (and the end). At a vertex of the
/// alignment the section is perpendicular to the bisector of the two segments.
/// @throws UsageError for interval or width <= 0, an alignment shorter than its first segment.
[[nodiscard]] std::vector<SectionLine> section_lines(std::span<const Point3> alignment,
                                                     const SectionOptions& options);

/// Cut and fill areas of one section: top above base is fill, below is cut (the integral of the
/// positive / negative part of top - base along the section, exact for the piecewise-linear
/// profiles); `width` is where both surfaces exist.
struct SectionAreas {
    double fill = 0.0;
    double cut = 0.0;
    double width = 0.0;
};
[[nodiscard]] SectionAreas section_areas(const Profile& top, const Profile& base);

/// Cut and fill volume of each slab between consecutive sections (slab k between lines k and
/// k + 1), exact: the difference surface overlaid with a triangulation of the slabs (the corridor
/// swept by the sections, the section lines as constraints), each piece integrated in closed form.
struct SlabVolume {
    double fill = 0.0;
    double cut = 0.0;
    double area = 0.0;  ///< plan area of the slab where both surfaces exist
};
[[nodiscard]] std::vector<SlabVolume> slab_volumes(const DifferenceSurface& difference,
                                                   std::span<const SectionLine> sections,
                                                   const Progress& progress = {});

}  // namespace dtm
