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
// Which segments touch others is found on a uniform grid (counting sort by cell, the pairs of
// every cell tested in parallel). Segments that cross, overlap or touch others
// are inserted afterwards one by one in input order, which keeps the vertices added at
// crossings numbered the same way for every tile and thread count.
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

#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

bool between(const Point2& a, const Point2& b, const Point2& q) {
    return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y &&
           q.y <= std::max(a.y, b.y);
}

/// Segments s and t (kernel vertex ids) meet anywhere but at one shared endpoint.
bool touch(const GhostMesh& m, const InputSegment& s, const InputSegment& t) {
    const VertexId shared =
        s.a == t.a || s.a == t.b ? s.a : (s.b == t.a || s.b == t.b ? s.b : no_vertex);
    if (shared != no_vertex) {
        if ((s.a == t.a && s.b == t.b) || (s.a == t.b && s.b == t.a)) return true;
        const VertexId x = s.a == shared ? s.b : s.a;
        const VertexId y = t.a == shared ? t.b : t.a;
        if (geom::orient2d(m.p(shared), m.p(x), m.p(y)) != 0) return false;
        // Collinear: they overlap unless they leave the shared endpoint in opposite directions.
        const Point2 &c = m.p(shared), &px = m.p(x), &py = m.p(y);
        return ((px.x > c.x) == (py.x > c.x)) && ((px.x < c.x) == (py.x < c.x)) &&
               ((px.y > c.y) == (py.y > c.y)) && ((px.y < c.y) == (py.y < c.y));
    }
    const Point2 &a = m.p(s.a), &b = m.p(s.b), &c = m.p(t.a), &d = m.p(t.b);
    const int o1 = geom::orient2d(a, b, c);
    const int o2 = geom::orient2d(a, b, d);
    const int o3 = geom::orient2d(c, d, a);
    const int o4 = geom::orient2d(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && between(a, b, c)) || (o2 == 0 && between(a, b, d)) ||
           (o3 == 0 && between(c, d, a)) || (o4 == 0 && between(c, d, b));
}

}  // namespace

std::vector<bool> find_free_segments(const GhostMesh& m,
                                     const std::vector<InputSegment>& segments) {
    const std::size_t count = segments.size();
    std::vector<bool> free(count, true);
    if (count < 2) return free;
    // Uniform grid over the segments' extent, about one cell per segment; each segment is
    // listed in every cell its bounding box covers, and pairs sharing a cell are tested.
    // The segments' boxes first, in parallel (their endpoints are scattered over the mesh's
    // points); everything after reads them in order.
    std::vector<std::array<double, 4>> boxes(count);  // x min, x max, y min, y max
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
        const Point2 &a = m.p(segments[i].a), &b = m.p(segments[i].b);
        boxes[i] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)};
    });
    Box2 box;
    double total_length = 0.0;
    for (const auto& [x0, x1, y0, y1] : boxes) {
        box.add(x0, y0);
        box.add(x1, y1);
        total_length += (x1 - x0) + (y1 - y0);
    }
    const double extent = std::max(box.xmax - box.xmin, box.ymax - box.ymin);
    const double cell = std::max(
        {total_length / static_cast<double>(count), extent / 4096.0, extent * 1e-12, 1e-300});
    const auto cols = static_cast<std::size_t>((box.xmax - box.xmin) / cell) + 1;
    const auto rows = static_cast<std::size_t>((box.ymax - box.ymin) / cell) + 1;
    const auto cell_of = [&](double v, double lo, std::size_t n) {
        return std::min(static_cast<std::size_t>((v - lo) / cell), n - 1);
    };
    // Bucket the segments by cell (counting sort: cell-major lists), then test the pairs of every
    // cell in parallel; a flag only ever goes from free to not free, so the order of the writes
    // does not matter.
    const auto cell_range = [&](std::size_t i) {
        const auto& [x0, x1, y0, y1] = boxes[i];
        return std::array<std::size_t, 4>{cell_of(x0, box.xmin, cols), cell_of(x1, box.xmin, cols),
                                          cell_of(y0, box.ymin, rows), cell_of(y1, box.ymin, rows)};
    };
    const std::size_t cells = cols * rows;
    std::vector<std::uint32_t> start(cells + 1, 0);
    for (std::size_t i = 0; i < count; ++i) {
        const auto [c0, c1, r0, r1] = cell_range(i);
        for (std::size_t r = r0; r <= r1; ++r) {
            for (std::size_t c = c0; c <= c1; ++c) ++start[r * cols + c + 1];
        }
    }
    for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
    std::vector<std::uint32_t> listed(start[cells]);
    {
        std::vector<std::uint32_t> at(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < count; ++i) {
            const auto [c0, c1, r0, r1] = cell_range(i);
            for (std::size_t r = r0; r <= r1; ++r) {
                for (std::size_t c = c0; c <= c1; ++c) {
                    listed[at[r * cols + c]++] = static_cast<std::uint32_t>(i);
                }
            }
        }
    }
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
                        touch(m, segments[a], segments[b])) {
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

}  // namespace

void insert_segments(MeshEditor& editor,
                     const GhostMesh& mesh,
                     const std::vector<InputSegment>& segments,
                     const Progress& progress) {
    const std::vector<bool> free = find_free_segments(mesh, segments);
    std::vector<std::uint32_t> pending;
    std::vector<std::uint32_t> later;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        (free[i] ? pending : later).push_back(static_cast<std::uint32_t>(i));
    }
    // Priorities: blocks of nearby segments, in random order within each block. The block is the
    // kernel number of the segment's smaller endpoint divided by 2^16: kernel numbers follow the
    // divide and conquer's cuts, so a block is one region of the mesh, which stays in the caches
    // while its segments are inserted (a fully random order missed the cache at every step).
    // Within a block a fixed hash of the input index orders the segments, so the consecutive
    // segments of a polyline (each shares a vertex with the next, and only the first of a chain of
    // conflicting plans can win a round) do not serialise the rounds. The result equals
    // sequential insertion in this order, whatever the thread count.
    const auto priority = [&](std::uint32_t i) {
        std::uint64_t h = i + 0x9e3779b97f4a7c15ull;
        h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
        h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
        h ^= h >> 31;
        const std::uint64_t block = std::min(segments[i].a, segments[i].b) >> 16;
        return (block << 32) | (h & 0xffffffffull);
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(pending.size());
    tbb::parallel_for(std::size_t{0}, pending.size(), [&](std::size_t k) {
        keyed[k] = {priority(pending[k]), pending[k]};
    });
    tbb::parallel_sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < keyed.size(); ++k) pending[k] = keyed[k].second;
    keyed = {};
    const std::size_t total = segments.size();
    std::size_t done = 0;
    // With one thread, plain insertion in priority order gives the very result of the rounds
    // (that is what the reservations guarantee) without their bookkeeping.
    if (tbb::this_task_arena::max_concurrency() == 1) {
        for (std::size_t k = 0; k < pending.size(); ++k) {
            // The walks start at scattered vertices of the block: their first reads are
            // requested a few segments ahead.
            if (k + 8 < pending.size()) {
                const InputSegment& ahead = segments[pending[k + 8]];
                editor.prefetch(ahead.a, ahead.b, false);
            }
            if (k + 3 < pending.size()) {
                const InputSegment& ahead = segments[pending[k + 3]];
                editor.prefetch(ahead.a, ahead.b, true);
            }
            const InputSegment& s = segments[pending[k]];
            editor.insert_segment(s.a, s.b, s.bits);
            if ((k & 4095u) == 0) {
                progress.report(static_cast<double>(k) / static_cast<double>(total),
                                "inserting breaklines");
            }
        }
        done = pending.size();
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
