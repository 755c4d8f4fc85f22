// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: what each edge of each triangle is (a plain edge, or a piece of a breakline,
/// soft breakline, boundary or hole), indexed by triangle so that it stays valid when the
/// vertices of the TIN are renumbered.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// Kind of one triangle edge: plain_edge, or 1 + ConstraintKind.
inline constexpr std::uint8_t plain_edge = 0;

[[nodiscard]] inline constexpr std::uint8_t edge_kind_of(ConstraintKind kind) {
    return static_cast<std::uint8_t>(1 + static_cast<std::uint8_t>(kind));
}

/// Per triangle, the kind of edge e (the edge opposite v[e]).
using TriangleEdgeKinds = std::vector<std::array<std::uint8_t, 3>>;

/// The kinds of every triangle edge of @p tin, from tin.constraints (O(V + C + T), parallel).
[[nodiscard]] TriangleEdgeKinds triangle_edge_kinds(const Tin& tin);

/// True for a hard breakline edge: the C1 surface creases along it.
[[nodiscard]] inline bool is_hard(std::uint8_t kind) {
    return kind == edge_kind_of(ConstraintKind::breakline);
}

}  // namespace dtm::detail
