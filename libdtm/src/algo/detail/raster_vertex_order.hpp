// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: a TIN copy with its vertices renumbered in first-use order, for the
/// cache-friendly sweeps of rasterisation and contouring.
#pragma once

#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// Triangles come in a spatially coherent order but vertices keep the input order (often
/// random), so reading the corners of each triangle costs three cache misses. After this one
/// renumbering the reads follow the triangles through memory. Vertex numbers are given in the
/// order of first use (triangle by triangle, corner by corner), computed by all threads with
/// the result of one sequential pass. Neighbour links and the triangle order are unchanged;
/// constraints are not copied.
[[nodiscard]] Tin with_coherent_vertices(const Tin& tin);

/// Whether @p tin's vertices are already in first-use order (no copy needed); no memory.
[[nodiscard]] bool has_coherent_vertices(const Tin& tin) noexcept;

/// The same renumbering in place: a new vertex array, the triangles renumbered where they are
/// (36 bytes a vertex while it runs instead of a whole copy): for a TIN that is its owner's to
/// change.
void make_vertices_coherent(Tin& tin);

}  // namespace dtm::detail
