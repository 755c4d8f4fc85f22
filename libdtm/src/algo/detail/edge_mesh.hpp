// SPDX-License-Identifier: MIT
/// @file
/// @brief Half-edge mesh in the style of Guibas and Stolfi's quad-edge, without the dual: the
/// working structure of constraint insertion and point location, made from the Delaunay
/// kernel's triangles (ghost_mesh.hpp, ghost_mesh_to_edge_mesh).
///
/// Directed edges come in pairs: e and sym(e) = e ^ 1 are the two directions of one undirected
/// edge (index e >> 1). For each directed edge we keep its origin vertex and the next and previous
/// edges counter-clockwise around that origin (onext, oprev). Faces are implicit: the left face of
/// e is bounded by e, lnext(e), lnext(lnext(e)).
///
///         lnext(e)                     onext(e): next edge ccw around org(e)
///      d <-------- c                   oprev(e): next edge cw around org(e)
///       \  left   ^                    lnext(e): next edge ccw around the left face
///        \ face  /                               = oprev(sym(e))
///         v     / e
///           org
///
/// References: L. Guibas, J. Stolfi, "Primitives for the manipulation of general subdivisions and
/// the computation of Voronoi diagrams", ACM TOG 4(2), 1985 (splice, connect, delete_edge, swap).
#pragma once

#include <cstdint>
#include <cstddef>
#include <stdexcept>

#include "algo/detail/big_array.hpp"
#include "dtm/core/point.hpp"

namespace dtm::detail {

using EdgeId = std::uint32_t;
using VertexId = std::uint32_t;
inline constexpr EdgeId no_edge = 0xffffffffu;

/// A vertex of the kernel: position and the caller's index (kept through the partitioning).
struct KernelPoint : Point2 {
    std::uint32_t id = 0;
};

/// Bit flags per undirected edge: which constraint kinds run along it.
enum ConstraintBits : std::uint8_t {
    constraint_none = 0,
    constraint_breakline = 1,
    constraint_soft = 2,
    constraint_boundary = 4,
    constraint_hole = 8,
};

/// Allocator of undirected edge slots: a never-used range [next, end) and a free list of
/// released slots (LIFO), threaded through the slots themselves (see EdgeMesh::release_slot).
/// The kernel's edges take the first slots, in the order of its triangles, which is the same
/// for every tile and thread count; so is the order of every later allocation (constraint
/// insertion is deterministic), and with it the order in which the TIN is read off the mesh.
struct EdgeSlots {
    EdgeId next = 0;  ///< next never-used undirected slot
    EdgeId end = 0;   ///< one past the last slot of the range
    EdgeId free_head = no_edge;
    EdgeId free_tail = no_edge;
    std::size_t free_count = 0;

    [[nodiscard]] std::size_t available() const noexcept { return free_count + (end - next); }
};

struct EdgeMesh {
    BigArray<KernelPoint> points;  ///< vertex positions (kernel order) and caller's ids
    BigArray<VertexId> org;        ///< per directed edge
    BigArray<EdgeId> onext;        ///< per directed edge
    BigArray<EdgeId> oprev;        ///< per directed edge
    BigArray<std::uint8_t> constrained;  ///< per undirected edge: ConstraintBits
    BigArray<std::uint8_t> alive;        ///< per undirected edge

    /// Reserve room for @p slot_count undirected edges.
    void resize_slots(std::size_t slot_count)
    {
        org.clear();
        onext.clear();
        oprev.clear();
        constrained.clear();
        alive.clear();
        grow_slots(slot_count);
    }
    [[nodiscard]] std::size_t slot_count() const noexcept { return alive.size(); }

    /// Grows the slot arrays to @p slot_count, keeping every existing edge. The links of a new
    /// slot are left unset: make_edge sets them, and nothing reads a slot that is not alive.
    void grow_slots(std::size_t slot_count)
    {
        org.resize(2 * slot_count);
        onext.resize(2 * slot_count);
        oprev.resize(2 * slot_count);
        constrained.resize(slot_count, 0);
        alive.resize(slot_count, 0);
    }

    static EdgeId sym(EdgeId e) noexcept { return e ^ 1u; }
    [[nodiscard]] VertexId dest(EdgeId e) const noexcept { return org[e ^ 1u]; }
    [[nodiscard]] EdgeId lnext(EdgeId e) const noexcept { return oprev[e ^ 1u]; }
    [[nodiscard]] EdgeId lprev(EdgeId e) const noexcept { return onext[e] ^ 1u; }
    [[nodiscard]] EdgeId rprev(EdgeId e) const noexcept { return onext[e ^ 1u]; }
    [[nodiscard]] EdgeId rnext(EdgeId e) const noexcept { return oprev[e] ^ 1u; }
    [[nodiscard]] const KernelPoint& p(VertexId v) const noexcept { return points[v]; }
    [[nodiscard]] bool is_constrained(EdgeId e) const noexcept { return constrained[e >> 1] != 0; }

    /// Puts slot s (not alive) on the free list of @p slots. The link to the next free slot is
    /// kept in oprev of the slot's second direction; a dead edge is otherwise a pair of loops.
    void release_slot(EdgeSlots& slots, EdgeId s) noexcept
    {
        oprev[2 * s + 1] = slots.free_head;
        if (slots.free_head == no_edge) slots.free_tail = s;
        slots.free_head = s;
        ++slots.free_count;
    }

    EdgeId make_edge(EdgeSlots& slots, VertexId a, VertexId b)
    {
        EdgeId s;
        if (slots.free_head != no_edge) {
            s = slots.free_head;
            slots.free_head = oprev[2 * s + 1];
            if (slots.free_head == no_edge) slots.free_tail = no_edge;
            --slots.free_count;
        } else if (slots.next < slots.end) {
            s = slots.next++;
        } else {
            throw std::logic_error("edge mesh: no free edge slot (internal error)");
        }
        const EdgeId e = 2 * s;
        org[e] = a;
        org[e + 1] = b;
        onext[e] = oprev[e] = e;
        onext[e + 1] = oprev[e + 1] = e + 1;
        constrained[s] = 0;
        alive[s] = 1;
        return e;
    }

    /// Guibas-Stolfi splice restricted to the primal rings: exchanges the rings around org(a) and
    /// org(b) (joins them if different, splits if the same).
    void splice(EdgeId a, EdgeId b) noexcept
    {
        const EdgeId an = onext[a];
        const EdgeId bn = onext[b];
        onext[a] = bn;
        onext[b] = an;
        oprev[bn] = a;
        oprev[an] = b;
    }

    /// New edge from dest(a) to org(b); a, b and the new edge share their left face afterwards.
    EdgeId connect(EdgeSlots& slots, EdgeId a, EdgeId b)
    {
        const EdgeId e = make_edge(slots, dest(a), org[b]);
        splice(e, lnext(a));
        splice(e ^ 1u, b);
        return e;
    }

    void delete_edge(EdgeSlots& slots, EdgeId e)
    {
        splice(e, oprev[e]);
        splice(e ^ 1u, oprev[e ^ 1u]);
        alive[e >> 1] = 0;
        constrained[e >> 1] = 0;
        release_slot(slots, e >> 1);
    }

    /// Flip e, the diagonal of the quadrilateral formed by its two triangles.
    void swap(EdgeId e) noexcept
    {
        const EdgeId a = oprev[e];
        const EdgeId b = oprev[e ^ 1u];
        splice(e, a);
        splice(e ^ 1u, b);
        splice(e, lnext(a));
        splice(e ^ 1u, lnext(b));
        org[e] = dest(a);
        org[e ^ 1u] = dest(b);
    }
};

}  // namespace dtm::detail
