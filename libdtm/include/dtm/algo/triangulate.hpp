// SPDX-License-Identifier: MIT
/// @file
/// @brief Constrained Delaunay triangulation of terrain input (points, breaklines, domain).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dtm/algo/line_heights.hpp"
#include "dtm/algo/optimize.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// How the z of merged duplicate points is chosen.
enum class DuplicateRule : std::uint8_t { first, mean, min, max };

struct TriangulateOptions {
    /// Points closer than this in xy are merged (0: only exact duplicates are merged).
    double snap_distance = 0.0;
    DuplicateRule duplicates = DuplicateRule::first;
    /// Border triangles whose outward edge is longer than this are trimmed, from the outside of
    /// the hull inwards (0: no trimming).
    double max_edge = 0.0;
    /// Two crossing breaklines whose interpolated heights at the crossing differ by more than this
    /// are reported as a conflict.
    double z_tolerance = 0.001;
    /// Worker threads for the parallel phases (0: all cores). The result never depends on it.
    unsigned threads = 0;
    /// Number of tiles for the parallel divide and conquer (0: automatic). The result never
    /// depends on it.
    std::size_t tiles = 0;
    /// After the constrained Delaunay TIN, Lawson flips under this criterion (optimize.hpp;
    /// constrained edges never flip). delaunay (default): none.
    Criterion optimize = Criterion::delaunay;
};

/// One merge of input points that share a position (or lie within snap_distance).
struct DuplicateMerge {
    std::size_t kept_input;    ///< index into the combined input (see input_to_vertex)
    std::size_t merged_input;  ///< the input point merged into it
    Point3 kept;               ///< position kept, with the z the rule gave
    Point3 merged;             ///< the merged point as given
};

/// Two breaklines cross and their heights at the crossing differ by more than z_tolerance.
struct ConstraintConflict {
    Point2 at;
    double z_first;
    double z_second;
};

struct TriangulateStats {
    std::size_t points_in = 0;          ///< survey points plus breakline/boundary/hole vertices
    std::size_t duplicates_merged = 0;  ///< input points merged into another
    std::size_t intersections = 0;      ///< vertices added where constraints cross
    std::size_t conflicts = 0;          ///< intersections whose heights disagree
    std::size_t removed_triangles = 0;  ///< outside the boundary, in holes, or trimmed
    double seconds_triangulate = 0.0;
    double seconds_constrain = 0.0;
    /// What TriangulateOptions::optimize did (flips, quality before and after, seconds).
    OptimizeStats optimize;
};

struct TriangulateResult {
    Tin tin;
    TriangulateStats stats;
    std::vector<DuplicateMerge> merges;
    std::vector<ConstraintConflict> conflicts;
    /// For every combined input point (points, then the vertices of breaklines, boundaries, holes
    /// and soft breaklines, in that order), the TIN vertex it became.
    std::vector<VertexIndex> input_to_vertex;
    /// How line vertices given without a height got one (resolve_line_heights).
    LineHeightReport line_heights;
};

/// Constrained Delaunay triangulation of @p input. Line vertices given without a height (NaN z)
/// get one first (resolve_line_heights; soft breakline vertices from the surface of everything
/// else).
/// @throws InputError fewer than 3 distinct points, all points collinear, an open boundary, a
/// hard breakline vertex without a height, ...
/// @throws Cancelled when @p progress asks to stop.
/// @post verify_topology and verify_constraints hold on the result; so does
/// verify_constrained_delaunay when options.optimize is delaunay, and otherwise every
/// unconstrained edge is locally optimal under the criterion (count_improvable_edges is 0).
[[nodiscard]] TriangulateResult triangulate(const TerrainInput& input,
                                            const TriangulateOptions& options = {},
                                            const Progress& progress = {});

/// Same, consuming @p input: its memory is released as soon as the vertices are merged, which
/// lowers the peak memory of large jobs by about 24 bytes per point.
[[nodiscard]] TriangulateResult triangulate(TerrainInput&& input,
                                            const TriangulateOptions& options = {},
                                            const Progress& progress = {});

}  // namespace dtm
