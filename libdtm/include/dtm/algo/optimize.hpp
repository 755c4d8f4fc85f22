// SPDX-License-Identifier: MIT
/// @file
/// @brief Lawson's local optimisation of a TIN under a criterion (criteria.hpp): flip edges whose
/// convex quadrilateral the criterion triangulates better, never a constrained edge, until none
/// is left. Applied after triangulate() by `dtm tin/grid/contour/build --optimize`.
#pragma once

#include <cstdint>

#include "dtm/algo/criteria.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct OptimizeOptions {
    Criterion criterion = Criterion::delaunay;
    /// Threads for the initial scan (0: all cores). The result never depends on it: the flips
    /// themselves run in one deterministic order.
    unsigned threads = 0;
    /// A second guard besides the termination argument (see optimize_tin): stop after this many
    /// flips (0: 50 per triangle plus 10^6) and report converged = false.
    std::uint64_t max_flips = 0;
};

struct OptimizeStats {
    Criterion criterion = Criterion::delaunay;
    std::uint64_t flips = 0;
    std::uint64_t edges_tested = 0;     ///< criterion evaluations
    std::size_t improvable_before = 0;  ///< edges a flip would improve at the start
    std::size_t improvable_after = 0;   ///< 0 when converged
    bool converged = true;              ///< false if max_flips stopped it
    QualitySummary before;              ///< of quality_vector() before the flips
    QualitySummary after;
    double seconds = 0.0;
};

/// Optimises @p tin in place under options.criterion (delaunay: nothing to do).
///
/// Termination: every flip strictly improves a global measure over the finitely many
/// triangulations with the same constraints, so no triangulation can repeat: the sorted vector of
/// per-triangle values (max-min criteria: lexicographically larger; min-max: smaller), the sorted
/// vector of edge lengths (shortest-diagonal), the exact sum of the computed edge costs
/// (data-dependent), or the lifted-paraboloid volume (maxmin-angle = Delaunay flips). The flip
/// budget (OptimizeOptions::max_flips) is a second guard against pathological inputs.
///
/// Determinism: edges are queued in triangle order and processed first in, first out; the same
/// input gives the same output for every thread count. The vertices, their order and the
/// constraints do not change; triangles keep their slots and stay counter-clockwise.
/// @throws Cancelled when @p progress asks to stop.
OptimizeStats optimize_tin(Tin& tin,
                           const OptimizeOptions& options = {},
                           const Progress& progress = {});

}  // namespace dtm
