// SPDX-License-Identifier: MIT
//
// Parallel constraint insertion by deterministic reservations.
//
// Segments that touch no other segment (except at shared endpoints) never create vertices and
// never meet a constrained edge of another segment while they are inserted, so the only way two
// of them interact is through the triangles they cross. Each is planned on the current mesh
// without changing it (the walk along the segment: crossed edges and cavity chains, see
// mesh_edit_segment.cpp); every vertex whose ring a plan would change is reserved with the
// segment's priority (its input index, by an atomic minimum); a plan that holds all its
// reservations is applied, concurrently with the other winners, whose vertex sets are disjoint from
// it; the rest try again in the next round on the updated mesh. A plan whose vertices are disjoint
// from every earlier pending plan cannot be changed by them, so the result equals sequential
// insertion in priority order whatever the schedule (Blelloch, Fineman, Gibbons, Shun, "Internally
// deterministic parallel algorithms can be fast", PPoPP 2012). The priority order takes blocks of
// nearby segments one after another and a fixed hash of the input index within a block, so the
// mesh a window works on stays in the caches and polyline chains do not serialise the rounds.
// Before the rounds, the free segments that are already one edge of the mesh (most short
// breakline segments between survey points) are marked in one parallel pass, for every thread
// count (the test is a turn around one endpoint comparing vertex ids): marking changes no
// triangle, so it commutes with every other free insertion. With up to two threads the rest are
// inserted one by one in priority order (the rounds' planning twice and reservations cost more
// than a second thread wins there), with more threads by the rounds; the result is the same.
// Which segments touch others is found on a uniform grid (counting sort by cell, the pairs of
// every cell tested in parallel; segment_grid.hpp). After the pre-pass (segment_split.cpp) none
// touch; any that still did would be inserted afterwards one by one in input order, which keeps
// the vertices added at crossings numbered the same way for every tile and thread count.
#include "algo/detail/constraint_batch.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>

#include "algo/detail/segment_grid.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {

std::vector<bool> find_free_segments(const GhostMesh& m,
                                     const std::vector<InputSegment>& segments) {
    const std::size_t count = segments.size();
    std::vector<bool> free(count, true);
    if (count < 2) return free;
    const auto point = [&m](VertexIndex v) { return m.p(v); };
    const SegmentGrid grid = segment_grid(segments, point);
    const std::size_t cells = grid.cells();
    const std::vector<std::uint32_t>& start = grid.start;
    const std::vector<std::uint32_t>& listed = grid.listed;
    // The pairs of every cell are tested in parallel; a flag only ever goes from free to not
    // free, so the order of the writes does not matter.
    std::vector<std::uint8_t> busy(count, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells, 1024), [&](const auto& range) {
        for (std::size_t c = range.begin(); c < range.end(); ++c) {
            for (std::uint32_t i = start[c]; i < start[c + 1]; ++i) {
                for (std::uint32_t j = i + 1; j < start[c + 1]; ++j) {
                    const std::uint32_t a = listed[i];
                    const std::uint32_t b = listed[j];
                    std::atomic_ref<std::uint8_t> busy_a(busy[a]);
                    std::atomic_ref<std::uint8_t> busy_b(busy[b]);
                    if ((busy_a.load(std::memory_order_relaxed) == 0 ||
                         busy_b.load(std::memory_order_relaxed) == 0) &&
                        segments_touch(point, segments[a], segments[b])) {
                        busy_a.store(1, std::memory_order_relaxed);
                        busy_b.store(1, std::memory_order_relaxed);
                    }
                }
            }
        }
    });
    for (std::size_t i = 0; i < count; ++i) free[i] = busy[i] == 0;
    return free;
}

namespace {

/// The indices of @p key in about ascending order of key: a counting sort on the keys' upper
/// bits, at most 4096 buckets over the window's range (nearby is all the order is for).
void order_by_key(const std::vector<std::uint32_t>& key,
                  std::vector<std::uint32_t>& order,
                  std::vector<std::uint32_t>& count) {
    const auto [lo, hi] = std::minmax_element(key.begin(), key.end());
    const std::uint32_t min = key.empty() ? 0 : *lo;
    const std::uint32_t range = key.empty() ? 0 : *hi - min;
    unsigned shift = 0;
    while ((range >> shift) >= 4096) ++shift;
    count.assign((range >> shift) + 2, 0);
    for (const std::uint32_t k : key) ++count[((k - min) >> shift) + 1];
    for (std::size_t b = 1; b < count.size(); ++b) count[b] += count[b - 1];
    order.resize(key.size());
    for (std::size_t i = 0; i < key.size(); ++i) {
        order[count[(key[i] - min) >> shift]++] = static_cast<std::uint32_t>(i);
    }
}

/// The walks start at scattered vertices of a block: the first reads of the segments a few
/// places after @p k (below @p end) in @p pending are requested ahead.
void prefetch_ahead(const MeshEditor& editor,
                    const std::vector<InputSegment>& segments,
                    const std::vector<std::uint32_t>& pending,
                    std::size_t k,
                    std::size_t end) {
    if (k + 8 < end) {
        const InputSegment& ahead = segments[pending[k + 8]];
        editor.prefetch(ahead.a, ahead.b, false);
    }
    if (k + 3 < end) {
        const InputSegment& ahead = segments[pending[k + 3]];
        editor.prefetch(ahead.a, ahead.b, true);
    }
}

/// Marks, in parallel, the free segments that are already one edge of the mesh and returns
/// the others, in input order. Marking changes no triangle, and no free segment crosses another,
/// so such an edge exists before and after the insertion of every other free segment: marking it
/// now gives the result of marking it in its turn. Short breakline segments between nearby
/// survey points are mostly such edges. The test is a turn around one endpoint comparing vertex
/// ids (a segment is one edge exactly when its endpoints are neighbours).
std::vector<std::uint32_t> mark_existing_edges(MeshEditor& editor,
                                               const std::vector<InputSegment>& segments,
                                               const std::vector<bool>& free) {
    const std::size_t count = segments.size();
    std::vector<std::uint8_t> rest(count, 0);
    // Each edge is one segment's (equal segments are not free), and its two half-edges' bits are
    // bytes of their own: the writes never meet.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) {
                              if (i + 16 < r.end()) {  // the turns start at scattered vertices
                                  editor.prefetch(segments[i + 16].a, segments[i + 16].a, false);
                              }
                              if (i + 6 < r.end()) {
                                  editor.prefetch(segments[i + 6].a, segments[i + 6].b, true);
                              }
                              if (!free[i]) continue;
                              const InputSegment& s = segments[i];
                              const HalfEdge along = editor.edge_between(s.a, s.b);
                              if (along == no_half_edge) {
                                  rest[i] = 1;
                              } else {
                                  editor.mark_edge(along, s.bits);
                              }
                          }
                      });
    std::vector<std::uint32_t> pending;
    for (std::size_t i = 0; i < count; ++i) {
        if (rest[i] != 0) pending.push_back(static_cast<std::uint32_t>(i));
    }
    return pending;
}

}  // namespace

void insert_segments(MeshEditor& editor,
                     const GhostMesh& mesh,
                     const std::vector<InputSegment>& segments,
                     bool all_free,
                     const Progress& progress) {
    const std::vector<bool> free =
        all_free ? std::vector<bool>(segments.size(), true) : find_free_segments(mesh, segments);
    std::vector<std::uint32_t> pending = mark_existing_edges(editor, segments, free);
    std::vector<std::uint32_t> later;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        if (!free[i]) later.push_back(static_cast<std::uint32_t>(i));
    }
    std::size_t done = segments.size() - pending.size() - later.size();
    // Priorities: blocks of nearby segments, in random order within each block. The block is the
    // kernel number of the segment's smaller endpoint divided by 2^16: kernel numbers follow the
    // divide and conquer's cuts, so a block is one region of the mesh, which stays in the caches
    // while its segments are inserted (a fully random order missed the cache at every step).
    // Within a block a fixed hash of the input index orders the segments, so the consecutive
    // segments of a polyline (each shares a vertex with the next, and only the first of a chain of
    // conflicting plans can win a round) do not serialise the rounds. The result equals
    // sequential insertion in this order, whatever the thread count.
    const auto priority = [&](std::uint32_t i) {
        return segment_priority(i, std::min(segments[i].a, segments[i].b));
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(pending.size());
    tbb::parallel_for(std::size_t{0}, pending.size(), [&](std::size_t k) {
        keyed[k] = {priority(pending[k]), pending[k]};
    });
    tbb::parallel_sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < keyed.size(); ++k) pending[k] = keyed[k].second;
    keyed = {};
    const std::size_t total = segments.size();
    const int threads = tbb::this_task_arena::max_concurrency();
    // With one thread (or two, where the rounds' bookkeeping costs more than the second thread
    // wins), plain insertion in priority order gives the very result of the rounds (that is what
    // the reservations guarantee).
    if (threads <= 2) {
        for (std::size_t k = 0; k < pending.size(); ++k) {
            prefetch_ahead(editor, segments, pending, k, pending.size());
            const InputSegment& s = segments[pending[k]];
            editor.insert_segment(s.a, s.b, s.bits);
            if ((k & 4095u) == 0) {
                progress.report(static_cast<double>(done + k) / static_cast<double>(total),
                                "inserting breaklines");
            }
        }
        done += pending.size();
        pending.clear();
    }
    if (!pending.empty()) {
        constexpr std::uint32_t unreserved = 0xffffffffu;
        const std::size_t vertex_count = mesh.points.size();
        std::unique_ptr<std::atomic<std::uint32_t>[]> reserve(
            new std::atomic<std::uint32_t>[vertex_count]);
        for (std::size_t v = 0; v < vertex_count; ++v) reserve[v].store(unreserved);
        const std::size_t window_size = 4096;
        std::vector<MeshEditor::SegmentPlan> plans;
        std::vector<char> applied;
        std::vector<std::uint32_t> next;
        std::vector<std::uint32_t> key;    ///< per window entry: its smaller endpoint
        std::vector<std::uint32_t> order;  ///< the window entries by key (about)
        std::vector<std::uint32_t> count;
        std::size_t first = 0;  // pending[first..] are not yet inserted
        while (first < pending.size()) {
            const std::size_t window = std::min(window_size, pending.size() - first);
            if (plans.size() < window) plans.resize(window);  // reused: each plan is refilled
            applied.assign(window, 0);
            // The window in mesh order, so that each thread takes a run of nearby segments and
            // the threads do not write the same cache lines of the mesh (the priorities, which
            // decide the outcome, stay the window indices k).
            key.resize(window);
            for (std::size_t k = 0; k < window; ++k) {
                const InputSegment& s = segments[pending[first + k]];
                key[k] = std::min(s.a, s.b);
            }
            order_by_key(key, order, count);
            tbb::parallel_for(std::size_t{0}, window, [&](std::size_t at) {
                const std::uint32_t k = order[at];
                const InputSegment& s = segments[pending[first + k]];
                editor.plan_segment(s.a, s.b, plans[k]);
                if (plans[k].crosses_constraint) return;
                for (const VertexId v : plans[k].vertices) {
                    std::uint32_t cur = reserve[v].load(std::memory_order_relaxed);
                    const auto mine = static_cast<std::uint32_t>(k);
                    while (mine < cur && !reserve[v].compare_exchange_weak(cur, mine)) {
                    }
                }
            });
            tbb::parallel_for(std::size_t{0}, window, [&](std::size_t at) {
                const std::uint32_t k = order[at];
                if (plans[k].crosses_constraint) return;
                for (const VertexId v : plans[k].vertices) {
                    if (reserve[v].load(std::memory_order_relaxed) != k) return;
                }
                editor.apply_segment(plans[k], segments[pending[first + k]].bits);
                applied[k] = 1;
            });
            tbb::parallel_for(std::size_t{0}, window, [&](std::size_t k) {
                for (const VertexId v : plans[k].vertices) reserve[v].store(unreserved);
            });
            // Losers keep their order at the front; segments that met a constraint wait.
            next.clear();
            for (std::size_t k = 0; k < window; ++k) {
                if (applied[k]) {
                    ++done;
                } else if (plans[k].crosses_constraint) {
                    later.push_back(pending[first + k]);
                } else {
                    next.push_back(pending[first + k]);
                }
            }
            first += window;
            std::copy(next.begin(), next.end(),
                      pending.begin() + static_cast<std::ptrdiff_t>(first - next.size()));
            first -= next.size();
            progress.report(static_cast<double>(done) / static_cast<double>(total),
                            "inserting breaklines");
        }
    }
    std::sort(later.begin(), later.end());
    for (std::size_t k = 0; k < later.size(); ++k) {
        const InputSegment& s = segments[later[k]];
        editor.insert_segment(s.a, s.b, s.bits);
        if ((k & 1023u) == 0) {
            progress.report(static_cast<double>(done + k) / static_cast<double>(total),
                            "inserting breaklines");
        }
    }
}

}  // namespace dtm::detail
