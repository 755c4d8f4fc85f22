// SPDX-License-Identifier: MIT
//
// From the kernel's edge mesh to the Tin value type, and the domain of the TIN.
//
// Domain: the outer boundary and hole rings are constrained edges. Triangles are classified by a
// 0-1 breadth-first search from the convex hull that counts how many boundary or hole edges must
// be crossed to reach them (the nesting depth of rings around them): with a boundary, depth 0 is
// outside it, 1 inside, 2 in a hole, 3 on an island in a hole, ...; odd depths are kept. Without a
// boundary the hull plays its part (the hull triangles start at depth 1). Hole seeds work as in
// Shewchuk's Triangle: the triangle holding the seed and everything reachable from it without
// crossing a constrained edge is removed. Finally, with a maximum edge length, border triangles
// whose border edge is longer than it (and not constrained) are peeled off, repeatedly, from the
// outside inwards.
#include "algo/detail/tin_build.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <deque>

#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

constexpr std::uint8_t domain_bits = constraint_boundary | constraint_hole;

bool left_face_is_triangle(const EdgeMesh& m, EdgeId e)
{
    const EdgeId e1 = m.lnext(e);
    const EdgeId e2 = m.lnext(e1);
    return m.lnext(e2) == e &&
           geom::orient2d(m.p(m.org[e]), m.p(m.dest(e)), m.p(m.dest(e1))) > 0;
}

}  // namespace

void compact(TinDraft& draft, const std::vector<bool>& keep)
{
    std::vector<TriangleIndex> new_index(keep.size(), no_triangle);
    TriangleIndex next = 0;
    for (std::size_t t = 0; t < keep.size(); ++t) {
        if (keep[t]) new_index[t] = next++;
    }
    std::vector<Triangle>& tris = draft.tin.triangles;
    for (std::size_t t = 0; t < keep.size(); ++t) {
        if (!keep[t]) continue;
        Triangle tri = tris[t];
        for (TriangleIndex& n : tri.n) n = n == no_triangle ? no_triangle : new_index[n];
        tris[new_index[t]] = tri;
        draft.edge_bits[new_index[t]] = draft.edge_bits[t];
    }
    tris.resize(next);
    draft.edge_bits.resize(next);
}

namespace {

/// The edges out of kernel vertex v whose left face is a triangle with v as its smallest vertex,
/// ordered by their other two vertices.
void triangles_at(const EdgeMesh& m, VertexId v, EdgeId start, std::vector<EdgeId>& out)
{
    out.clear();
    EdgeId e = start;
    do {
        if (m.dest(e) > v && m.dest(m.lnext(e)) > v && left_face_is_triangle(m, e)) out.push_back(e);
        e = m.onext[e];
    } while (e != start);
    std::sort(out.begin(), out.end(), [&](EdgeId a, EdgeId b) {
        const VertexId a1 = m.dest(a), b1 = m.dest(b);
        return a1 < b1 || (a1 == b1 && m.dest(m.lnext(a)) < m.dest(m.lnext(b)));
    });
}

template <class Vector>
void release(Vector& v)
{
    Vector().swap(v);
}

}  // namespace

TinDraft mesh_to_tin(EdgeMesh& m, const std::vector<VertexIndex>& kernel_to_vertex,
                     std::vector<Point3> vertices)
{
    // Triangles are emitted in the canonical order: by their smallest kernel vertex, then by the
    // other two. The kernel numbering comes from the divide and conquer's median splits, which
    // depend on the input only (never on threads or tiles), and it is spatially coherent, so this
    // order costs no global sort and keeps neighbours close in memory. Blocks of vertices are
    // counted, then filled, in parallel; the mesh arrays are released as soon as they are not
    // needed, and the face ids reuse the origin array, to keep the peak memory low.
    TinDraft draft;
    draft.tin.vertices = std::move(vertices);
    const std::size_t directed = 2 * m.slot_count();
    const std::size_t kernel_count = m.points.size();
    std::vector<EdgeId> vertex_edge(kernel_count, no_edge);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, directed), [&](const auto& r) {
        for (std::size_t e = r.begin(); e < r.end(); ++e) {
            if (m.alive[e >> 1]) {
                std::atomic_ref<EdgeId>(vertex_edge[m.org[e]]).store(static_cast<EdgeId>(e),
                                                                    std::memory_order_relaxed);
            }
        }
    });
    constexpr std::size_t block = 4096;
    const std::size_t block_count = (kernel_count + block - 1) / block;
    std::vector<std::vector<EdgeId>> found(block_count);
    tbb::parallel_for(std::size_t{0}, block_count, [&](std::size_t b) {
        std::vector<EdgeId> local;
        found[b].reserve(2 * block + 16);
        for (std::size_t v = b * block; v < std::min(kernel_count, (b + 1) * block); ++v) {
            if (vertex_edge[v] == no_edge) continue;
            triangles_at(m, static_cast<VertexId>(v), vertex_edge[v], local);
            found[b].insert(found[b].end(), local.begin(), local.end());
        }
    });
    std::vector<std::size_t> offset(block_count + 1, 0);
    for (std::size_t b = 0; b < block_count; ++b) offset[b + 1] = offset[b] + found[b].size();
    const std::size_t count = offset[block_count];
    std::vector<EdgeId> first_edge(count);
    tbb::parallel_for(std::size_t{0}, block_count, [&](std::size_t b) {
        std::copy(found[b].begin(), found[b].end(),
                  first_edge.begin() + static_cast<std::ptrdiff_t>(offset[b]));
        release(found[b]);
    });
    release(vertex_edge);
    release(offset);

    draft.edge_bits.resize(count);
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t t) {
        const EdgeId f = first_edge[t];
        const EdgeId f1 = m.lnext(f);
        draft.edge_bits[t] = {m.constrained[f1 >> 1], m.constrained[m.lnext(f1) >> 1],
                              m.constrained[f >> 1]};
    });
    release(m.onext);  // from here on only org and oprev (lnext) are read
    release(m.alive);
    release(m.constrained);
    release(m.points);

    std::vector<Triangle>& tris = draft.tin.triangles;
    tris.resize(count);
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t t) {
        const EdgeId f = first_edge[t];
        const EdgeId f1 = m.lnext(f);
        tris[t].v = {kernel_to_vertex[m.org[f]], kernel_to_vertex[m.org[f1]],
                     kernel_to_vertex[m.org[m.lnext(f1)]]};
    });
    // Neighbours through a face id per directed edge, stored in the origin array.
    auto& face = m.org;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, directed), [&](const auto& r) {
        std::fill(face.begin() + static_cast<std::ptrdiff_t>(r.begin()),
                  face.begin() + static_cast<std::ptrdiff_t>(r.end()), no_triangle);
    });
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t t) {
        const EdgeId e = first_edge[t];
        const EdgeId e1 = m.lnext(e);
        face[e] = face[e1] = face[m.lnext(e1)] = static_cast<TriangleIndex>(t);
    });
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t t) {
        const EdgeId e = first_edge[t];
        const EdgeId e1 = m.lnext(e);
        const EdgeId e2 = m.lnext(e1);
        tris[t].n = {face[e1 ^ 1u], face[e2 ^ 1u], face[e ^ 1u]};
    });
    return draft;
}

std::size_t apply_domain(TinDraft& draft, bool has_boundary, const std::vector<Point2>& hole_seeds,
                         double max_edge)
{
    const Tin& tin = draft.tin;
    const std::size_t count = tin.triangles.size();
    std::vector<bool> keep(count, true);
    // Rings: 0-1 BFS over crossings of boundary/hole edges.
    bool any_ring = has_boundary;
    for (const auto& bits : draft.edge_bits) {
        for (const std::uint8_t b : bits) any_ring = any_ring || (b & domain_bits) != 0;
    }
    if (any_ring) {
        constexpr std::uint32_t unset = 0xffffffffu;
        std::vector<std::uint32_t> depth(count, unset);
        std::deque<std::pair<TriangleIndex, std::uint32_t>> queue;
        const std::uint32_t outside = has_boundary ? 0 : 1;
        for (TriangleIndex t = 0; t < count; ++t) {
            for (int i = 0; i < 3; ++i) {
                if (tin.triangles[t].n[i] != no_triangle) continue;
                const bool ring = (draft.edge_bits[t][i] & domain_bits) != 0;
                if (ring) {
                    queue.emplace_back(t, outside + 1);
                } else {
                    queue.emplace_front(t, outside);
                }
            }
        }
        while (!queue.empty()) {
            const auto [t, d] = queue.front();
            queue.pop_front();
            if (depth[t] <= d) continue;
            depth[t] = d;
            for (int i = 0; i < 3; ++i) {
                const TriangleIndex n = tin.triangles[t].n[i];
                if (n == no_triangle || depth[n] != unset) continue;
                if ((draft.edge_bits[t][i] & domain_bits) != 0) {
                    queue.emplace_back(n, d + 1);
                } else {
                    queue.emplace_front(n, d);
                }
            }
        }
        for (TriangleIndex t = 0; t < count; ++t) keep[t] = depth[t] % 2 == 1;
    }
    // Hole seeds.
    for (const Point2& seed : hole_seeds) {
        std::vector<TriangleIndex> stack;
        for (TriangleIndex t = 0; t < count && stack.empty(); ++t) {
            const auto& v = tin.triangles[t].v;
            const Point3& a = tin.vertices[v[0]];
            const Point3& b = tin.vertices[v[1]];
            const Point3& c = tin.vertices[v[2]];
            if (geom::orient2d(a.x, a.y, b.x, b.y, seed.x, seed.y) >= 0 &&
                geom::orient2d(b.x, b.y, c.x, c.y, seed.x, seed.y) >= 0 &&
                geom::orient2d(c.x, c.y, a.x, a.y, seed.x, seed.y) >= 0) {
                stack.push_back(t);
            }
        }
        while (!stack.empty()) {
            const TriangleIndex t = stack.back();
            stack.pop_back();
            if (!keep[t]) continue;
            keep[t] = false;
            for (int i = 0; i < 3; ++i) {
                const TriangleIndex n = tin.triangles[t].n[i];
                if (n != no_triangle && keep[n] && draft.edge_bits[t][i] == 0) stack.push_back(n);
            }
        }
    }
    std::size_t removed = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), false));
    if (removed > 0) compact(draft, keep);
    if (max_edge > 0.0) removed += trim_long_edges(draft, max_edge);
    return removed;
}

}  // namespace dtm::detail
