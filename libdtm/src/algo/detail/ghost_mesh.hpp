// SPDX-License-Identifier: MIT
/// @file
/// @brief Triangle-based mesh with ghost triangles: the working structure of the Delaunay kernel.
///
/// Every face is a Triangle (the Tin's own type, so the finished mesh becomes the Tin without a
/// copy). Half-edge i of triangle t runs from v[i] to v[(i + 1) % 3] and is named by the code
/// (t << 2) | i; n[i] holds the code of its twin, the same edge in the other direction. Every
/// edge of the convex hull has a ghost triangle on its outer side, whose third vertex is the
/// ghost vertex (`ghost`), so every half-edge has a twin and the hull is a cycle of ghost
/// triangles: the ghost (a, b, ghost) is followed by (b, c, ghost). Its "base" is the half-edge
/// a -> b, with the outer face on its left.
///
/// A triangulation of m points with its ghosts has exactly 2m - 2 triangles (Euler's formula on
/// the sphere closed by the ghost vertex; also for collinear points, whose "hull" is a chain
/// walked in both directions), so a subtree of the divide and conquer over points [lo, hi) fits
/// in the triangle slots [2 lo, 2 hi) with exactly two to spare.
///
/// Reference: J. R. Shewchuk, "Triangle: engineering a 2D quality mesh generator and Delaunay
/// triangulator", 1996 (triangle-based data structure with ghost triangles for divide and
/// conquer).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "algo/detail/big_array.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::detail {

using VertexId = std::uint32_t;
using HalfEdge = std::uint32_t;

/// A vertex of the kernel: position and the caller's index (kept through the partitioning).
/// Packed into 20 bytes instead of 24: the array is one of the three that make the kernel's peak
/// memory, and every pass of the partitioning moves fewer bytes (x86 reads unaligned doubles at
/// full speed). Left uninitialised by default, so a fresh array is not written twice.
struct [[gnu::packed]] KernelPoint {
    double x;
    double y;
    std::uint32_t id;

    KernelPoint() = default;
    KernelPoint(Point2 p, std::uint32_t index) noexcept : x(p.x), y(p.y), id(index) {}
    [[nodiscard]] Point2 xy() const noexcept { return {x, y}; }
};
static_assert(sizeof(KernelPoint) == 20);

/// Bit flags per edge: which constraint kinds run along it (constraint_bit, core/tin.hpp).
enum ConstraintBits : std::uint8_t {
    constraint_none = 0,
    constraint_breakline = constraint_bit(ConstraintKind::breakline),
    constraint_soft = constraint_bit(ConstraintKind::soft_breakline),
    constraint_boundary = constraint_bit(ConstraintKind::boundary),
    constraint_hole = constraint_bit(ConstraintKind::hole),
};

inline constexpr VertexId ghost = no_vertex;
inline constexpr HalfEdge no_half_edge = 0xffffffffu;
/// Triangle slots are addressed by 30 bits in a half-edge code.
inline constexpr std::size_t max_kernel_points = (std::size_t{1} << 29) - 8;

constexpr HalfEdge half_edge(std::size_t t, unsigned i) noexcept {
    return static_cast<HalfEdge>(t << 2 | i);
}
constexpr std::size_t tri_of(HalfEdge h) noexcept { return h >> 2; }
constexpr HalfEdge next(HalfEdge h) noexcept { return (h & 3u) == 2 ? h - 2 : h + 1; }
constexpr HalfEdge prev(HalfEdge h) noexcept { return (h & 3u) == 0 ? h + 2 : h - 1; }

/// A slot holds a ghost triangle (or is unused) when any corner is the ghost vertex.
[[nodiscard]] inline bool is_ghost_triangle(const Triangle& t) noexcept {
    return std::max({t.v[0], t.v[1], t.v[2]}) == ghost;  // the ghost vertex is the largest id
}

/// The kernel's output: triangles with ghosts, over the points in kernel order; with
/// constraints, their ConstraintBits per half-edge (both halves of an edge carry the same).
struct GhostMesh {
    std::vector<Triangle> tris;
    BigArray<KernelPoint> points;
    std::vector<std::array<std::uint8_t, 3>> bits;  ///< per triangle; empty until constrained

    [[nodiscard]] Point2 p(VertexId v) const noexcept { return points[v].xy(); }
    [[nodiscard]] std::uint8_t edge_bits(HalfEdge h) const noexcept { return bits[h >> 2][h & 3u]; }
    /// Sets the bits of the edge of @p h on both of its half-edges.
    void set_edge_bits(HalfEdge h, std::uint8_t b) noexcept {
        bits[h >> 2][h & 3u] = b;
        const HalfEdge t = twin(h);
        bits[t >> 2][t & 3u] = b;
    }

    [[nodiscard]] VertexId& org(HalfEdge h) noexcept { return tris[h >> 2].v[h & 3u]; }
    [[nodiscard]] VertexId org(HalfEdge h) const noexcept { return tris[h >> 2].v[h & 3u]; }
    [[nodiscard]] VertexId dest(HalfEdge h) const noexcept { return org(next(h)); }
    [[nodiscard]] HalfEdge& twin(HalfEdge h) noexcept { return tris[h >> 2].n[h & 3u]; }
    [[nodiscard]] HalfEdge twin(HalfEdge h) const noexcept { return tris[h >> 2].n[h & 3u]; }
    /// @p h runs between two real vertices (one direction of an edge of the triangulation).
    [[nodiscard]] bool is_edge(HalfEdge h) const noexcept {
        return org(h) != ghost && dest(h) != ghost;
    }
    /// Links @p a and @p b as twins.
    void bond(HalfEdge a, HalfEdge b) noexcept {
        twin(a) = b;
        twin(b) = a;
    }
    void set_triangle(std::size_t t, VertexId a, VertexId b, VertexId c) noexcept {
        tris[t].v = {a, b, c};
    }
    /// The triangle of @p h is real (no corner is the ghost vertex).
    [[nodiscard]] bool is_real(HalfEdge h) const noexcept { return !is_ghost(h >> 2); }
    [[nodiscard]] bool is_ghost(std::size_t t) const noexcept { return is_ghost_triangle(tris[t]); }
};

}  // namespace dtm::detail
