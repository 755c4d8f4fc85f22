// SPDX-License-Identifier: MIT
/// @file
/// @brief Turning TerrainInput into distinct vertices and constraint segments: duplicate and
/// snap merging with the z rule, every merge recorded.
#pragma once

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
    std::vector<VertexIndex> input_to_vertex;  ///< per combined input point
    std::vector<DuplicateMerge> merges;
    std::vector<InputSegment> segments;  ///< hard, boundary, hole, then soft; input order
    std::size_t points_in = 0;
};

/// @throws InputError on non-finite coordinates or an open boundary/hole ring.
[[nodiscard]] MergedInput merge_input(const TerrainInput& input, const TriangulateOptions& options);
/// Same, taking over input.points (left empty) instead of copying them.
[[nodiscard]] MergedInput merge_input(TerrainInput&& input, const TriangulateOptions& options);

}  // namespace dtm::detail
