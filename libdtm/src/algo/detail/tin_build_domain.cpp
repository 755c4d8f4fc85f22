// SPDX-License-Identifier: MIT
//
// The domain of the TIN (the conversion from the kernel's triangles is in tin_build_triangles.cpp).
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
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <deque>

#include "algo/detail/tin_build.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

constexpr std::uint8_t domain_bits = constraint_boundary | constraint_hole;

}  // namespace

void compact(TinDraft& draft, const std::vector<bool>& keep) {
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
        if (draft.any_constraint()) draft.edge_bits[new_index[t]] = draft.edge_bits[t];
    }
    tris.resize(next);
    if (draft.any_constraint()) draft.edge_bits.resize(next);
}

std::size_t apply_domain(TinDraft& draft,
                         bool has_boundary,
                         const std::vector<Point2>& hole_seeds,
                         double max_edge) {
    const Tin& tin = draft.tin;
    const std::size_t count = tin.triangles.size();
    // Rings: 0-1 BFS over crossings of boundary/hole edges.
    std::atomic<bool> ring_edge{false};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, draft.edge_bits.size(), 1 << 16),
                      [&](const auto& range) {
                          std::uint8_t all = 0;
                          for (std::size_t t = range.begin(); t < range.end(); ++t) {
                              const auto& bits = draft.edge_bits[t];
                              all |= static_cast<std::uint8_t>(bits[0] | bits[1] | bits[2]);
                          }
                          if ((all & domain_bits) != 0)
                              ring_edge.store(true, std::memory_order_relaxed);
                      });
    const bool any_ring = has_boundary || ring_edge.load();
    if (!any_ring && hole_seeds.empty())
        return max_edge > 0.0 ? trim_long_edges(draft, max_edge) : 0;
    std::vector<bool> keep(count, true);
    if (any_ring) {
        constexpr std::uint32_t unset = 0xffffffffu;
        std::vector<std::uint32_t> depth(count, unset);
        std::deque<std::pair<TriangleIndex, std::uint32_t>> queue;
        const std::uint32_t outside = has_boundary ? 0 : 1;
        for (TriangleIndex t = 0; t < count; ++t) {
            for (int i = 0; i < 3; ++i) {
                if (tin.triangles[t].n[i] != no_triangle) continue;
                const bool ring = (draft.bits(t, i) & domain_bits) != 0;
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
                if ((draft.bits(t, i) & domain_bits) != 0) {
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
                if (n != no_triangle && keep[n] && draft.bits(t, i) == 0) stack.push_back(n);
            }
        }
    }
    std::size_t removed = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), false));
    if (removed > 0) compact(draft, keep);
    if (max_edge > 0.0) removed += trim_long_edges(draft, max_edge);
    return removed;
}

}  // namespace dtm::detail
