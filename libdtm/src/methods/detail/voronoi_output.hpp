// SPDX-License-Identifier: MIT
/// @file
/// @brief What the three Voronoi methods share: their generators (the distinct input points,
/// optionally followed by auxiliary ones), circumcentres, and the last step from a method's
/// working half-edge graph to MethodResult: auxiliary regions dropped, zero-length edges of
/// cocircular generators merged into vertices of degree > 3, positions, the dual Tin.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/methods/method.hpp"
#include "methods/detail/counting_predicates.hpp"

namespace dtm::methods::detail {

inline constexpr std::uint32_t no_index = VoronoiDiagram::none;
/// Face of a half-edge that is free (deleted, or never used).
inline constexpr std::uint32_t dead_face = VoronoiDiagram::none - 1;

/// The generators of a Voronoi method.
struct Sites {
    std::vector<Point2> xy;          ///< distinct input points in input order, then auxiliaries
    std::vector<VertexIndex> input;  ///< per distinct point: its index in the input
    std::vector<VertexIndex> first;  ///< per input point: the first input point at its xy
    std::uint32_t real = 0;          ///< number of distinct points
};

/// The distinct points of @p points (the first of exact xy duplicates kept).
/// @throws InputError fewer than two distinct points.
[[nodiscard]] Sites make_sites(std::span<const Point3> points, const char* method);

/// A method's Voronoi diagram under construction: half-edges h and h ^ 1 are twins; origin is a
/// vertex id below vertex_count or no_index (at infinity); free half-edges have face dead_face.
/// Faces at or above sites.real are auxiliary and are dropped. Every live vertex has degree 3.
struct VoronoiGraph {
    std::vector<VoronoiDiagram::HalfEdge> he;
    std::uint32_t vertex_count = 0;
};

struct FinishOptions {
    /// false: keep the graph as it is (no cocircular merging, no geometric use of the
    /// predicates) and give an empty triangle list: for diagrams built from corrupted signs.
    bool exact = true;
};

/// Fills result.voronoi and result.tin from @p graph (consumed) and adds the diagram's counts to
/// result.counters.extra. Vertices with an auxiliary generator go to infinity.
void finish_voronoi(VoronoiGraph&& graph,
                    const Sites& sites,
                    std::span<const Point3> input,
                    const FinishOptions& options,
                    CountingPredicates& predicates,
                    MethodResult& result,
                    const Progress& progress);

}  // namespace dtm::methods::detail
