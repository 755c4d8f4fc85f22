// SPDX-License-Identifier: MIT
/// @file
/// @brief Raster DEM cells combined with a survey: cells near the survey dropped
/// (`dem.clip_radius`), and the cells thinned to the few a TIN needs to stay within a given
/// height error of every cell (`dem.max_error`; greedy insertion after Garland and Heckbert,
/// breaklines respected). docs/algorithms/dem_reduce.md.
#pragma once

#include <cstddef>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"

namespace dtm {

struct DemReduceOptions {
    /// Cells whose centre lies within this distance (CRS units) of a survey point or of a hard or
    /// soft breakline are dropped: the survey describes the ground there. 0: none dropped.
    double clip_radius = 0.0;
    /// Keep only the cells needed for the TIN to be within this height of every (unclipped)
    /// cell. 0: every cell is kept.
    double max_error = 0.0;
    /// Refinement passes at most; each pass inserts the worst cell of every triangle still in
    /// error, so the count roughly doubles per pass and 64 is never reached in practice.
    std::size_t max_passes = 64;
};

struct DemReduceReport {
    std::size_t cells = 0;     ///< DEM cells given
    std::size_t clipped = 0;   ///< dropped by clip_radius
    std::size_t kept = 0;      ///< cells that became TIN input points
    std::size_t vertices = 0;  ///< vertices of the final TIN (with the survey's)
    std::size_t passes = 0;    ///< triangulations run (max_error)
    /// Height error of the final TIN over the unclipped cells on it: largest and root mean square.
    double max_error = 0.0;
    double rms_error = 0.0;
    std::size_t measured = 0;  ///< cells the errors were taken over
    std::size_t outside = 0;   ///< unclipped cells on no triangle (outside a boundary, in a hole)
    /// Cells still above max_error although kept: a survey point at the same position (or
    /// within the snap distance) gave the vertex its height.
    std::size_t over_error = 0;
};

struct DemReduceResult {
    /// The input of the final TIN: the survey (points, lines, rings as given), then the kept
    /// cells in their given order.
    TerrainInput terrain;
    std::vector<std::size_t> kept;  ///< indices into the given cells of the kept ones, ascending
    /// The final TIN when max_error was given (the triangulation of terrain with the given
    /// options); otherwise not run (empty TIN, no triangles).
    TriangulateResult triangulation;
    bool triangulated = false;
    DemReduceReport report;
};

/// Drops and thins @p cells against @p survey. With max_error: starts from the cells on the convex
/// hull of all cells and, pass by pass, triangulates survey + chosen cells (triangulate() with
/// @p triangulate, so breaklines, boundaries and holes hold), measures every cell against the TIN
/// and adds the worst cell of each triangle whose error exceeds max_error, until none does.
/// @throws OptionError for a negative or non-finite `dem.clip_radius` or `dem.max_error`;
/// InputError from triangulate(); Cancelled
[[nodiscard]] DemReduceResult reduce_dem(TerrainInput survey,
                                         const std::vector<Point3>& cells,
                                         const DemReduceOptions& options,
                                         const TriangulateOptions& triangulate,
                                         const Progress& progress = {});

}  // namespace dtm
