// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: a TIN copy with its vertices renumbered in first-use order, for the
/// cache-friendly sweeps of rasterisation and contouring.
#pragma once

#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// Triangles come in a spatially coherent order but vertices keep the input order (often
/// random), so reading the corners of each triangle costs three cache misses. After this one
/// renumbering pass the reads follow the triangles through memory. Neighbour links and the
/// triangle order are unchanged; constraints are not copied.
[[nodiscard]] inline Tin with_coherent_vertices(const Tin& tin) {
    Tin out;
    out.triangles = tin.triangles;
    out.vertices.reserve(tin.vertices.size());
    std::vector<VertexIndex> renumber(tin.vertices.size(), no_vertex);
    for (Triangle& t : out.triangles) {
        for (VertexIndex& v : t.v) {
            VertexIndex& to = renumber[v];
            if (to == no_vertex) {
                to = static_cast<VertexIndex>(out.vertices.size());
                out.vertices.push_back(tin.vertices[v]);
            }
            v = to;
        }
    }
    return out;
}

}  // namespace dtm::detail
