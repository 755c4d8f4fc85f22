// SPDX-License-Identifier: MIT
// Lawson's local optimisation procedure (LOP) under a criterion.
//
// C. L. Lawson, "Software for C1 surface interpolation" (1977): flip the diagonal of a convex
// quadrilateral when the criterion prefers the other one, until every quadrilateral is
// optimal (a locally optimal triangulation, thesis 000 §2.3; slides 004 "lokální prohazování",
// "usable with any local criterion"). Dyn, Levin and Rippa (1990) run the same loop with
// data-dependent edge costs. Constrained edges (breaklines, boundaries) are never flipped.
//
// Order: the initial scan marks every improvable edge (in parallel: a pure read); the marked
// edges are queued in triangle order and processed first in, first out. A flip re-queues the
// edges whose test it can change: the four sides of its quadrilateral, and for the data-dependent
// criteria (whose test reads the triangles beyond the sides) the edges of those four triangles.
// A queued edge is named by a triangle and its two vertices; entries made stale by later flips are
// skipped. Termination and the flip budget: optimize.hpp.
#include "dtm/algo/optimize.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <deque>

#include "algo/detail/tin_flip.hpp"

namespace dtm {
namespace {

struct QueuedEdge {
    TriangleIndex t;
    VertexIndex a;
    VertexIndex b;
};

/// The slot of edge {a, b} in triangle t, or -1.
int slot_of(const Triangle& t, VertexIndex a, VertexIndex b) noexcept {
    for (int s = 0; s < 3; ++s) {
        const VertexIndex p = t.v[(s + 1) % 3];
        const VertexIndex q = t.v[(s + 2) % 3];
        if ((p == a && q == b) || (p == b && q == a)) return s;
    }
    return -1;
}

std::vector<std::uint8_t> scan(const Tin& tin,
                               const detail::ConstrainedEdgeSet& constrained,
                               Criterion criterion,
                               unsigned threads) {
    std::vector<std::uint8_t> marks(tin.triangles.size() * 3, 0);
    auto body = [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            const Triangle& t = tin.triangles[i];
            for (int s = 0; s < 3; ++s) {
                if (t.n[s] == no_triangle || t.n[s] < i) continue;  // each edge once
                marks[3 * i + s] = detail::edge_improvable(
                    tin, constrained, static_cast<TriangleIndex>(i), s, criterion);
            }
        }
    };
    const tbb::blocked_range<std::size_t> all(0, tin.triangles.size(), 1024);
    if (threads > 0) {
        tbb::task_arena arena(static_cast<int>(threads));
        arena.execute([&] { tbb::parallel_for(all, body); });
    } else {
        tbb::parallel_for(all, body);
    }
    return marks;
}

void push_edges_of(std::deque<QueuedEdge>& queue, const Tin& tin, TriangleIndex t) {
    if (t == no_triangle) return;
    const Triangle& tri = tin.triangles[t];
    for (int s = 0; s < 3; ++s) {
        queue.push_back({t, tri.v[(s + 1) % 3], tri.v[(s + 2) % 3]});
    }
}

}  // namespace

OptimizeStats optimize_tin(Tin& tin, const OptimizeOptions& options, const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    OptimizeStats stats;
    stats.criterion = options.criterion;
    if (options.criterion == Criterion::delaunay || tin.triangles.empty()) return stats;
    const Criterion criterion = options.criterion;
    stats.before = summarize_quality(quality_vector(tin, criterion));
    const detail::ConstrainedEdgeSet constrained(tin);
    progress.report(0.0, "optimize");

    std::deque<QueuedEdge> queue;
    {
        const std::vector<std::uint8_t> marks = scan(tin, constrained, criterion, options.threads);
        for (std::size_t k = 0; k < marks.size(); ++k) {
            if (marks[k] == 0) continue;
            const auto t = static_cast<TriangleIndex>(k / 3);
            const int s = static_cast<int>(k % 3);
            const Triangle& tri = tin.triangles[t];
            queue.push_back({t, tri.v[(s + 1) % 3], tri.v[(s + 2) % 3]});
        }
    }
    stats.improvable_before = queue.size();
    stats.edges_tested = tin.triangles.size() * 3 / 2;

    const std::uint64_t budget =
        options.max_flips > 0 ? options.max_flips : 50 * tin.triangles.size() + 1'000'000;
    const bool wide = is_data_dependent(criterion);
    std::uint64_t popped = 0;
    while (!queue.empty()) {
        if ((++popped & 4095) == 0) progress.check();
        const QueuedEdge e = queue.front();
        queue.pop_front();
        const int s = slot_of(tin.triangles[e.t], e.a, e.b);
        if (s < 0) continue;  // flipped away since it was queued
        ++stats.edges_tested;
        if (!detail::edge_improvable(tin, constrained, e.t, s, criterion)) continue;
        if (stats.flips == budget) {
            stats.converged = false;
            break;
        }
        const detail::EdgeQuad q = detail::edge_quad(tin, e.t, s);
        detail::flip(tin, q);
        ++stats.flips;
        // t = (c, a, d), u = (d, b, c): the four sides.
        queue.push_back({q.t, q.c, q.a});
        queue.push_back({q.t, q.a, q.d});
        queue.push_back({q.u, q.d, q.b});
        queue.push_back({q.u, q.b, q.c});
        if (wide) {
            for (const TriangleIndex n : {tin.triangles[q.t].n[0], tin.triangles[q.t].n[2],
                                          tin.triangles[q.u].n[0], tin.triangles[q.u].n[2]}) {
                push_edges_of(queue, tin, n);
            }
        }
    }
    stats.improvable_after = count_improvable_edges(tin, criterion);  // the local-optimality check
    stats.after = summarize_quality(quality_vector(tin, criterion));
    progress.report(1.0, "optimize");
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace dtm
