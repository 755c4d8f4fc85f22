// SPDX-License-Identifier: MIT
//
// Exact duplicate positions by hashing, partitioned so that every hash table fits the caches.
//
// One hash table over all points makes one cache miss per point once it outgrows the caches
// (10^7 points: a 128 MB table, 0.8 s on one thread). Instead the points are first distributed by
// the top bits of their hash into partitions of about 2^13 points (a counting pass and a scatter
// pass, both streaming, in parallel over blocks of points), each partition keeping its points
// in index order; then every partition is searched with its own small open-addressing table, in
// parallel over the partitions. Equal positions have equal hashes, so they meet in one partition,
// where the first of them in index order claims the slot: the result is the same for every thread
// count. A table entry carries 32 further bits of the hash, so the points' coordinates are read
// only for equal hashes (duplicates, and collisions of 64-bit hashes).
//
// Used by the duplicate merge of triangulate() and the input summary's count.
#include "algo/detail/exact_duplicates.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cstdint>

#include "algo/detail/big_array.hpp"

namespace dtm::detail {
namespace {

/// 64-bit hash of p's position; -0.0 and 0.0 alike.
std::uint64_t hash_of(const Point3& p) {
    const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); };
    const std::uint64_t bx = bits(p.x);
    const std::uint64_t by = bits(p.y);
    std::uint64_t h = (bx * 0x9e3779b97f4a7c15ull) ^ (by + 0x7f4a7c159e3779b9ull + (bx << 6));
    h ^= h >> 29;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 32;
    h *= 0x94d049bb133111ebull;
    h ^= h >> 31;
    return h;
}

bool same_position(const Point3& a, const Point3& b) { return a.x == b.x && a.y == b.y; }

/// A point in its partition: the low 32 bits of its hash and its index.
struct Entry {
    std::uint32_t hash;
    VertexIndex index;
};

constexpr std::size_t block = std::size_t{1} << 16;  ///< points per block of the two passes

/// Searches one partition (its entries in index order) with the open-addressing @p table.
void search_partition(std::span<const Point3> pts,
                      const Entry* entries,
                      std::size_t count,
                      std::vector<Entry>& table,
                      BigArray<VertexIndex>& first) {
    std::size_t capacity = 16;  // a power of two, at least twice the entries
    while (capacity < 2 * count) capacity *= 2;
    table.assign(capacity, Entry{0, no_vertex});
    for (std::size_t e = 0; e < count; ++e) {
        const Entry entry = entries[e];
        for (std::size_t slot = entry.hash & (capacity - 1);; slot = (slot + 1) & (capacity - 1)) {
            const Entry held = table[slot];
            if (held.index == no_vertex) {
                table[slot] = entry;
                break;
            }
            if (held.hash == entry.hash && same_position(pts[held.index], pts[entry.index])) {
                first[entry.index] = held.index;
                break;
            }
        }
    }
}

}  // namespace

BigArray<VertexIndex> first_occurrences(std::span<const Point3> pts) {
    const std::size_t n = pts.size();
    BigArray<VertexIndex> first(n);
    unsigned partition_bits = 0;  // partitions of 2^12 to 2^13 points, at most 2^10 of them
    while (partition_bits < 10 && (n >> partition_bits) > (std::size_t{1} << 13)) ++partition_bits;
    const std::size_t partitions = std::size_t{1} << partition_bits;
    const unsigned shift = 64 - partition_bits;
    const auto partition_of = [&](std::uint64_t h) {
        return partition_bits == 0 ? std::size_t{0} : static_cast<std::size_t>(h >> shift);
    };
    // 1. Points per (block, partition).
    const std::size_t blocks = (n + block - 1) / block;
    std::vector<std::uint32_t> offset(blocks * partitions, 0);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        std::uint32_t* count = offset.data() + b * partitions;
        const std::size_t end = std::min(n, (b + 1) * block);
        for (std::size_t i = b * block; i < end; ++i) ++count[partition_of(hash_of(pts[i]))];
    });
    // Where each block's points of each partition go: partitions in order, blocks in order
    // within a partition, so every partition lists its points by increasing index.
    std::vector<std::size_t> start(partitions + 1, 0);
    std::size_t sum = 0;
    for (std::size_t p = 0; p < partitions; ++p) {
        start[p] = sum;
        for (std::size_t b = 0; b < blocks; ++b) {
            const std::uint32_t here = offset[b * partitions + p];
            offset[b * partitions + p] = static_cast<std::uint32_t>(sum);
            sum += here;
        }
    }
    start[partitions] = sum;
    // 2. Scatter; first[i] = i meanwhile (duplicates are overwritten in 3).
    BigArray<Entry> entries(n);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        std::uint32_t* next = offset.data() + b * partitions;
        const std::size_t end = std::min(n, (b + 1) * block);
        for (std::size_t i = b * block; i < end; ++i) {
            const std::uint64_t h = hash_of(pts[i]);
            entries[next[partition_of(h)]++] = {static_cast<std::uint32_t>(h),
                                                static_cast<VertexIndex>(i)};
            first[i] = static_cast<VertexIndex>(i);
        }
    });
    // 3. Every partition on its own.
    tbb::enumerable_thread_specific<std::vector<Entry>> tables;
    tbb::parallel_for(std::size_t{0}, partitions, [&](std::size_t p) {
        search_partition(pts, entries.data() + start[p], start[p + 1] - start[p], tables.local(),
                         first);
    });
    return first;
}

}  // namespace dtm::detail
