// SPDX-License-Identifier: MIT
//
// Exact duplicate positions by an open-addressing hash table of 32-bit point indices on the
// coordinate bits. One thread: the first occurrence of a position claims its slot. Several: every
// thread inserts at once; a slot, once claimed, only ever holds that position, and among equal
// positions an atomic minimum keeps the smallest index, so the table ends as the sequential one.
// Used by the duplicate merge of triangulate() and the input summary's count.
#include "algo/detail/exact_duplicates.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <bit>
#include <cstdint>

#include "algo/detail/big_array.hpp"

namespace dtm::detail {
namespace {

/// Slot of p's position in a table of @p capacity slots (a power of two); -0.0 and 0.0 alike.
std::size_t slot_of(const Point3& p, std::size_t capacity)
{
    const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); };
    const std::uint64_t bx = bits(p.x);
    const std::uint64_t by = bits(p.y);
    std::uint64_t h = (bx * 0x9e3779b97f4a7c15ull) ^ (by + 0x7f4a7c159e3779b9ull + (bx << 6));
    h ^= h >> 29;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 32;
    return static_cast<std::size_t>(h) & (capacity - 1);
}

/// One thread: the first occurrence of a position claims its slot.
std::vector<VertexIndex> first_occurrences_sequential(std::span<const Point3> pts,
                                                      std::vector<VertexIndex>& table)
{
    const std::size_t n = pts.size();
    const std::size_t capacity = table.size();
    std::vector<VertexIndex> rep(n);
    constexpr std::size_t ahead = 16;  // prefetch distance: the table is far larger than the caches
    for (std::size_t i = 0; i < n; ++i) {
        if (i + ahead < n) __builtin_prefetch(&table[slot_of(pts[i + ahead], capacity)]);
        rep[i] = static_cast<VertexIndex>(i);
        for (std::size_t slot = slot_of(pts[i], capacity);; slot = (slot + 1) & (capacity - 1)) {
            const VertexIndex j = table[slot];
            if (j == no_vertex) {
                table[slot] = static_cast<VertexIndex>(i);
                break;
            }
            if (pts[j].x == pts[i].x && pts[j].y == pts[i].y) {
                rep[i] = j;
                break;
            }
        }
    }
    return rep;
}

/// All threads at once (see the file comment); a second parallel pass reads the first
/// occurrences when any position repeats.
std::vector<VertexIndex> first_occurrences_parallel(std::span<const Point3> pts,
                                                    std::vector<VertexIndex>& table)
{
    const std::size_t n = pts.size();
    const std::size_t capacity = table.size();
    std::atomic<bool> repeats{false};
    const auto find = [&](std::size_t i, bool claim) {
        for (std::size_t slot = slot_of(pts[i], capacity);; slot = (slot + 1) & (capacity - 1)) {
            std::atomic_ref<VertexIndex> cell(table[slot]);
            VertexIndex j = cell.load(std::memory_order_acquire);
            if (j == no_vertex) {
                if (!claim) return slot;  // cannot happen after the first pass
                if (cell.compare_exchange_strong(j, static_cast<VertexIndex>(i),
                                                 std::memory_order_acq_rel)) {
                    return slot;
                }
                // j now holds the winner: fall through and compare with it
            }
            if (pts[j].x == pts[i].x && pts[j].y == pts[i].y) {
                if (claim) {
                    repeats.store(true, std::memory_order_relaxed);
                    while (i < j && !cell.compare_exchange_weak(j, static_cast<VertexIndex>(i),
                                                                std::memory_order_acq_rel)) {
                    }
                }
                return slot;
            }
        }
    };
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1 << 14), [&](const auto& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) find(i, true);
    });
    std::vector<VertexIndex> rep(n);
    const bool any = repeats.load();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1 << 14), [&](const auto& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
            rep[i] = any ? table[find(i, false)] : static_cast<VertexIndex>(i);
        }
    });
    return rep;
}

}  // namespace

std::vector<VertexIndex> first_occurrences(std::span<const Point3> pts)
{
    std::size_t capacity = 16;  // a power of two, at least twice the points: half the table empty
    while (capacity < 2 * pts.size()) capacity *= 2;
    std::vector<VertexIndex> table;
    reserve_huge(table, capacity);
    table.resize(capacity, no_vertex);
    if (tbb::this_task_arena::max_concurrency() > 1 && pts.size() > 100'000) {
        return first_occurrences_parallel(pts, table);
    }
    return first_occurrences_sequential(pts, table);
}

}  // namespace dtm::detail
