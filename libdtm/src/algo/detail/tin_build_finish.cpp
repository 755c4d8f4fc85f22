// SPDX-License-Identifier: MIT
//
// Finishing a TinDraft: trimming long border triangles and listing the constraints in sorted
// order, so that output files are byte-identical whatever the thread or tile count.
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>

#include "algo/detail/big_array.hpp"
#include "algo/detail/tin_build.hpp"

namespace dtm::detail {
std::size_t trim_long_edges(TinDraft& draft, double max_edge) {
    const Tin& tin = draft.tin;
    const std::size_t count = tin.triangles.size();
    std::vector<bool> keep(count, true);
    const double limit2 = max_edge * max_edge;
    const auto removable = [&](TriangleIndex t) {
        const Triangle& tri = tin.triangles[t];
        for (int i = 0; i < 3; ++i) {
            const TriangleIndex n = tri.n[i];
            if ((n != no_triangle && keep[n]) || draft.bits(t, i) != 0) continue;
            const Point3& a = tin.vertices[tri.v[(i + 1) % 3]];
            const Point3& b = tin.vertices[tri.v[(i + 2) % 3]];
            const double dx = a.x - b.x;
            const double dy = a.y - b.y;
            if (dx * dx + dy * dy > limit2) return true;
        }
        return false;
    };
    std::vector<TriangleIndex> stack;
    for (TriangleIndex t = 0; t < count; ++t) {
        const auto& n = tin.triangles[t].n;
        if (n[0] == no_triangle || n[1] == no_triangle || n[2] == no_triangle) stack.push_back(t);
    }
    std::size_t removed = 0;
    while (!stack.empty()) {
        const TriangleIndex t = stack.back();
        stack.pop_back();
        if (!keep[t] || !removable(t)) continue;
        keep[t] = false;
        ++removed;
        for (const TriangleIndex n : tin.triangles[t].n) {
            if (n != no_triangle && keep[n]) stack.push_back(n);
        }
    }
    if (removed > 0) compact(draft, keep);
    return removed;
}

void finish_tin(TinDraft& draft) {
    // Triangles are already in canonical order; collect the constraints, per block of triangles
    // in parallel, then sort them by (a, b).
    const std::vector<Triangle>& tris = draft.tin.triangles;
    std::vector<ConstrainedEdge>& constraints = draft.tin.constraints;
    constraints.clear();
    if (!draft.any_constraint()) return;
    // Two passes per block: count, then write at the block's offset (no per-block lists to
    // grow and concatenate).
    constexpr std::size_t block = std::size_t{1} << 16;
    const std::size_t blocks = (tris.size() + block - 1) / block;
    const auto for_each_constraint = [&](std::size_t b, const auto& body) {
        const std::size_t end = std::min(tris.size(), (b + 1) * block);
        for (std::size_t t = b * block; t < end; ++t) {
            const Triangle& tri = tris[t];
            const auto& bits = draft.edge_bits[t];
            for (int j = 0; j < 3; ++j) {
                if (bits[j] == 0) continue;
                const VertexIndex a = tri.v[(j + 1) % 3];
                const VertexIndex c = tri.v[(j + 2) % 3];
                // An interior edge is seen from both sides: keep it from the side where a < c.
                if (a < c || tri.n[j] == no_triangle) {
                    body(ConstrainedEdge{std::min(a, c), std::max(a, c),
                                         constraint_kind_of(bits[j])});
                }
            }
        }
    };
    std::vector<std::size_t> offset(blocks + 1, 0);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        std::size_t count = 0;
        for_each_constraint(b, [&](const ConstrainedEdge&) { ++count; });
        offset[b + 1] = count;
    });
    for (std::size_t b = 0; b < blocks; ++b) offset[b + 1] += offset[b];
    assign_fresh(constraints, offset[blocks], ConstrainedEdge{});  // faulted in on all threads
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        std::size_t at = offset[b];
        for_each_constraint(b, [&](const ConstrainedEdge& e) { constraints[at++] = e; });
    });
    tbb::parallel_sort(constraints.begin(), constraints.end(), [](const auto& x, const auto& y) {
        return x.a < y.a || (x.a == y.a && x.b < y.b);
    });
    draft.edge_bits.clear();
}

}  // namespace dtm::detail
