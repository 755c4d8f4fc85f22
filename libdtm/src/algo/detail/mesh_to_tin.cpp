// SPDX-License-Identifier: MIT
//
// From the kernel's edge mesh to the Tin value type: triangles with neighbour links in the
// canonical order.
//
// Canonical order: triangles in the order of their canonical edge's slot, the canonical edge being
// the one out of the triangle's smallest vertex. The kernel's edges have their slots in the order
// of the kernel's triangles (ghost_mesh.cpp), and constraint insertion is deterministic, so slot
// order depends on the input only (never on threads or tiles; see delaunay_dc.cpp and
// constraint_batch.cpp), and it follows the recursion, so it is spatially coherent: each pass
// below reads the mesh almost sequentially. (Without constraints the TIN is the kernel's triangle
// array itself: ghost_mesh_to_tin.)
//
//   1. one pass over the slots collects the canonical edges per block of slots (branch-free: one
//      candidate direction per slot); the outer face is recognised by walking it once from a
//      corner of the hull, not by an orientation test per face;
//   2. a prefix sum over the blocks numbers the triangles;
//   3. per triangle: vertices, constraint bits and its id at its three directed edges, stored in
//      the origin array to keep the peak memory low; then the neighbours through those ids.
// Every pass runs in parallel over blocks and writes only its own elements.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>

#include "algo/detail/tin_build.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

template <class Vector>
void release(Vector& v)
{
    Vector().swap(v);
}

/// An edge with the outer face on its left, found at the lexicographically smallest vertex (a
/// corner of the hull, where the outer face is the one wedge wider than a half turn); no_edge when
/// the mesh has no triangle.
EdgeId outer_face_edge(const EdgeMesh& m)
{
    const std::size_t kernel_count = m.points.size();
    if (kernel_count < 3) return no_edge;
    VertexId corner = 0;
    for (VertexId v = 1; v < kernel_count; ++v) {
        const KernelPoint& p = m.points[v];
        const KernelPoint& c = m.points[corner];
        if (p.x < c.x || (p.x == c.x && p.y < c.y)) corner = v;
    }
    EdgeId start = no_edge;
    for (EdgeId e = 0; e < 2 * m.slot_count(); ++e) {
        if (m.alive[e >> 1] && m.org[e] == corner) {
            start = e;
            break;
        }
    }
    if (start == no_edge) return no_edge;
    EdgeId e = start;
    do {
        const EdgeId next = m.onext[e];
        if (next != e && geom::orient2d(m.p(corner), m.p(m.dest(e)), m.p(m.dest(next))) < 0) {
            return e;
        }
        e = next;
    } while (e != start);
    return no_edge;  // collinear: no triangle
}

/// The three edges of the outer face when it is a 3-cycle (hull of three vertices), which the
/// canonical-edge test must not take for a triangle; else no_edge three times.
std::array<EdgeId, 3> outer_triangle(const EdgeMesh& m, EdgeId outer)
{
    if (outer == no_edge) return {no_edge, no_edge, no_edge};
    const EdgeId e1 = m.lnext(outer);
    const EdgeId e2 = m.lnext(e1);
    if (m.lnext(e2) != outer) return {no_edge, no_edge, no_edge};
    return {outer, e1, e2};
}

/// The canonical edge of slot s, when s has one: the direction out of the smaller vertex (the
/// other direction can never be canonical), if its left face is a triangle, not the outer face,
/// and that vertex is the triangle's smallest. Returns the edge with bit 31 set when there is
/// none. Branch-free past the alive test: the outcome is unpredictable, the loads are not.
inline EdgeId canonical_edge_of(const EdgeMesh& m, std::size_t s, const std::array<EdgeId, 3>& outer)
{
    constexpr EdgeId none = 0x80000000u;
    if (!m.alive[s]) return none;
    const auto e = static_cast<EdgeId>(2 * s + (m.org[2 * s] > m.org[2 * s + 1] ? 1 : 0));
    const EdgeId e1 = m.oprev[e ^ 1u];
    const EdgeId e2 = m.oprev[e1 ^ 1u];
    const bool triangle = m.oprev[e2 ^ 1u] == e;
    const bool smallest = m.org[e] < m.org[e2];
    const bool inner = (e != outer[0]) & (e != outer[1]) & (e != outer[2]);
    return (triangle & smallest & inner) ? e : none;
}

constexpr std::size_t block = 1 << 15;  ///< slots per block of the slot passes

}  // namespace

TinDraft mesh_to_tin(EdgeMesh& m, const std::vector<VertexIndex>& kernel_to_vertex,
                     std::vector<Point3> vertices, bool constrained)
{
    TinDraft draft;
    draft.tin.vertices = std::move(vertices);
    const EdgeId outer_edge = outer_face_edge(m);
    const std::array<EdgeId, 3> outer = outer_triangle(m, outer_edge);
    release(m.points);  // from here on: org, oprev (lnext), alive until step 1, constraint bits
    release(m.onext);

    // 1-2. Canonical edges in slot order, collected per block of slots; the blocks are used as
    // they are (no concatenated copy) and give the triangles their numbers by a prefix sum.
    const std::size_t slot_count = m.slot_count();
    const std::size_t blocks = (slot_count + block - 1) / block;
    std::vector<std::vector<EdgeId>> found(blocks);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        const std::size_t end = std::min(slot_count, (b + 1) * block);
        std::vector<EdgeId>& out = found[b];
        out.resize(end - b * block + 1);
        std::size_t at = 0;
        for (std::size_t s = b * block; s < end; ++s) {
            const EdgeId e = canonical_edge_of(m, s, outer);
            out[at] = e;
            at += e >> 31 ^ 1u;
        }
        out.resize(at);
        out.shrink_to_fit();
    });
    release(m.alive);
    std::vector<std::size_t> offset(blocks + 1, 0);
    for (std::size_t b = 0; b < blocks; ++b) offset[b + 1] = offset[b] + found[b].size();
    const std::size_t count = offset[blocks];
    const auto for_each_triangle = [&](const auto& body) {
        tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
            const std::vector<EdgeId>& edges = found[b];
            for (std::size_t j = 0; j < edges.size(); ++j) body(offset[b] + j, edges[j]);
        });
    };

    // 3. Vertices and constraint bits; each triangle's id goes into the origin array at its own
    // three directed edges (no other triangle reads those entries); then the neighbours.
    std::vector<Triangle>& tris = draft.tin.triangles;
    reserve_huge(tris, count);
    tris.resize(count);
    if (constrained) {
        reserve_huge(draft.edge_bits, count);
        draft.edge_bits.resize(count);
    } else {
        release(m.constrained);
    }
    auto& face = m.org;
    for_each_triangle([&](std::size_t t, EdgeId e) {
        const EdgeId e1 = m.lnext(e);
        const EdgeId e2 = m.lnext(e1);
        tris[t].v = {kernel_to_vertex[m.org[e]], kernel_to_vertex[m.org[e1]],
                     kernel_to_vertex[m.org[e2]]};
        if (constrained) {
            draft.edge_bits[t] = {m.constrained[e1 >> 1], m.constrained[e2 >> 1],
                                  m.constrained[e >> 1]};
        }
        face[e] = face[e1] = face[e2] = static_cast<TriangleIndex>(t);
    });
    release(m.constrained);
    // The outer face's edges have no triangle on their left.
    if (outer_edge != no_edge) {
        EdgeId e = outer_edge;
        do {
            face[e] = no_triangle;
            e = m.lnext(e);
        } while (e != outer_edge);
    }
    for_each_triangle([&](std::size_t t, EdgeId e) {
        const EdgeId e1 = m.lnext(e);
        const EdgeId e2 = m.lnext(e1);
        tris[t].n = {face[e1 ^ 1u], face[e2 ^ 1u], face[e ^ 1u]};
    });
    return draft;
}

}  // namespace dtm::detail
