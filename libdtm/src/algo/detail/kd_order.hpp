// SPDX-License-Identifier: MIT
/// @file
/// @brief The order in which the divide and conquer cuts its points: median cuts alternately
/// by x and by y, down to strips of at most strip_size points sorted by x.
///
/// The cut of a subtree of n points by axis a puts the n / 2 smallest under Before<a> first; its
/// two halves are cut by the other axis. The resulting order is a function of the point set
/// only, so every algorithm that produces it (kd_order.cpp) gives the same kernel numbering and
/// the same triangles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "algo/detail/ghost_mesh.hpp"

namespace dtm::detail {

/// Subtrees of at most this many points are not cut alternately but sorted by x once and cut
/// vertically by index (Guibas and Stolfi's original scheme).
constexpr std::size_t strip_size = 16;

/// Strict order of a cut's frame: lexicographic (x, y) for axis 0, (y, -x) for axis 1. Written
/// without branches, for the median selection.
template <int Axis>
struct Before {
    bool operator()(const KernelPoint& a, const KernelPoint& b) const noexcept {
        if constexpr (Axis == 0) return (a.x < b.x) | ((a.x == b.x) & (a.y < b.y));
        return (a.y < b.y) | ((a.y == b.y) & (a.x > b.x));
    }
};

/// Scratch memory of one thread for order_subtree, allocated on first use for the subtree's
/// size (grown to at most capacity).
class SubtreeScratch {
public:
    /// The largest subtree order_subtree takes (its ranks are 16-bit); about 1 MiB of scratch.
    static constexpr std::size_t capacity = std::size_t{1} << 14;

    SubtreeScratch();
    ~SubtreeScratch();
    SubtreeScratch(const SubtreeScratch&) = delete;
    SubtreeScratch& operator=(const SubtreeScratch&) = delete;
    SubtreeScratch(SubtreeScratch&&) noexcept;
    SubtreeScratch& operator=(SubtreeScratch&&) noexcept;

    struct Buffers;
    /// Buffers for a subtree of @p n <= capacity points.
    Buffers& get(std::size_t n);

private:
    std::unique_ptr<Buffers> buffers_;
};

/// Puts a[0, n) (pairwise distinct, n <= SubtreeScratch::capacity) into the order of the
/// recursion whose first cut is by axis @p cut (0: x, 1: y).
void order_subtree(KernelPoint* a, std::size_t n, int cut, SubtreeScratch& scratch);

}  // namespace dtm::detail
