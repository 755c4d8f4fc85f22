// SPDX-License-Identifier: MIT
/// @file
/// @brief The planar straight-line graph pre-pass: constraint segments split at their crossings,
/// T-junctions and overlaps before triangulation, so that the segments the insertion gets touch
/// one another at shared endpoints only.
#pragma once

#include <vector>

#include "algo/detail/input_merge.hpp"
#include "algo/detail/mesh_edit.hpp"

namespace dtm::detail {

struct SegmentSplit {
    std::vector<Crossing> crossings;  ///< one per crossing pair, in pair order
    /// No two segments touch except at shared endpoints (false only when the rounds ran out; the
    /// insertion then handles the rest one by one).
    bool all_free = true;
};

/// Splits in.segments (merged vertex ids) in place and appends the crossing vertices to
/// in.vertices and in.z_known, numbered by their smallest crossing pair of segment indices.
/// A crossing vertex takes the mean of the two lines' heights, or the hard line's when the other
/// is soft (unknown, to interpolate like a soft vertex, when both are soft); a vertex of unknown
/// height on a non-soft segment takes the segment's height there. Equal segments become one, their
/// ConstraintBits or-ed.
[[nodiscard]] SegmentSplit split_segments(MergedInput& in, double z_tolerance);

}  // namespace dtm::detail
