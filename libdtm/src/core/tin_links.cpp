// SPDX-License-Identifier: MIT
//
// Neighbour links rebuilt from the triangles (link_neighbours), in streaming passes.
//
// Every side of every triangle is a directed edge; it is listed under the smaller of its two
// vertices, so an edge and its twin land in the same row, and a row holding the same pair twice
// in one direction means overlapping or inconsistently oriented triangles. Large TINs number their
// vertices in survey order, not in space, so building the rows directly (a counting sort by
// vertex) writes and reads all over memory, one cache miss per side. Instead:
//   1. the sides are distributed, in triangle order, into buckets of consecutive row vertices (a
//      counting and a scatter pass over blocks of triangles, in parallel, both streaming);
//   2. each bucket (a few thousand vertices, its sides in the caches) is sorted into its rows,
//      where twins are paired: each side's entry gets the triangle across it;
//   3. each block of triangles gathers its sides' entries from every bucket (the scatter left
//      them in one run per block and bucket) and writes its links.
// A row keeps its sides in triangle order, so pairs, and the first error reported (in the row of
// the smallest vertex), are those of one sequential pass.
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {
namespace {

constexpr std::size_t block = std::size_t{1} << 14;  ///< triangles per block

/// One side of a triangle, in its bucket.
struct Side {
    std::uint32_t other;   ///< the larger vertex; once paired, the triangle across (or none)
    std::uint32_t code;    ///< 3 t + s
    std::uint16_t row;     ///< the smaller vertex, less the bucket's first
    std::uint8_t forward;  ///< runs from the smaller vertex to the larger (2: paired)
};

/// The first overlap found: in the row of vertex `row`, the edge from -> to.
struct Overlap {
    std::size_t row = std::numeric_limits<std::size_t>::max();
    std::size_t from = 0;
    std::size_t to = 0;
};

}  // namespace

void link_neighbours(Tin& tin) {
    const std::size_t n = tin.vertices.size();
    const std::size_t count = tin.triangles.size();
    if (count > std::numeric_limits<std::uint32_t>::max() / 3) throw InputError("too many faces");
    if (count == 0) return;
    // 2^12 row vertices per bucket (about 6 sides each), at most 2^10 buckets until the rows
    // reach 2^16 vertices (Side::row), more buckets beyond
    unsigned shift = 12;
    while ((n >> shift) >= 1024 && shift < 16) ++shift;
    const std::size_t buckets = (n >> shift) + 1;
    const std::size_t blocks = (count + block - 1) / block;
    const auto for_block = [&](std::size_t b, auto&& body) {
        const std::size_t end = std::min(count, (b + 1) * block);
        for (std::size_t t = b * block; t < end; ++t) {
            const auto& v = tin.triangles[t].v;
            for (std::uint32_t s = 0; s < 3; ++s) body(t, s, v[(s + 1) % 3], v[(s + 2) % 3]);
        }
    };
    // 1. Sides per (bucket, block), then where each run goes: buckets in order, blocks in order
    // within a bucket, so that a bucket lists its sides in triangle order.
    std::vector<std::uint32_t> at(buckets * blocks, 0);  // bucket-major
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        for_block(b, [&](std::size_t, std::uint32_t, VertexIndex a, VertexIndex c) {
            ++at[(std::min(a, c) >> shift) * blocks + b];
        });
    });
    std::uint32_t sum = 0;
    for (std::uint32_t& run : at) {
        const std::uint32_t here = run;
        run = sum;
        sum += here;
    }
    std::vector<Side> sides(sum);
    {
        std::vector<std::uint32_t> next = at;
        tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
            for_block(b, [&](std::size_t t, std::uint32_t s, VertexIndex a, VertexIndex c) {
                const VertexIndex low = std::min(a, c);
                sides[next[(low >> shift) * blocks + b]++] = {
                    std::max(a, c), static_cast<std::uint32_t>(3 * t + s),
                    static_cast<std::uint16_t>(low & ((1u << shift) - 1)),
                    a < c ? std::uint8_t{1} : std::uint8_t{0}};
            });
        });
    }
    // 2. Pairs within each bucket's rows.
    struct Rows {
        std::vector<std::uint32_t> first;   ///< per row vertex of the bucket, + 1
        std::vector<std::uint32_t> listed;  ///< side indices, row by row
    };
    tbb::enumerable_thread_specific<Rows> scratch;
    tbb::enumerable_thread_specific<Overlap> overlaps;
    tbb::parallel_for(std::size_t{0}, buckets, [&](std::size_t q) {
        const std::size_t lo = at[q * blocks];
        const std::size_t hi = q + 1 < buckets ? at[(q + 1) * blocks] : sides.size();
        Rows& r = scratch.local();
        const std::size_t width = std::size_t{1} << shift;
        r.first.assign(width + 1, 0);
        for (std::size_t i = lo; i < hi; ++i) ++r.first[sides[i].row + 1];
        for (std::size_t v = 0; v < width; ++v) r.first[v + 1] += r.first[v];
        r.listed.resize(hi - lo);
        for (std::size_t i = lo; i < hi; ++i) {
            r.listed[r.first[sides[i].row]++] = static_cast<std::uint32_t>(i);
        }
        // r.first[v] is now the end of row v (the start of row v + 1). Each row is checked as
        // one sequential pass would (the first pair of sides with the same vertices and the same
        // direction is the error), then its twins are paired.
        std::size_t start = 0;
        Overlap& found = overlaps.local();
        for (std::size_t v = 0; v < width; ++v) {
            const std::size_t end = r.first[v];
            const std::size_t row = (q << shift) + v;
            for (std::size_t k = start; k < end && row < found.row; ++k) {
                const Side& x = sides[r.listed[k]];
                for (std::size_t j = k + 1; j < end; ++j) {
                    const Side& y = sides[r.listed[j]];
                    if (y.other == x.other && y.forward == x.forward) {
                        found = {row, x.forward ? row : x.other, x.forward ? x.other : row};
                        break;
                    }
                }
            }
            for (std::size_t k = start; k < end; ++k) {
                Side& x = sides[r.listed[k]];
                if (x.forward > 1) continue;  // paired already
                std::uint32_t across = no_triangle;
                for (std::size_t j = k + 1; j < end; ++j) {
                    Side& y = sides[r.listed[j]];
                    if (y.forward > 1 || y.other != x.other) continue;
                    across = y.code / 3;
                    y.other = x.code / 3;
                    y.forward = 2;
                    break;
                }
                x.other = across;
                x.forward = 2;
            }
            start = end;
        }
    });
    Overlap first;
    for (const Overlap& o : overlaps) {
        if (o.row < first.row) first = o;
    }
    if (first.row != std::numeric_limits<std::size_t>::max()) {
        throw InputError("edge " + std::to_string(first.from) + "-" + std::to_string(first.to) +
                         " is used twice in the same direction (faces overlap or are not "
                         "consistently oriented)");
    }
    // 3. Every block writes its own triangles' links.
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        for (std::size_t q = 0; q < buckets; ++q) {
            const std::size_t end = b + 1 < blocks    ? at[q * blocks + b + 1]
                                    : q + 1 < buckets ? at[(q + 1) * blocks]
                                                      : sides.size();
            for (std::size_t i = at[q * blocks + b]; i < end; ++i) {
                tin.triangles[sides[i].code / 3].n[sides[i].code % 3] = sides[i].other;
            }
        }
    });
}

}  // namespace dtm
