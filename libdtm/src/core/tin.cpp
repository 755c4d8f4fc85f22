// SPDX-License-Identifier: MIT
// Tin helpers: constraint kind names and half-edge twins (neighbour links rebuilt from the
// triangles: tin_links.cpp).
#include "dtm/core/tin.hpp"

#include <cstdint>

namespace dtm {

const char* constraint_kind_name(ConstraintKind kind) noexcept {
    switch (kind) {
        case ConstraintKind::breakline:
            return "breakline";
        case ConstraintKind::soft_breakline:
            return "soft breakline";
        case ConstraintKind::boundary:
            return "boundary";
        case ConstraintKind::hole:
            return "hole";
    }
    return "breakline";
}

HalfEdge twin(const Tin& tin, HalfEdge e) {
    const TriangleIndex across = tin.triangles[e.triangle].n[e.side];
    if (across == no_triangle) return {};
    const Triangle& other = tin.triangles[across];
    for (std::uint8_t s = 0; s < 3; ++s) {
        if (other.n[s] == e.triangle && other.v[(s + 1U) % 3U] == destination(tin, e)) {
            return {across, s};
        }
    }
    return {};
}

}  // namespace dtm
