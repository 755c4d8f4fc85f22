// SPDX-License-Identifier: MIT
// Tin helpers: constraint kind names, half-edge twins, and neighbour links rebuilt from the
// triangles. link_neighbours lists every directed edge (counting sort) under the smaller of its
// two vertices, so an edge and its twin land in the same short row: both the duplicate check and
// the twin search scan that one contiguous row, with no jump to the other vertex's row (which is
// what costs on large TINs, whose vertex numbering follows the survey, not the space).
#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

const char* constraint_kind_name(ConstraintKind kind) noexcept
{
    switch (kind) {
    case ConstraintKind::breakline: return "breakline";
    case ConstraintKind::soft_breakline: return "soft breakline";
    case ConstraintKind::boundary: return "boundary";
    case ConstraintKind::hole: return "hole";
    }
    return "breakline";
}

HalfEdge twin(const Tin& tin, HalfEdge e)
{
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

void link_neighbours(Tin& tin)
{
    const std::size_t n = tin.vertices.size();
    if (tin.triangles.size() > std::numeric_limits<std::uint32_t>::max() / 3) {
        throw InputError("too many faces");
    }
    struct Listed {
        VertexIndex other;       ///< the larger vertex of the edge
        TriangleIndex triangle;  ///< the edge is HalfEdge{triangle, side}
        std::uint8_t side;
        bool forward;  ///< the edge runs from the row's vertex to `other`
    };
    std::vector<std::uint32_t> first(n + 1, 0);
    for (const Triangle& t : tin.triangles) {
        for (unsigned i = 0; i < 3; ++i) ++first[std::min(t.v[(i + 1) % 3], t.v[(i + 2) % 3]) + 1];
    }
    for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    std::vector<Listed> rows(first[n]);
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        Triangle& tri = tin.triangles[t];
        tri.n = {no_triangle, no_triangle, no_triangle};
        for (std::uint8_t i = 0; i < 3; ++i) {
            const VertexIndex a = tri.v[(i + 1U) % 3U];
            const VertexIndex b = tri.v[(i + 2U) % 3U];
            rows[fill[std::min(a, b)]++] = {std::max(a, b), static_cast<TriangleIndex>(t), i, a < b};
        }
    }
    for (std::size_t a = 0; a < n; ++a) {
        for (std::uint32_t k = first[a]; k < first[a + 1]; ++k) {
            for (std::uint32_t j = k + 1; j < first[a + 1]; ++j) {
                if (rows[j].other != rows[k].other) continue;
                if (rows[j].forward == rows[k].forward) {
                    const std::size_t from = rows[k].forward ? a : rows[k].other;
                    const std::size_t to = rows[k].forward ? rows[k].other : a;
                    throw InputError("edge " + std::to_string(from) + "-" + std::to_string(to) +
                                     " is used twice in the same direction (faces overlap or are "
                                     "not consistently oriented)");
                }
                tin.triangles[rows[k].triangle].n[rows[k].side] = rows[j].triangle;
                tin.triangles[rows[j].triangle].n[rows[j].side] = rows[k].triangle;
            }
        }
    }
}

}  // namespace dtm
