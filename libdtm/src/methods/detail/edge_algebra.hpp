// SPDX-License-Identifier: MIT
/// @file
/// @brief The primal half of Guibas and Stolfi's quad-edge structure ("Primitives for the
/// manipulation of general subdivisions", 1985): half-edges in twin pairs (e, e ^ 1), each
/// with its origin and its neighbours counter-clockwise and clockwise around the origin;
/// make_edge, splice, connect and delete_edge keep it a subdivision of an orientable surface.
#pragma once

#include <cstdint>
#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm::methods::detail {

using HalfEdge = std::uint32_t;
inline constexpr HalfEdge no_half_edge = 0xffffffffu;

class EdgeAlgebra {
public:
    void reserve(std::size_t edges) { he_.reserve(2 * edges); }

    [[nodiscard]] static HalfEdge sym(HalfEdge e) noexcept { return e ^ 1u; }
    [[nodiscard]] VertexIndex org(HalfEdge e) const noexcept { return he_[e].org; }
    [[nodiscard]] VertexIndex dest(HalfEdge e) const noexcept { return he_[e ^ 1u].org; }
    /// Next counter-clockwise around the origin.
    [[nodiscard]] HalfEdge onext(HalfEdge e) const noexcept { return he_[e].onext; }
    /// Next clockwise around the origin.
    [[nodiscard]] HalfEdge oprev(HalfEdge e) const noexcept { return he_[e].oprev; }
    /// Next counter-clockwise around the left face.
    [[nodiscard]] HalfEdge lnext(HalfEdge e) const noexcept { return he_[e ^ 1u].oprev; }
    /// Previous around the right face (clockwise from the destination).
    [[nodiscard]] HalfEdge rprev(HalfEdge e) const noexcept { return he_[e ^ 1u].onext; }

    /// A new isolated edge a -> b.
    HalfEdge make_edge(VertexIndex a, VertexIndex b) {
        HalfEdge e;
        if (free_ != no_half_edge) {
            e = free_;
            free_ = he_[e].onext;
        } else {
            e = static_cast<HalfEdge>(he_.size());
            he_.resize(he_.size() + 2);
        }
        he_[e] = {a, e, e};
        he_[e ^ 1u] = {b, e ^ 1u, e ^ 1u};
        ++live_;
        return e;
    }

    /// Guibas-Stolfi splice on the origin rings of a and b (joins two rings or splits one).
    void splice(HalfEdge a, HalfEdge b) noexcept {
        const HalfEdge alpha = he_[a].onext;
        const HalfEdge beta = he_[b].onext;
        he_[a].onext = beta;
        he_[b].onext = alpha;
        he_[beta].oprev = a;
        he_[alpha].oprev = b;
    }

    /// A new edge from a's destination to b's origin, in the face left of both.
    HalfEdge connect(HalfEdge a, HalfEdge b) {
        const HalfEdge e = make_edge(dest(a), org(b));
        splice(e, lnext(a));
        splice(sym(e), b);
        return e;
    }

    void delete_edge(HalfEdge e) noexcept {
        splice(e, he_[e].oprev);
        splice(sym(e), he_[sym(e)].oprev);
        e &= ~1u;
        he_[e].org = he_[e ^ 1u].org = no_vertex;
        he_[e].onext = free_;
        free_ = e;
        --live_;
    }

    [[nodiscard]] bool alive(HalfEdge e) const noexcept { return he_[e].org != no_vertex; }
    [[nodiscard]] std::size_t half_edges() const noexcept { return he_.size(); }
    [[nodiscard]] std::size_t edges() const noexcept { return live_; }
    [[nodiscard]] std::size_t bytes() const noexcept { return he_.capacity() * sizeof(Record); }

private:
    struct Record {
        VertexIndex org;
        HalfEdge onext;
        HalfEdge oprev;
    };
    std::vector<Record> he_;  ///< one record per half-edge: a walk touches one cache line
    HalfEdge free_ = no_half_edge;
    std::size_t live_ = 0;
};

}  // namespace dtm::methods::detail
