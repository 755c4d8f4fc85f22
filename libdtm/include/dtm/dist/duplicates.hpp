// SPDX-License-Identifier: MIT
/// @file
/// @brief Exact duplicates merged across ranks (R-D3 of docs/distributed.md), as the serial
/// merge does: the first occurrence in input order is kept, its z follows the DuplicateRule over
/// the group's heights in input order, every merge is reported.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/point.hpp"
#include "dtm/dist/comm.hpp"

namespace dtm::dist {

/// A combined input point (survey points, then breakline vertices, as the serial merge orders
/// them); z_known is false for vertices that only soft breaklines give.
struct InputPoint {
    Point3 p;
    bool z_known = true;
};

/// The bits of a vertex number in Vertex::id (mask a number with it where one is stored).
inline constexpr std::uint64_t vertex_id_bits = (std::uint64_t{1} << 63) - 1;

/// A kept vertex with its global vertex number (32 bytes: the number and the flag share a word).
struct Vertex {
    Point3 p;
    std::uint64_t id : 63 = 0;
    bool z_known : 1 = true;
};
static_assert(sizeof(Vertex) == 32);

/// This rank's part of the merge: rank r holds the global input indices [first_input,
/// first_input + local count), ranks in input order.
struct MergedShare {
    std::uint64_t first_input = 0;
    std::uint64_t total_inputs = 0;
    std::uint64_t first_vertex = 0;  ///< global number of this rank's first kept vertex
    std::uint64_t total_vertices = 0;
    std::vector<Vertex> vertices;  ///< the kept vertices first seen on this rank, input order
    /// Per local input point, its vertex number (the distributed surface frees it once the
    /// breaklines are placed).
    std::vector<std::uint64_t> vertex_of_input;
    std::vector<DuplicateMerge> merges;  ///< merged local input points, input order
    /// The kept vertices' z once keep_heights() freed `vertices` (the kernel's positions hold
    /// their x and y): vertex first_vertex + i has height heights[i].
    std::vector<double> heights;

    /// Frees `vertices`, keeping their z in `heights` (32 bytes per vertex down to 8).
    void keep_heights();
    /// The kept vertices first seen on this rank, before or after keep_heights().
    [[nodiscard]] std::size_t count() const noexcept {
        return vertices.empty() ? heights.size() : vertices.size();
    }
    /// The z of vertex first_vertex + @p i.
    [[nodiscard]] double z(std::size_t i) const {
        return vertices.empty() ? heights[i] : vertices[i].p.z;
    }
    /// The kept vertex numbered @p number when this rank holds it (before keep_heights()),
    /// else nullptr.
    [[nodiscard]] Vertex* kept(std::uint64_t number) noexcept {
        if (number < first_vertex || number - first_vertex >= vertices.size()) return nullptr;
        return &vertices[number - first_vertex];
    }
};

/// Collective: every point goes to the rank of a hash of its exact coordinates (-0 as 0), which
/// groups its duplicates, keeps the smallest input index, folds the heights in input order and
/// answers the owners of the inputs; kept vertices are numbered by an exclusive scan. Equal to
/// the serial merge (no snapping) for every rank count.
MergedShare merge_exact_duplicates(Comm& comm,
                                   std::span<const InputPoint> local,
                                   DuplicateRule rule);

}  // namespace dtm::dist
