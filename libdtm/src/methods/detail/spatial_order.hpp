// SPDX-License-Identifier: MIT
/// @file
/// @brief Insertion orders of the incremental methods: a seeded random permutation, and the
/// order along a Hilbert curve (consecutive points near each other, so a walk from the last
/// point is short). Orders only: no geometric decision depends on them.
#pragma once

#include <cstdint>
#include <vector>

#include "dtm/core/tin.hpp"

namespace dtm::methods::detail {

/// A random permutation of 0 .. n-1, the same for the same seed on every platform.
[[nodiscard]] std::vector<VertexIndex> random_order(std::size_t n, std::uint64_t seed);

/// The points sorted by their position along a Hilbert curve over their bounding box
/// (2^16 x 2^16 cells; ties by index).
[[nodiscard]] std::vector<VertexIndex> hilbert_order(const std::vector<Point3>& points);

/// Biased randomized insertion order (Amenta, Choi, Rote 2003): a random permutation cut into
/// rounds of doubling size (the last holds half the points), each round in Hilbert order. Keeps
/// the randomized analysis (every round is a random sample) and gives nearby consecutive
/// points, so the location structure's paths stay in the caches.
[[nodiscard]] std::vector<VertexIndex> brio_order(const std::vector<Point3>& points,
                                                  std::uint64_t seed);

/// The points renumbered in insertion order, in place: points[k] becomes the old
/// points[order[k]]. A method that inserts vertex k at step k then reads coordinates and
/// writes per-vertex records in sequence rather than at random. Only the numbering changes:
/// the coordinates, hence every predicate and every decision, are the same.
void to_insertion_order(std::vector<Point3>& points, const std::vector<VertexIndex>& order);

/// Back to the input numbering after to_insertion_order: every corner v of @p triangles
/// becomes order[v], and @p points goes back to input order, in place.
void to_input_numbering(std::vector<Triangle>& triangles,
                        std::vector<Point3>& points,
                        const std::vector<VertexIndex>& order);

}  // namespace dtm::methods::detail
