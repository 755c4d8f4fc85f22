// SPDX-License-Identifier: MIT
/// @file
/// @brief The serial kernel's recursion tree as the distributed run walks it: nodes, their cuts
/// (alternating, strips of at most strip_size points by x) and their halves (delaunay_dc.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

#include "algo/detail/kd_order.hpp"

namespace dtm::dist {

struct Node {
    std::uint64_t lo = 0;
    std::uint64_t hi = 0;
    std::uint32_t depth = 0;
    std::uint8_t cut = 0;  ///< the nominal cut (alternating); effective_cut applies the strip rule
    std::uint8_t frame = 0;
};

inline std::uint8_t effective_cut(const Node& n) noexcept {
    return n.hi - n.lo <= detail::strip_size ? 0 : n.cut;
}

inline bool splits(const Node& n, std::uint32_t max_depth) noexcept {
    return n.depth < max_depth && n.hi - n.lo > 3;
}

inline std::array<Node, 2> children(const Node& n) noexcept {
    const std::uint8_t c = effective_cut(n);
    const std::uint64_t mid = n.lo + (n.hi - n.lo) / 2;
    const auto other = static_cast<std::uint8_t>(1 - c);
    return {Node{n.lo, mid, n.depth + 1, other, c}, Node{mid, n.hi, n.depth + 1, other, c}};
}

inline std::uint32_t max_depth(int ranks, unsigned extra_levels) noexcept {
    const auto p = static_cast<std::uint32_t>(std::max(ranks, 1));
    return static_cast<std::uint32_t>(std::bit_width(p - 1)) + extra_levels;
}

}  // namespace dtm::dist
