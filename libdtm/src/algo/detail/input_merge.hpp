// SPDX-License-Identifier: MIT
/// @file
/// @brief Turning TerrainInput into distinct vertices and constraint segments: duplicate and
/// snap merging with the z rule, every merge recorded.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dtm/algo/triangulate.hpp"

namespace dtm::detail {

struct InputSegment {
    VertexIndex a;
    VertexIndex b;
    std::uint8_t bits;  ///< ConstraintBits
};

struct MergedInput {
    std::vector<Point3> vertices;  ///< distinct vertices, in order of first input occurrence
    std::vector<bool> z_known;     ///< false for vertices only soft breaklines gave (z to compute)
    /// Per combined input point; empty when nothing merged (the identity), which spares the
    /// run 4 bytes per point while the kernel's arrays exist.
    std::vector<VertexIndex> input_to_vertex;
    std::vector<DuplicateMerge> merges;
    std::vector<InputSegment> segments;  ///< hard, boundary, hole, then soft; input order
    std::size_t points_in = 0;

    [[nodiscard]] VertexIndex vertex_of_input(std::size_t i) const noexcept {
        return input_to_vertex.empty() ? static_cast<VertexIndex>(i) : input_to_vertex[i];
    }
};

/// The kept vertex's z after one more duplicate with height @p z, its @p count -th height (the
/// heights fold in input order; the distributed merge folds them in the same order).
inline double duplicate_rule_z(DuplicateRule rule, double current, double z, std::size_t count) {
    switch (rule) {
        case DuplicateRule::first:
            return current;
        case DuplicateRule::mean:
            return current + (z - current) / static_cast<double>(count);
        case DuplicateRule::min:
            return std::min(current, z);
        case DuplicateRule::max:
            return std::max(current, z);
    }
    return current;
}

/// The combined input before merging: survey points, then the line vertices.
struct CombinedInput {
    std::vector<Point3> points;
    std::vector<bool> z_known;
    std::vector<InputSegment> segments;  ///< indices into points
};

/// Appends the vertices and segments of input's breaklines, boundaries, holes and soft
/// breaklines to @p c, in that order (merge_input's order; the distributed run's too).
/// @throws InputError on non-finite coordinates or an open boundary/hole ring.
void add_lines(const TerrainInput& input, CombinedInput& c);

/// @throws InputError on non-finite coordinates or an open boundary/hole ring.
[[nodiscard]] MergedInput merge_input(const TerrainInput& input, const TriangulateOptions& options);
/// Same, taking over input.points (left empty) instead of copying them.
[[nodiscard]] MergedInput merge_input(TerrainInput&& input, const TriangulateOptions& options);

}  // namespace dtm::detail
