// SPDX-License-Identifier: MIT
/// @file
/// @brief Exact median selection for the divide and conquer's cuts, without branch mispredictions.
///
/// select_kth(a, n, k, less) reorders a[0, n) so that the k smallest elements under the strict
/// total order `less` come first (as std::nth_element, but a[k] need not be the k-th itself). The
/// set that ends up on each side is a function of the elements only, never of their order or of
/// the pivots chosen, so the divide and conquer's recursion tree stays a function of the input.
///
/// Each round takes the pivot from a deterministic sample (the sample's element of the wanted
/// rank), so the wanted position usually lands in a few per cent of the range after one pass, and
/// partitions with a branch-free loop: the comparison result only moves indices. std::nth_element
/// loses most of its time on mispredicted branches in its partition loops (one in two for
/// coordinates). Ranges that fit a per-thread scratch buffer are scattered into it from both ends
/// and copied back (no store-to-load dependency); larger ones are partitioned in place by blocks.
/// Small ranges fall back to std::nth_element.
///
/// References: R. W. Floyd, R. L. Rivest, "Expected time bounds for selection", CACM 18(3), 1975
/// (pivots from a sample); S. Edelkamp, A. Weiss, "BlockQuicksort: avoiding branch mispredictions
/// in quicksort", ESA 2016 (branch-free and block partitioning).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>

namespace dtm::detail {

/// Scratch memory of one thread for select_kth.
template <class T>
struct SelectScratch {
    static constexpr std::size_t capacity = std::size_t{1} << 14;  // 384 KiB of points: in L2
    std::unique_ptr<T[]> data;
    T* get() {
        if (!data) data = std::make_unique<T[]>(capacity);
        return data.get();
    }
};

/// Partitions a[0, n) in place by `less(x, pivot)` (block partitioning after Edelkamp and Weiss):
/// blocks at both ends are classified branch-free into lists of misplaced offsets, which are then
/// swapped pairwise. Every element is read once and about half of them are written once, where
/// an in-place Lomuto pass reads and writes every element twice; for the large ranges that stream
/// from memory that halves the traffic. @return the number of elements before.
template <class T, class Less>
std::size_t partition_blocks(T* a, std::size_t n, const T& pivot, Less less) {
    constexpr std::size_t block = 128;
    std::uint8_t misplaced_left[block];
    std::uint8_t misplaced_right[block];
    std::size_t l = 0;  // a[0, l) before the pivot
    std::size_t r = n;  // a[r, n) not before it
    std::size_t count_left = 0, count_right = 0, first_left = 0, first_right = 0;
    while (r - l > 2 * block) {
        if (count_left == 0) {
            first_left = 0;
            for (std::size_t i = 0; i < block; ++i) {
                misplaced_left[count_left] = static_cast<std::uint8_t>(i);
                count_left += less(a[l + i], pivot) ? 0 : 1;
            }
        }
        if (count_right == 0) {
            first_right = 0;
            for (std::size_t i = 0; i < block; ++i) {
                misplaced_right[count_right] = static_cast<std::uint8_t>(i);
                count_right += less(a[r - 1 - i], pivot) ? 1 : 0;
            }
        }
        const std::size_t swaps = std::min(count_left, count_right);
        for (std::size_t k = 0; k < swaps; ++k) {
            std::swap(a[l + misplaced_left[first_left + k]],
                      a[r - 1 - misplaced_right[first_right + k]]);
        }
        count_left -= swaps;
        count_right -= swaps;
        first_left += swaps;
        first_right += swaps;
        if (count_left == 0) l += block;
        if (count_right == 0) r -= block;
    }
    // The rest, at most two blocks: a branch-free Lomuto pass.
    std::size_t store = l;
    for (std::size_t i = l; i < r; ++i) {
        const T v = a[i];
        const bool before = less(v, pivot);
        a[i] = a[store];
        a[store] = v;
        store += before ? 1 : 0;
    }
    return store;
}

/// Partitions a[0, n) by `less(x, pivot)`, branch-free. @return the number of elements before.
template <class T, class Less>
std::size_t partition_branch_free(
    T* a, std::size_t n, const T& pivot, Less less, SelectScratch<T>& scratch) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (n <= SelectScratch<T>::capacity) {
        T* out = scratch.get();
        std::size_t l = 0;
        std::size_t r = n - 1;
        for (std::size_t i = 0; i < n; ++i) {
            const T v = a[i];
            const bool before = less(v, pivot);
            out[l] = v;
            out[r] = v;
            l += before ? 1 : 0;
            r -= before ? 0 : 1;
        }
        std::memcpy(static_cast<void*>(a), out, n * sizeof(T));
        return l;
    }
    return partition_blocks(a, n, pivot, less);
}

/// Moves the k smallest of a[0, n) (pairwise distinct under the strict order `less`) to the front.
template <class T, class Less>
void select_kth(T* a, std::size_t n, std::size_t k, Less less, SelectScratch<T>& scratch) {
    constexpr std::size_t small = 1024;  // in cache: std::nth_element is as fast
    constexpr std::size_t max_sample = 127;
    while (n > small && k > 0 && k < n) {
        const std::size_t s = n > 8192 ? max_sample : (n > 512 ? 31 : 9);
        T sample[max_sample];
        const std::size_t step = n / s;
        for (std::size_t i = 0; i < s; ++i) sample[i] = a[i * step];
        // The sample element of the wanted rank; never the sample's minimum, so that at least
        // one element goes before the pivot and every round shrinks the range.
        std::size_t want = static_cast<std::size_t>(
            static_cast<double>(k) / static_cast<double>(n) * static_cast<double>(s));
        want = std::clamp<std::size_t>(want, 1, s - 1);
        std::nth_element(sample, sample + want, sample + s, less);
        const std::size_t before = partition_branch_free(a, n, sample[want], less, scratch);
        if (k < before) {
            n = before;
        } else {
            a += before;
            n -= before;
            k -= before;
        }
    }
    if (k > 0 && k < n) std::nth_element(a, a + k, a + n, less);
}

}  // namespace dtm::detail
