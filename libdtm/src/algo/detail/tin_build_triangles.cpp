// SPDX-License-Identifier: MIT
//
// From the kernel's triangles with ghosts (ghost_mesh.hpp), after any constraint insertion, to
// the TIN, in place: the ghosts (the hull's, and the two unused slots) are replaced by the last
// real triangles, then the neighbour links become triangle indices and the constraint bits move
// to the Tin's convention (per edge opposite a vertex). The triangle array becomes the Tin's
// without a copy, which keeps the peak memory at the TIN's own size plus the points.
//
// Order: the triangles stay in slot order, which depends on the input only (never on threads or
// tiles; see delaunay_dc.cpp and constraint_batch.cpp) and follows the recursion, so it is
// canonical and spatially coherent; only the few triangles moved into ghost slots leave it.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>

#include "algo/detail/ghost_mesh.hpp"
#include "algo/detail/tin_build.hpp"

namespace dtm::detail {
namespace {

constexpr std::size_t block = std::size_t{1} << 14;  ///< triangles per block of a parallel pass

std::size_t block_count(std::size_t triangles) { return (triangles + block - 1) / block; }

/// Runs @p body(t) for the triangles of block @p b.
template <class Body>
void for_block(std::size_t b, std::size_t triangles, const Body& body) {
    const std::size_t end = std::min(triangles, (b + 1) * block);
    for (std::size_t t = b * block; t < end; ++t) body(t);
}

std::vector<std::size_t> concatenate(const std::vector<std::vector<std::size_t>>& lists) {
    std::vector<std::size_t> all;
    for (const auto& list : lists) all.insert(all.end(), list.begin(), list.end());
    return all;
}

}  // namespace

TinDraft ghost_mesh_to_tin(GhostMesh& g, std::vector<Point3> vertices) {
    std::vector<Triangle>& tris = g.tris;
    const std::size_t count = tris.size();
    const std::size_t blocks = block_count(count);
    // 1. The ghost slots (the hull's and the unused ones: few), per block, in slot order.
    std::vector<std::vector<std::size_t>> ghosts(blocks);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        for_block(b, count, [&](std::size_t t) {
            if (g.is_ghost(t)) ghosts[b].push_back(t);
        });
    });
    const std::vector<std::size_t> ghost_slots = concatenate(ghosts);
    const std::size_t real = count - ghost_slots.size();
    // 2. Real triangles on the hull lose their link to the ghost.
    for (const std::size_t t : ghost_slots) {
        for (unsigned i = 0; i < 3; ++i) {
            const HalfEdge h = half_edge(t, i);
            if (g.is_edge(h)) g.twin(g.twin(h)) = no_half_edge;
        }
    }
    // 3. Ghost slots below `real` take the real triangles above it, in order.
    const bool constrained = !g.bits.empty();
    std::size_t mover = real;
    for (const std::size_t hole : ghost_slots) {
        if (hole >= real) break;
        while (g.is_ghost(mover)) ++mover;
        tris[hole] = tris[mover];
        if (constrained) g.bits[hole] = g.bits[mover];
        for (unsigned i = 0; i < 3; ++i) {
            const HalfEdge across = tris[hole].n[i];
            if (across != no_half_edge) g.twin(across) = half_edge(hole, i);
        }
        ++mover;
    }
    tris.resize(real);
    if (constrained) g.bits.resize(real);
    // 4. Vertex numbers, neighbour links and constraint bits of the Tin (n[k] across the edge
    // opposite v[k]; half-edge i is opposite v[i + 2]).
    tbb::parallel_for(std::size_t{0}, block_count(real), [&](std::size_t b) {
        for_block(b, real, [&](std::size_t t) {
            Triangle& tri = tris[t];
            const auto twins = tri.n;
            for (unsigned i = 0; i < 3; ++i) {
                tri.v[i] = g.points[tri.v[i]].id;
                tri.n[(i + 2) % 3] = twins[i] == no_half_edge
                                         ? no_triangle
                                         : static_cast<TriangleIndex>(tri_of(twins[i]));
            }
            if (constrained) {
                const auto bits = g.bits[t];
                for (unsigned i = 0; i < 3; ++i) g.bits[t][(i + 2) % 3] = bits[i];
            }
        });
    });
    TinDraft draft;
    draft.tin.vertices = std::move(vertices);
    draft.tin.triangles = std::move(tris);
    draft.edge_bits = std::move(g.bits);
    g = GhostMesh{};
    return draft;
}

}  // namespace dtm::detail
