// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: corner-cutting smoothing of a contour piece, constrained to its triangle strip.
#pragma once

#include <utility>
#include <vector>

#include "algo/detail/contour_trace.hpp"

namespace dtm::detail {

/// Chaikin corner cutting (@p iterations passes) of @p piece. A corner is cut only where the
/// triangle it spans (previous, corner, next point) lies inside the two TIN triangles meeting
/// at the corner and the surface height there stays strictly inside @p band (the half-way
/// heights to the neighbouring levels); other corners stay fixed. Every smoothed point therefore
/// lies in the triangle strip of the piece, and smoothed lines of different levels occupy
/// disjoint height bands of the surface, so they cannot cross.
[[nodiscard]] std::vector<Point3> smooth_chain(const Tin& tin,
                                               const RawChain& piece,
                                               std::pair<double, double> band,
                                               unsigned iterations);

}  // namespace dtm::detail
