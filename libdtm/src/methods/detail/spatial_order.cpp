// SPDX-License-Identifier: MIT
// Insertion orders (spatial_order.hpp): splitmix64 shuffles and the Hilbert curve index
// (the classical bit-by-bit xy -> d conversion with quadrant rotations).
#include "methods/detail/spatial_order.hpp"

#include <algorithm>
#include <bit>
#include <utility>

namespace dtm::methods::detail {
namespace {

std::uint64_t splitmix(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/// Position of cell (x, y) along the Hilbert curve of a side-n grid (n a power of two).
std::uint64_t hilbert_index(std::uint32_t n, std::uint32_t x, std::uint32_t y) {
    std::uint64_t d = 0;
    for (std::uint32_t s = n / 2; s > 0; s /= 2) {
        const std::uint32_t rx = (x & s) != 0 ? 1u : 0u;
        const std::uint32_t ry = (y & s) != 0 ? 1u : 0u;
        d += static_cast<std::uint64_t>(s) * s * ((3u * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = n - 1 - x;
                y = n - 1 - y;
            }
            std::swap(x, y);
        }
    }
    return d;
}

}  // namespace

std::vector<VertexIndex> random_order(std::size_t n, std::uint64_t seed) {
    std::vector<VertexIndex> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<VertexIndex>(i);
    std::uint64_t state = seed * 0x2545f4914f6cdd1dull + 1;
    for (std::size_t i = n; i > 1; --i) std::swap(order[i - 1], order[splitmix(state) % i]);
    return order;
}

namespace {

/// Sorts @p keys by their bits from @p low up (those above are zero): a stable LSD radix sort
/// on 16-bit digits (keys equal in those bits keep their order); a comparison sort below a
/// few thousand keys.
void sort_keys(std::vector<std::uint64_t>& keys, int low, int bits) {
    if (keys.size() < 4096) {
        std::stable_sort(keys.begin(), keys.end(), [low](std::uint64_t a, std::uint64_t b) {
            return (a >> low) < (b >> low);
        });
        return;
    }
    std::vector<std::uint64_t> other(keys.size());
    std::vector<std::uint32_t> count(1u << 16);
    for (int shift = low; shift < bits; shift += 16) {
        std::fill(count.begin(), count.end(), 0u);
        for (const std::uint64_t k : keys) ++count[(k >> shift) & 0xffffu];
        std::uint32_t sum = 0;
        for (std::uint32_t& c : count) {
            const std::uint32_t here = c;
            c = sum;
            sum += here;
        }
        for (const std::uint64_t k : keys) other[count[(k >> shift) & 0xffffu]++] = k;
        keys.swap(other);
    }
}

/// Sorts order[begin, end) by the Hilbert index of the points over @p box (ties by index).
void hilbert_sort(const std::vector<Point3>& points,
                  const Box2& box,
                  VertexIndex* begin,
                  VertexIndex* end) {
    constexpr std::uint32_t side = 1u << 16;
    const double w = std::max(box.xmax - box.xmin, 1e-300);
    const double h = std::max(box.ymax - box.ymin, 1e-300);
    const double sx = (side - 1) / w;
    const double sy = (side - 1) / h;
    // The key: the 32-bit Hilbert index above the vertex index, so sorting the keys sorts by
    // Hilbert index, ties by vertex.
    VertexIndex largest = 0;
    for (const VertexIndex* it = begin; it != end; ++it) largest = std::max(largest, *it);
    const int index_bits = static_cast<int>(std::bit_width(largest));
    const std::uint64_t index_mask = (std::uint64_t{1} << index_bits) - 1;
    std::vector<std::uint64_t> keyed;
    keyed.reserve(static_cast<std::size_t>(end - begin));
    for (const VertexIndex* it = begin; it != end; ++it) {
        const Point3& p = points[*it];
        const auto x = static_cast<std::uint32_t>(
            std::clamp((p.x - box.xmin) * sx, 0.0, static_cast<double>(side - 1)));
        const auto y = static_cast<std::uint32_t>(
            std::clamp((p.y - box.ymin) * sy, 0.0, static_cast<double>(side - 1)));
        keyed.push_back(hilbert_index(side, x, y) << index_bits | *it);
    }
    // Vertices already ascending (hilbert_order): a stable sort by the Hilbert index alone
    // keeps ties by vertex; otherwise all bits.
    sort_keys(keyed, std::is_sorted(begin, end) ? index_bits : 0, 32 + index_bits);
    for (std::size_t i = 0; i < keyed.size(); ++i) {
        begin[i] = static_cast<VertexIndex>(keyed[i] & index_mask);
    }
}

Box2 box_of(const std::vector<Point3>& points) {
    Box2 box;
    for (const Point3& p : points) box.add(p);
    return box;
}

}  // namespace

std::vector<VertexIndex> hilbert_order(const std::vector<Point3>& points) {
    std::vector<VertexIndex> order(points.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<VertexIndex>(i);
    hilbert_sort(points, box_of(points), order.data(), order.data() + order.size());
    return order;
}

std::vector<VertexIndex> brio_order(const std::vector<Point3>& points, std::uint64_t seed) {
    std::vector<VertexIndex> order = random_order(points.size(), seed);
    const Box2 box = box_of(points);
    std::size_t end = order.size();
    while (end > 0) {
        const std::size_t begin = end > 64 ? end / 2 : 0;
        hilbert_sort(points, box, order.data() + begin, order.data() + end);
        end = begin;
    }
    return order;
}

void to_insertion_order(std::vector<Point3>& points, const std::vector<VertexIndex>& order) {
    // Along each cycle of the permutation: points[j] <- points[order[j]].
    std::vector<bool> done(points.size());
    for (std::size_t s = 0; s < points.size(); ++s) {
        if (done[s]) continue;
        const Point3 first = points[s];
        std::size_t j = s;
        for (;;) {
            done[j] = true;
            const std::size_t k = order[j];
            if (k == s) {
                points[j] = first;
                break;
            }
            points[j] = points[k];
            j = k;
        }
    }
}

void to_input_numbering(std::vector<Triangle>& triangles,
                        std::vector<Point3>& points,
                        const std::vector<VertexIndex>& order) {
    for (Triangle& t : triangles) {
        for (VertexIndex& v : t.v) v = order[v];
    }
    // Along each cycle: points[order[j]] <- points[j].
    std::vector<bool> done(points.size());
    for (std::size_t s = 0; s < points.size(); ++s) {
        if (done[s]) continue;
        Point3 carried = points[s];
        std::size_t j = s;
        do {
            const std::size_t k = order[j];
            std::swap(carried, points[k]);
            done[k] = true;
            j = k;
        } while (j != s);
    }
}

}  // namespace dtm::methods::detail
