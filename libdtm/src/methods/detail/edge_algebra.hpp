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
    void reserve(std::size_t edges) {
        org_.reserve(2 * edges);
        onext_.reserve(2 * edges);
        oprev_.reserve(2 * edges);
    }

    [[nodiscard]] static HalfEdge sym(HalfEdge e) noexcept { return e ^ 1u; }
    [[nodiscard]] VertexIndex org(HalfEdge e) const noexcept { return org_[e]; }
    [[nodiscard]] VertexIndex dest(HalfEdge e) const noexcept { return org_[e ^ 1u]; }
    /// Next counter-clockwise around the origin.
    [[nodiscard]] HalfEdge onext(HalfEdge e) const noexcept { return onext_[e]; }
    /// Next clockwise around the origin.
    [[nodiscard]] HalfEdge oprev(HalfEdge e) const noexcept { return oprev_[e]; }
    /// Next counter-clockwise around the left face.
    [[nodiscard]] HalfEdge lnext(HalfEdge e) const noexcept { return oprev_[e ^ 1u]; }
    /// Previous around the right face (clockwise from the destination).
    [[nodiscard]] HalfEdge rprev(HalfEdge e) const noexcept { return onext_[e ^ 1u]; }

    /// A new isolated edge a -> b.
    HalfEdge make_edge(VertexIndex a, VertexIndex b) {
        HalfEdge e;
        if (free_ != no_half_edge) {
            e = free_;
            free_ = onext_[e];
        } else {
            e = static_cast<HalfEdge>(org_.size());
            org_.resize(org_.size() + 2);
            onext_.resize(onext_.size() + 2);
            oprev_.resize(oprev_.size() + 2);
        }
        org_[e] = a;
        org_[e ^ 1u] = b;
        onext_[e] = oprev_[e] = e;
        onext_[e ^ 1u] = oprev_[e ^ 1u] = e ^ 1u;
        ++live_;
        return e;
    }

    /// Guibas-Stolfi splice on the origin rings of a and b (joins two rings or splits one).
    void splice(HalfEdge a, HalfEdge b) noexcept {
        const HalfEdge alpha = onext_[a];
        const HalfEdge beta = onext_[b];
        onext_[a] = beta;
        onext_[b] = alpha;
        oprev_[beta] = a;
        oprev_[alpha] = b;
    }

    /// A new edge from a's destination to b's origin, in the face left of both.
    HalfEdge connect(HalfEdge a, HalfEdge b) {
        const HalfEdge e = make_edge(dest(a), org(b));
        splice(e, lnext(a));
        splice(sym(e), b);
        return e;
    }

    void delete_edge(HalfEdge e) noexcept {
        splice(e, oprev_[e]);
        splice(sym(e), oprev_[sym(e)]);
        e &= ~1u;
        org_[e] = org_[e ^ 1u] = no_vertex;
        onext_[e] = free_;
        free_ = e;
        --live_;
    }

    [[nodiscard]] bool alive(HalfEdge e) const noexcept { return org_[e] != no_vertex; }
    [[nodiscard]] std::size_t half_edges() const noexcept { return org_.size(); }
    [[nodiscard]] std::size_t edges() const noexcept { return live_; }
    [[nodiscard]] std::size_t bytes() const noexcept {
        return (org_.capacity() + onext_.capacity() + oprev_.capacity()) * 4;
    }

private:
    std::vector<VertexIndex> org_;
    std::vector<HalfEdge> onext_;
    std::vector<HalfEdge> oprev_;
    HalfEdge free_ = no_half_edge;
    std::size_t live_ = 0;
};

}  // namespace dtm::methods::detail
