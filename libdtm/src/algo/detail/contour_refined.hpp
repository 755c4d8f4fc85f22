// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: contour tracing shared by the linear and the smooth surfaces.
#pragma once

#include <vector>

#include "dtm/algo/contour.hpp"

namespace dtm::detail {

class EdgeCrossing;

/// Traces @p levels exactly on the triangles of @p tin (the linear surface) into @p sink;
/// @p edge_crossing, when given, places the points on the edges.
void trace_contour_levels(const Tin& tin,
                          const std::vector<ContourLevel>& levels,
                          const ContourOptions& options,
                          ContourSink& sink,
                          const Progress& progress,
                          const EdgeCrossing* edge_crossing = nullptr);

/// The same for the levels [first, last) of @p levels only (the smoothing band of a level is
/// the one of the whole list).
void trace_level_range(const Tin& tin,
                       const std::vector<ContourLevel>& levels,
                       std::size_t first,
                       std::size_t last,
                       const ContourOptions& options,
                       ContourSink& sink,
                       const Progress& progress,
                       const EdgeCrossing* edge_crossing = nullptr);

/// Contours of a cubic or natural-neighbour surface: traced on a refinement of the TIN whose
/// vertices lie on that surface (contour_refined.cpp).
void contour_refined(const Tin& tin,
                     const TinInterpolant& interpolant,
                     const ContourOptions& options,
                     ContourSink& sink,
                     const Progress& progress);

/// The refinement contour_refined() traces, of the triangles @p selected (ascending indices of
/// interpolant.surface(tin), the TIN the contours are traced on):
/// each cut into 3 m^2 pieces whose corners carry the surface's heights; the TIN's vertices
/// come first (unused ones included), neighbour links are complete inside the selection and
/// no_triangle towards unselected triangles. Exposed for tests.
[[nodiscard]] Tin refine_for_contours(const Tin& tin,
                                      const TinInterpolant& interpolant,
                                      const std::vector<TriangleIndex>& selected,
                                      unsigned subdivisions);

}  // namespace dtm::detail
