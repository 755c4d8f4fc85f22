// SPDX-License-Identifier: MIT
// Checks of a TIN read from a file: one exact orientation test per face, and one pass over the
// edges for the constrained edges (a hash set of the few constraints, not of all edges).
#include "tin_checks.hpp"

#include <cstdint>
#include <string>
#include <unordered_set>

#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::io::detail {
namespace {

std::uint64_t key(VertexIndex a, VertexIndex b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

}  // namespace

void check_tin_from_file(const Tin& tin) {
    const std::size_t nv = tin.vertices.size();
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        const Triangle& f = tin.triangles[t];
        if (f.v[0] >= nv || f.v[1] >= nv || f.v[2] >= nv) {
            throw InputError("face " + std::to_string(t) + " refers to a missing vertex");
        }
        if (geom::orient2d(tin.vertex(f.v[0]), tin.vertex(f.v[1]), tin.vertex(f.v[2])) <= 0) {
            throw InputError("face " + std::to_string(t) + " (vertices " + std::to_string(f.v[0]) +
                             ", " + std::to_string(f.v[1]) + ", " + std::to_string(f.v[2]) +
                             ") is clockwise or degenerate; expected counter-clockwise faces");
        }
    }
    if (tin.constraints.empty()) return;
    std::unordered_set<std::uint64_t> missing;
    for (const ConstrainedEdge& e : tin.constraints) {
        if (e.a >= nv || e.b >= nv || e.a == e.b) {
            throw InputError("constrained edge " + std::to_string(e.a) + "-" + std::to_string(e.b) +
                             " refers to a missing vertex or to one vertex twice");
        }
        missing.insert(key(e.a, e.b));
    }
    for (const Triangle& f : tin.triangles) {
        for (int i = 0; i < 3 && !missing.empty(); ++i)
            missing.erase(key(f.v[i], f.v[(i + 1) % 3]));
    }
    if (!missing.empty()) {
        const std::uint64_t k = *missing.begin();
        throw InputError("constrained edge " + std::to_string(k >> 32) + "-" +
                         std::to_string(k & 0xffffffffU) + " is not an edge of any face");
    }
}

}  // namespace dtm::io::detail
