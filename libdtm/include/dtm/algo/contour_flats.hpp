// SPDX-License-Identifier: MIT
/// @file
/// @brief Terrain from contour lines without the terracing: flat triangles that are not real
/// flats are removed by points on the skeleton of each flat region.
#pragma once

#include <cstddef>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct ContourFlatsOptions {
    /// Breaklines (indices into TerrainInput::breaklines) that outline real flats, such as lake
    /// shores: flat regions touching them stay flat.
    std::vector<std::size_t> flat_outlines{};
    /// Estimate a summit (or pit) inside a closed contour that encloses no point: half a
    /// contour interval above (below) its level at the middle of the enclosed area. When
    /// false, such areas stay flat.
    bool estimate_summits = true;
    /// Rounds of "find flat regions, add skeleton points, triangulate again" at most.
    unsigned max_rounds = 2;
    TriangulateOptions triangulate{};
};

/// A summit or pit estimated inside a closed contour that held no point.
struct EstimatedPeak {
    Point3 at;             ///< the estimate, at the middle of the enclosed area
    double contour = 0.0;  ///< the level of the enclosing contour
    bool summit = true;    ///< false for a pit
};

struct ContourFlatsReport {
    std::size_t contour_lines = 0;     ///< hard breaklines with one height (the contours)
    std::size_t triangles_before = 0;  ///< triangles of the TIN of the input as given
    std::size_t flat_before = 0;       ///< of them flat (three vertices at one height)
    std::size_t triangles_after = 0;
    std::size_t flat_after = 0;
    std::size_t regions = 0;     ///< connected flat regions found (first round)
    std::size_t true_flats = 0;  ///< of them kept flat (a spot height at their level, or a
                                 ///< flat outline)
    std::size_t unresolved = 0;  ///< enclosed regions with no neighbouring level to go to
    std::size_t points_added = 0;
    unsigned rounds = 0;
    std::vector<EstimatedPeak> peaks;  ///< summits and pits estimated (flag them on maps)
};

struct ContourFlatsResult {
    TriangulateResult triangulation;  ///< of the input plus the added points
    std::vector<Point3> added;        ///< the added points (appended to the input's points)
    ContourFlatsReport report;
};

/// Triangulates @p input whose hard breaklines are contour lines (one height per line) and
/// removes the flat triangles that are artefacts of the contours: where a contour bends back on
/// itself (a spur, a valley head) or closes around a summit, the Delaunay triangles join points
/// of one line and lie flat. Each connected region of flat triangles (joined through edges that
/// are not breaklines) gets points on its skeleton, the midpoints of its inner edges (which
/// join the two banks of the region, so their midpoints lie on the region's medial axis). Their
/// band of heights lies between the region's level z0 and the neighbouring level z1 found where
/// the region opens onto other ground (a summit or pit, enclosed by its contour: z0 and half an
/// interval beyond, by the levels outside it). The height is the smooth (cubic) surface of the
/// contour TIN there, kept strictly inside the band; where it has none, the skeleton estimate
///     z = z0 + (z1 - z0) d0 / (d0 + d1),
/// d0 the distance to the contour (half the edge), d1 the distance along the skeleton to the
/// opening plus from there to the neighbouring level's vertex. So every new height lies strictly
/// between the neighbouring levels. Summits and pits are reported. Real flats stay: regions with
/// a spot height (a survey point) at their level, and regions touching options.flat_outlines.
/// Then the TIN is built again with the new points.
/// @throws InputError, Cancelled (as triangulate())
[[nodiscard]] ContourFlatsResult triangulate_contours(const TerrainInput& input,
                                                      const ContourFlatsOptions& options = {},
                                                      const Progress& progress = {});

/// Triangles whose three vertices have the same height.
[[nodiscard]] std::size_t count_flat_triangles(const Tin& tin);

}  // namespace dtm
