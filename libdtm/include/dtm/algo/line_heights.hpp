// SPDX-License-Identifier: MIT
/// @file
/// @brief Heights for the vertices of lines given without them (2-D breaklines, boundaries,
/// holes, soft breaklines): triangulate() calls it first, so a library user who passes 2-D rings
/// gets what `dtm` gives; callers may also run it on its own.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>

#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"

namespace dtm {

struct LineHeightOptions {
    /// Worker threads and tiles of the surface triangulation for the rings (0: automatic); they
    /// never change the result.
    unsigned threads = 0;
    std::size_t tiles = 0;
};

/// What resolve_line_heights() did.
struct LineHeightReport {
    std::size_t from_points = 0;   ///< vertices that took the z of a survey point at their xy
    std::size_t from_surface = 0;  ///< boundary and hole vertices that took the surface height
};

/// Gives every line vertex whose z is NaN a height:
/// 1. the z of a survey point at exactly the same x, y (any kind of line);
/// 2. boundary and hole vertices still without: the height of the surface of the survey points
///    and hard breaklines (their constrained Delaunay TIN, built without the rings), linear on
///    its triangles, the nearest vertex's beyond its hull (SurfaceSampler);
/// 3. soft breakline vertices still without keep NaN: triangulate() interpolates them on the
///    surface of everything else.
/// @throws InputError a hard breakline vertex is left without a height (naming the line's
/// source and the vertex), or rings need the surface and there are fewer than 3 survey points;
/// Cancelled.
LineHeightReport resolve_line_heights(TerrainInput& input,
                                      const LineHeightOptions& options = {},
                                      const Progress& progress = {});

/// The z of the first survey point (in input order) at exactly a position, if any.
using SurveyHeightAt = std::function<std::optional<double>(const Point2&)>;

/// Step 1 of resolve_line_heights() alone, the survey points' heights given by @p height_at
/// (a distributed run looks them up over all ranks): fills the NaN z of the lines' vertices
/// that lie on a survey point. @return the vertices filled. @throws InputError as
/// resolve_line_heights() for a hard breakline vertex left without a height.
std::size_t heights_from_survey_points(TerrainInput& lines, const SurveyHeightAt& height_at);

}  // namespace dtm
