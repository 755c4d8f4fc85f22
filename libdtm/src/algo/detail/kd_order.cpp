// SPDX-License-Identifier: MIT
//
// The divide and conquer's point order for a subtree that fits the caches, in rank space.
//
// Selecting a median for every node of a subtree costs one partition pass per level, and below a
// few thousand points the selection's per-node work and the strips' sorts dominate the whole
// split. Instead, order_subtree sorts the subtree's points once by x and once by y (radix sorts
// of monotone 32-bit keys; equal keys are ordered by the exact comparison afterwards), replaces
// every point by its pair of ranks (rx, ry), and cuts the ranks:
//   - the points stay sorted by rx within every node (the partitions are stable), so a cut by x
//     takes the first half and costs nothing, and every strip comes out sorted by x;
//   - a cut by y needs the median of ry in the node: its ry values lie in the y range the node
//     inherited from the cuts above, so a bitmap over that range and a popcount scan find it,
//     and one stable branch-free pass partitions the node.
// Ranks are exact (the order Before<axis> of the points), so the sets on each side of every cut,
// and hence the final order, are those of median selection.
//
// Reference: J. L. Bentley, "Multidimensional binary search trees used for associative
// searching", CACM 18(9), 1975 (the alternating median cuts of a k-d tree); presorting both
// coordinates once to build it in O(n log n) is the classical construction.
#include "algo/detail/kd_order.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

namespace dtm::detail {

struct SubtreeScratch::Buffers {
    std::vector<std::uint64_t> by_x;  ///< key << 32 | index, sorted by x
    std::vector<std::uint64_t> by_y;  ///< key << 32 | index, sorted by y
    std::vector<std::uint64_t> sort_tmp;
    std::vector<std::uint16_t> y_rank;  ///< per index
    std::vector<std::uint32_t> ranks;   ///< rx << 16 | ry
    std::vector<std::uint32_t> ranks_tmp;
    std::vector<std::uint64_t> bitmap;  ///< all zero between uses
    std::vector<KernelPoint> points;

    std::size_t size;  ///< the largest subtree they hold

    explicit Buffers(std::size_t n)
        : by_x(n),
          by_y(n),
          sort_tmp(n),
          y_rank(n),
          ranks(n),
          ranks_tmp(n + 2),
          bitmap(n / 64 + 1, 0),
          points(n),
          size(n) {}
};

SubtreeScratch::SubtreeScratch() = default;
SubtreeScratch::~SubtreeScratch() = default;
SubtreeScratch::SubtreeScratch(SubtreeScratch&&) noexcept = default;
SubtreeScratch& SubtreeScratch::operator=(SubtreeScratch&&) noexcept = default;

SubtreeScratch::Buffers& SubtreeScratch::get(std::size_t n) {
    // Sized to the subtree (a power of two, at most capacity), grown when a larger one comes:
    // a small triangulation does not allocate and clear the whole MiB.
    if (!buffers_ || buffers_->size < n) {
        buffers_.reset();
        buffers_ = std::make_unique<Buffers>(std::min(capacity, std::bit_ceil(n)));
    }
    return *buffers_;
}

namespace {

/// A monotone map of one coordinate to 32 bits: v < w gives key(v) <= key(w) (a subtraction and
/// a multiplication by a positive number, each correctly rounded, never reverse an order), so
/// sorting by key and then ordering equal keys exactly sorts exactly.
class KeyMap {
public:
    KeyMap(double lo, double hi) : lo_(lo) {
        const double range = hi - lo;
        const double scale = 4294967040.0 / range;  // just below 2^32
        if (range > 0.0 && std::isfinite(range) && std::isfinite(scale)) scale_ = scale;
    }
    [[nodiscard]] std::uint64_t operator()(double v) const noexcept {
        const double k = (v - lo_) * scale_;
        return k < 4294967295.0 ? static_cast<std::uint64_t>(k) : 0xffffffffu;
    }

private:
    double lo_;
    double scale_ = 0.0;  // every key 0: the exact order does all the work
};

constexpr std::uint32_t index_of(std::uint64_t record) noexcept {
    return static_cast<std::uint32_t>(record);
}

/// Sorts v[0, n) by the high 32 bits, stably (LSD radix, three digits of 11 bits; a digit equal
/// for every record is skipped).
void radix_sort_by_key(std::uint64_t* v, std::uint64_t* tmp, std::size_t n) {
    constexpr unsigned digit_bits = 11;
    constexpr std::size_t buckets = std::size_t{1} << digit_bits;
    std::uint32_t count[3][buckets] = {};
    for (std::size_t i = 0; i < n; ++i) {
        const auto key = static_cast<std::uint32_t>(v[i] >> 32);
        ++count[0][key & (buckets - 1)];
        ++count[1][(key >> digit_bits) & (buckets - 1)];
        ++count[2][key >> (2 * digit_bits)];
    }
    std::uint64_t* src = v;
    std::uint64_t* dst = tmp;
    for (unsigned pass = 0; pass < 3; ++pass) {
        const unsigned shift = 32 + pass * digit_bits;
        const auto digit = [shift](std::uint64_t r) {
            return static_cast<std::size_t>(r >> shift) & (buckets - 1);
        };
        std::uint32_t* c = count[pass];
        if (c[digit(src[0])] == n) continue;
        std::uint32_t sum = 0;
        for (std::size_t b = 0; b < buckets; ++b) {
            const std::uint32_t here = c[b];
            c[b] = sum;
            sum += here;
        }
        for (std::size_t i = 0; i < n; ++i) dst[c[digit(src[i])]++] = src[i];
        std::swap(src, dst);
    }
    if (src != v) std::memcpy(v, src, n * sizeof(std::uint64_t));
}

/// Orders the runs of equal keys in v[0, n) (sorted by key) by @p less on the points.
template <class Less>
void order_equal_keys(std::uint64_t* v, std::size_t n, const KernelPoint* p, Less less) {
    for (std::size_t i = 0; i + 1 < n;) {
        if ((v[i] >> 32) != (v[i + 1] >> 32)) {
            ++i;
            continue;
        }
        std::size_t j = i + 2;
        while (j < n && (v[j] >> 32) == (v[i] >> 32)) ++j;
        std::sort(v + i, v + j, [&](std::uint64_t a, std::uint64_t b) {
            return less(p[index_of(a)], p[index_of(b)]);
        });
        i = j;
    }
}

/// Cuts the ranks r[0, n) (sorted by rx; every ry in [y_lo, y_hi)) as the recursion does.
void cut_ranks(std::uint32_t* r,
               std::size_t n,
               int cut,
               std::uint32_t y_lo,
               std::uint32_t y_hi,
               SubtreeScratch::Buffers& s) {
    while (n > strip_size) {
        const std::size_t half = n / 2;
        if (cut == 0) {  // the first half by rx
            cut_ranks(r, half, 1, y_lo, y_hi, s);
            r += half;
            n -= half;
            cut = 1;
            continue;
        }
        // The median of ry: the half-th (from 0) set bit of the node's ry bitmap.
        std::uint64_t* bits = s.bitmap.data();
        const std::size_t words = (y_hi - y_lo + 63) / 64;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t y = (r[i] & 0xffffu) - y_lo;
            bits[y >> 6] |= std::uint64_t{1} << (y & 63);
        }
        std::size_t before = 0;
        std::size_t w = 0;
        for (;; ++w) {
            const auto here = static_cast<std::size_t>(std::popcount(bits[w]));
            if (before + here > half) break;
            before += here;
        }
        std::uint64_t word = bits[w];
        for (std::size_t k = before; k < half; ++k) word &= word - 1;  // drop lower set bits
        const auto median = static_cast<std::uint32_t>(y_lo + 64 * w + std::countr_zero(word));
        std::fill(bits, bits + words, std::uint64_t{0});
        // Stable partition: ry < median first, both sides keep their rx order. Every rank is
        // stored on both sides and only one side's index moves (no branch to mispredict).
        std::uint32_t* low = s.ranks_tmp.data();
        std::uint32_t* high = s.ranks_tmp.data() + half + 1;
        std::size_t l = 0;
        std::size_t h = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t v = r[i];
            const std::size_t below = (v & 0xffffu) < median ? 1 : 0;
            low[l] = v;
            high[h] = v;
            l += below;
            h += 1 - below;
        }
        std::memcpy(r, low, half * sizeof(std::uint32_t));
        std::memcpy(r + half, high, (n - half) * sizeof(std::uint32_t));
        cut_ranks(r, half, 0, y_lo, median, s);
        r += half;
        n -= half;
        y_lo = median;
        cut = 0;
    }
}

}  // namespace

void order_subtree(KernelPoint* a, std::size_t n, int cut, SubtreeScratch& scratch) {
    if (n <= strip_size) {
        std::sort(a, a + n, Before<0>{});
        return;
    }
    SubtreeScratch::Buffers& s = scratch.get(n);
    double x_lo = a[0].x, x_hi = a[0].x, y_lo = a[0].y, y_hi = a[0].y;
    for (std::size_t i = 1; i < n; ++i) {
        x_lo = std::min(x_lo, a[i].x);
        x_hi = std::max(x_hi, a[i].x);
        y_lo = std::min(y_lo, a[i].y);
        y_hi = std::max(y_hi, a[i].y);
    }
    const KeyMap key_x(x_lo, x_hi);
    const KeyMap key_y(y_lo, y_hi);
    std::uint64_t* by_x = s.by_x.data();
    std::uint64_t* by_y = s.by_y.data();
    for (std::size_t i = 0; i < n; ++i) {
        by_x[i] = key_x(a[i].x) << 32 | i;
        by_y[i] = key_y(a[i].y) << 32 | i;
    }
    radix_sort_by_key(by_x, s.sort_tmp.data(), n);
    order_equal_keys(by_x, n, a, Before<0>{});
    radix_sort_by_key(by_y, s.sort_tmp.data(), n);
    order_equal_keys(by_y, n, a, Before<1>{});
    std::uint16_t* y_rank = s.y_rank.data();
    for (std::size_t j = 0; j < n; ++j) y_rank[index_of(by_y[j])] = static_cast<std::uint16_t>(j);
    std::uint32_t* ranks = s.ranks.data();
    for (std::size_t i = 0; i < n; ++i) {
        ranks[i] = static_cast<std::uint32_t>(i) << 16 | y_rank[index_of(by_x[i])];
    }
    cut_ranks(ranks, n, cut, 0, static_cast<std::uint32_t>(n), s);
    std::memcpy(static_cast<void*>(s.points.data()), a, n * sizeof(KernelPoint));
    for (std::size_t k = 0; k < n; ++k) a[k] = s.points[index_of(by_x[ranks[k] >> 16])];
}

}  // namespace dtm::detail
