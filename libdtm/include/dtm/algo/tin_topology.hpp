// SPDX-License-Identifier: MIT
/// @file
/// @brief The rings of a Tin's border (the outline of the surface: outer boundaries and holes);
/// neighbour links are dtm::link_neighbours (core/tin.hpp).
#pragma once

#include <string>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// The border of the TIN (edges without a neighbour) chained into closed rings, each listing its
/// vertices once, with the surface on the left: outer boundaries counter-clockwise, holes
/// clockwise. Where the border touches itself at a vertex the rings are separated there.
/// @pre neighbour links are set
[[nodiscard]] std::vector<std::vector<VertexIndex>> border_rings(const Tin& tin);

/// Signed area of a closed ring (counter-clockwise positive), coordinates taken relative to its
/// first point.
template <class P>
[[nodiscard]] double ring_area(const std::vector<P>& ring) {
    double twice = 0.0;
    for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
        twice += (ring[i].x - ring[0].x) * (ring[i + 1].y - ring[0].y) -
                 (ring[i].y - ring[0].y) * (ring[i + 1].x - ring[0].x);
    }
    return 0.5 * twice;
}

}  // namespace dtm
