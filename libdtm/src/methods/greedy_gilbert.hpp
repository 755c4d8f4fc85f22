// SPDX-License-Identifier: MIT
/// @file
/// @brief [greedy-gilbert] The greedy triangulation with one segment tree per point (Gilbert 1979;
/// thesis 000 §3.1b and §3.1.1), O(n^2 log n) time, O(n^2) memory.
#pragma once

#include <cstdint>
#include <vector>

#include "dtm/methods/method.hpp"

namespace dtm::methods {

/// The segment tree T(l, r) of Preparata and Shamos (thesis 000 §3.1.1): node v covers the
/// standard interval [B[v], E[v]]; leaves are the elementary intervals [k, k + 1]; children
/// T(l, floor((l + r) / 2)) and T(floor((l + r) / 2), r) (erratum 4: the thesis' ceiling would
/// leave a gap). Only the shape: the per-node edge fields live with each point's tree.
struct SegmentTreeShape {
    std::vector<std::uint32_t> begin, end, left, right;  ///< B, E, LSON, RSON (root = 0)
    static constexpr std::uint32_t none = 0xffffffffu;
    /// Builds T(l, r), l < r.
    SegmentTreeShape(std::uint32_t l, std::uint32_t r);
    [[nodiscard]] std::size_t size() const noexcept { return begin.size(); }
    /// Depth of the tree (a single leaf has depth 0): ceil(log2(r - l)).
    [[nodiscard]] int depth() const;
};

[[nodiscard]] MethodResult run_greedy_gilbert(const MethodInput& input,
                                              const MethodOptions& options,
                                              const Progress& progress);

}  // namespace dtm::methods
