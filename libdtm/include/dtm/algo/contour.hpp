// SPDX-License-Identifier: MIT
/// @file
/// @brief Contour lines traced exactly on the TIN (or on its cubic or natural-neighbour surface)
/// and streamed to a sink.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "dtm/algo/interpolation.hpp"
#include "dtm/core/contour.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct ContourOptions {
    double interval = 1.0;  ///< distance between levels (> 0) when fixed_levels is empty
    double base = 0.0;      ///< levels are base + k * interval
    std::vector<double> fixed_levels{};  ///< if non-empty, overrides interval/base
    std::size_t index_every = 5;         ///< every k-th level (k % index_every == 0) is an index
                                         ///< contour (0: none)
    std::size_t max_levels = 100'000;    ///< guard against absurd intervals
    /// Corner-cutting passes (0: none). Smoothed vertices stay inside the triangles the line
    /// crosses, so lines still never cross; smoothed vertices are not on TIN edges any more.
    unsigned smooth = 0;
    unsigned threads = 0;  ///< worker threads (0: all cores); never changes the result
    /// The surface the lines follow. linear: traced exactly on the TIN's triangles. cubic,
    /// natural: traced exactly on a fine linear sampling of that surface, each triangle cut
    /// into its three Clough-Tocher sub-triangles and each of those into subdivisions^2 pieces
    /// whose corners lie on the surface; the lines are smooth (and, being traced on one
    /// consistent triangulation, still continuous, closed where the surface's level set is
    /// closed, and never crossing). Ignored by the overload that takes a TinInterpolant.
    Interpolation surface = Interpolation::linear;
    unsigned subdivisions = 4;    ///< for cubic and natural (at least 1)
    GradientOptions gradients{};  ///< for cubic
};

/// Receives finished contour lines, level by level in increasing order, from one thread at a
/// time. Implemented by io writers, tests and samples.
class ContourSink {
public:
    virtual ~ContourSink() = default;
    /// @param line   points with z == level.value; a closed ring repeats its first point last
    /// @param closed true for a closed ring
    virtual void add(const ContourLevel& level, std::span<const Point3> line, bool closed) = 0;
};

/// The levels that cut the height range [zmin, zmax] (a level L cuts it when zmin < L <= zmax:
/// a vertex exactly on a level counts as slightly above it).
/// @throws UsageError for interval <= 0 or more than options.max_levels levels.
[[nodiscard]] std::vector<ContourLevel> contour_levels(double zmin,
                                                       double zmax,
                                                       const ContourOptions& options);

/// Traces every contour of @p tin and streams it to @p sink. Lines are continuous polylines
/// through the TIN; a vertex with z == level is treated as slightly above the level (no gaps, no
/// doubled pieces), the output point stays exactly on the vertex; zero-length parts are dropped.
/// @throws UsageError (see contour_levels); Cancelled
void contour(const Tin& tin,
             const ContourOptions& options,
             ContourSink& sink,
             const Progress& progress = {});

/// Same, on a prepared interpolant of @p tin (options.surface is ignored; a linear interpolant
/// traces the TIN itself). Memory: the refinement of the triangles crossed by a batch of
/// levels, a few million sub-triangles at most at a time.
void contour(const Tin& tin,
             const TinInterpolant& interpolant,
             const ContourOptions& options,
             ContourSink& sink,
             const Progress& progress = {});

/// Traces, on the linear surface of @p tin, the levels [first, last) of @p levels (as
/// contour_levels gives them for the whole surface) into @p sink, as contour() traces them:
/// lines of those levels only, in the same order and bits, provided @p tin holds every triangle
/// those levels cross, in the whole TIN's relative order, with the same corner order and vertex
/// order (a distributed run whose ranks trace disjoint level ranges). @throws Cancelled
void contour_level_range(const Tin& tin,
                         const std::vector<ContourLevel>& levels,
                         std::size_t first,
                         std::size_t last,
                         const ContourOptions& options,
                         ContourSink& sink,
                         const Progress& progress = {});

/// Convenience for small data: collect into memory.
[[nodiscard]] std::vector<Contour> contour(const Tin& tin,
                                           const ContourOptions& options = {},
                                           const Progress& progress = {});

}  // namespace dtm
