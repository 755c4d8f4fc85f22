// SPDX-License-Identifier: MIT
//
// From the kernel's triangles with ghosts (ghost_mesh.hpp) to the two structures that use them:
//
// - the half-edge mesh of constraint insertion and point location (edge_mesh.hpp): one edge slot
//   per edge, numbered in the order of the triangles (so the slot order is, like the triangle
//   order, a function of the input only), at the edge's direction with the smaller code; origin,
//   next and previous edge around the origin read off the triangles, skipping the ghost vertex;
// - the TIN directly, when nothing is inserted: in place, the ghosts (the hull's, and the two
//   unused slots) replaced by the last real triangles, then the neighbour links turned into
//   triangle indices. The triangle array becomes the Tin's without a copy, which keeps the peak
//   memory at the TIN's own size plus the points.
#include "algo/detail/ghost_mesh.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "algo/detail/tin_build.hpp"

namespace dtm::detail {
namespace {

constexpr std::size_t block = std::size_t{1} << 14;  ///< triangles per block of a parallel pass

std::size_t block_count(std::size_t triangles) { return (triangles + block - 1) / block; }

/// Runs @p body(t) for the triangles of block @p b.
template <class Body>
void for_block(std::size_t b, std::size_t triangles, const Body& body)
{
    const std::size_t end = std::min(triangles, (b + 1) * block);
    for (std::size_t t = b * block; t < end; ++t) body(t);
}

/// Triangles per chunk of the last pass of ghost_mesh_to_edge_mesh: 8 MiB, so that a chunk holds
/// three or four whole 2 MiB pages to give back.
constexpr std::size_t release_chunk_triangles = (std::size_t{8} << 20) / sizeof(Triangle);

/// Gives the whole pages inside [begin, end) back to the system (their contents are not needed
/// any more; the memory stays allocated and reads as zeros). Linux only; elsewhere nothing.
void release_pages(const Triangle* begin, const Triangle* end)
{
#if defined(__linux__)
    constexpr std::uintptr_t page = std::uintptr_t{2} << 20;
    const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(begin) + page - 1) / page * page;
    const std::uintptr_t last = reinterpret_cast<std::uintptr_t>(end) / page * page;
    if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
#else
    (void)begin;
    (void)end;
#endif
}

std::vector<std::size_t> concatenate(const std::vector<std::vector<std::size_t>>& lists)
{
    std::vector<std::size_t> all;
    for (const auto& list : lists) all.insert(all.end(), list.begin(), list.end());
    return all;
}

/// @p h runs between two real vertices (one direction of an edge of the triangulation).
bool is_edge(const GhostMesh& g, HalfEdge h) noexcept
{
    return g.org(h) != ghost && g.dest(h) != ghost;
}

/// The direction of an edge that gets its slot: the one with the smaller code.
bool owns_slot(const GhostMesh& g, HalfEdge h) noexcept
{
    return is_edge(g, h) && h < g.twin(h);
}

}  // namespace

void ghost_mesh_to_edge_mesh(GhostMesh& g, EdgeMesh& m, EdgeSlots& slots)
{
    const std::size_t count = g.tris.size();
    const std::size_t blocks = block_count(count);
    // 1. Which half-edges own a slot (bit i of owner[t]), and how many per block.
    BigArray<std::uint8_t> owner(count);
    std::vector<std::size_t> offset(blocks + 1, 0);
    std::vector<std::vector<std::size_t>> ghosts(blocks);  // few: the hull's and two unused
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        std::size_t owned = 0;
        for_block(b, count, [&](std::size_t t) {
            if (g.is_ghost(t)) ghosts[b].push_back(t);
            std::uint8_t bits = 0;
            for (unsigned i = 0; i < 3; ++i) {
                bits |= static_cast<std::uint8_t>(owns_slot(g, half_edge(t, i)) ? 1u << i : 0u);
            }
            owner[t] = bits;
            owned += static_cast<std::size_t>(std::popcount(bits));
        });
        offset[b + 1] = owned;
    });
    for (std::size_t b = 0; b < blocks; ++b) offset[b + 1] += offset[b];
    const std::size_t edges = offset[blocks];
    const std::vector<std::size_t> ghost_slots = concatenate(ghosts);
    m.resize_slots(std::max(edges, 3 * g.points.size()) + 16);

    // 2. In place, the twin link of every edge half-edge h becomes the edge mesh's directed edge
    // of twin(h): slot s at the owner (2 s + 1 for the twin), then the other direction from it.
    // Links of the ghost vertex's edges stay half-edge codes (the walk around a hull vertex).
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        auto s = static_cast<EdgeId>(offset[b]);
        for_block(b, count, [&](std::size_t t) {
            for (unsigned i = 0; i < 3; ++i) {
                if ((owner[t] >> i & 1u) == 0) continue;
                g.tris[t].n[i] = 2 * s + 1;
                m.alive[s] = 1;
                ++s;
            }
        });
    });
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        for_block(b, count, [&](std::size_t t) {
            for (unsigned i = 0; i < 3; ++i) {
                const HalfEdge h = half_edge(t, i);
                if ((owner[t] >> i & 1u) != 0 || !is_edge(g, h)) continue;
                g.twin(h) = g.twin(g.twin(h)) ^ 1u;  // the owner's entry is final
            }
        });
    });
    owner = {};
    // 3. Origin and the rings around it: the next edge counter-clockwise around org(h) is the
    // twin of prev(h); past the ghost vertex, of prev(twin(prev(h))), which lies in another
    // ghost: those few are looked up first, so that each chunk of triangles reads only itself
    // and can hand its memory back as soon as it is done (the mesh's fresh pages then reuse it).
    std::vector<std::pair<HalfEdge, EdgeId>> past_ghost;
    for (const std::size_t t : ghost_slots) {
        for (unsigned i = 0; i < 3; ++i) {
            const HalfEdge h = half_edge(t, i);
            if (is_edge(g, h)) past_ghost.emplace_back(h, g.twin(prev(g.twin(prev(h)))));
        }
    }
    std::sort(past_ghost.begin(), past_ghost.end());
    const std::size_t chunk = release_chunk_triangles;
    tbb::parallel_for(std::size_t{0}, (count + chunk - 1) / chunk, [&](std::size_t c) {
        const std::size_t end = std::min(count, (c + 1) * chunk);
        for (std::size_t t = c * chunk; t < end; ++t) {
            for (unsigned i = 0; i < 3; ++i) {
                const HalfEdge h = half_edge(t, i);
                if (!is_edge(g, h)) continue;
                const EdgeId e = g.twin(h) ^ 1u;
                const HalfEdge p = prev(h);
                const EdgeId around =
                    g.org(p) != ghost
                        ? g.twin(p)
                        : std::lower_bound(past_ghost.begin(), past_ghost.end(),
                                           std::pair<HalfEdge, EdgeId>{h, 0})->second;
                m.org[e] = g.org(h);
                m.onext[e] = around;
                m.oprev[around] = e;  // onext is a permutation: every entry written once
            }
        }
        release_pages(g.tris.data() + c * chunk, g.tris.data() + end);
    }, tbb::simple_partitioner{});
    slots = EdgeSlots{static_cast<EdgeId>(edges), static_cast<EdgeId>(m.slot_count())};
    m.points = std::move(g.points);
    g = GhostMesh{};
}

TinDraft ghost_mesh_to_tin(GhostMesh& g, std::vector<Point3> vertices)
{
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
            if (is_edge(g, h)) g.twin(g.twin(h)) = no_half_edge;
        }
    }
    // 3. Ghost slots below `real` take the real triangles above it, in order.
    std::size_t mover = real;
    for (const std::size_t hole : ghost_slots) {
        if (hole >= real) break;
        while (g.is_ghost(mover)) ++mover;
        tris[hole] = tris[mover];
        for (unsigned i = 0; i < 3; ++i) {
            const HalfEdge across = tris[hole].n[i];
            if (across != no_half_edge) g.twin(across) = half_edge(hole, i);
        }
        ++mover;
    }
    tris.resize(real);
    // 4. Vertex numbers and neighbour links of the Tin (n[k] across the edge opposite v[k]).
    tbb::parallel_for(std::size_t{0}, block_count(real), [&](std::size_t b) {
        for_block(b, real, [&](std::size_t t) {
            Triangle& tri = tris[t];
            const auto twins = tri.n;
            for (unsigned i = 0; i < 3; ++i) {
                tri.v[i] = g.points[tri.v[i]].id;
                tri.n[(i + 2) % 3] =
                    twins[i] == no_half_edge ? no_triangle : static_cast<TriangleIndex>(tri_of(twins[i]));
            }
        });
    });
    TinDraft draft;
    draft.tin.vertices = std::move(vertices);
    draft.tin.triangles = std::move(tris);
    g = GhostMesh{};
    return draft;
}

}  // namespace dtm::detail
