// SPDX-License-Identifier: MIT
/// @file
/// @brief The TIN's constrained edges chained back into polylines, one kind at a time
/// (breaklines, soft breaklines, boundaries, holes): for drawing and for line layers.
#pragma once

#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct ConstraintLine {
    ConstraintKind kind = ConstraintKind::breakline;
    std::vector<Point3> points;  ///< a closed ring repeats its first point last
    bool closed = false;
};

/// Chains the constrained edges of @p tin of each kind into maximal polylines: a line runs
/// through vertices where exactly two edges of its kind meet and ends elsewhere (line ends,
/// junctions). Cycles come out as closed rings. Every edge is in exactly one line; the order
/// is deterministic (kinds in enum order, then by the smallest vertex index).
[[nodiscard]] std::vector<ConstraintLine> constraint_lines(const Tin& tin);

}  // namespace dtm
