// SPDX-License-Identifier: MIT
/// @file
/// @brief The triangulation methods of the source literature as plain functions: what they take,
/// what they return, what they count. The registry (registry.hpp) lists them; `dtm methods`
/// runs and compares them. Pure core: no file formats.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::methods {

/// What a method did, counted by the method itself. Predicate calls are counted by the
/// CountingPredicates wrapper every method uses (src/methods/detail/counting_predicates.hpp).
struct MethodCounters {
    std::uint64_t orient_calls = 0;    ///< geom::orient2d (and orient3d for lifting)
    std::uint64_t incircle_calls = 0;  ///< geom::incircle
    std::uint64_t flips = 0;           ///< edge flips (Lawson, legalisation, generalized flips)
    std::uint64_t walk_steps = 0;      ///< triangles or edges visited by point location
    std::size_t peak_bytes = 0;        ///< peak size of the method's own data structures
    /// Method-specific counts ("dag_nodes", "active_edges", "swaps", ...), printed by --stats.
    std::map<std::string, std::uint64_t> extra;
};

/// A segment between two input points (indices into MethodInput::points) that must be an edge.
using Segment = std::pair<VertexIndex, VertexIndex>;

struct MethodInput {
    std::span<const Point3> points;
    std::span<const Segment> segments;  ///< only for methods with takes_constraints
};

/// Options common to every method plus free-form method parameters.
struct MethodOptions {
    unsigned threads = 0;    ///< for the parallel methods (0: all cores); never changes the result
    std::uint64_t seed = 1;  ///< randomised methods: the insertion order is a function of it
    /// Method parameters by name ("super-triangle" = "symbolic|finite", "swap" = "post", ...);
    /// every method documents its keys in the registry and rejects unknown ones (UsageError
    /// naming the key).
    std::map<std::string, std::string> params;
};

/// A Voronoi diagram as a doubly connected edge list. Half-edge i and i^1 are twins. Vertex
/// positions are computed (circumcentres, rounded to double); the topology is exact (decided by
/// the predicates). A half-edge with no origin starts at infinity: the unbounded edges (rays,
/// and whole lines for collinear generators) have one or both ends there. The direction of a
/// half-edge is rot90ccw(q - p) for p the generator of its face and q that of its twin's
/// (dtm/methods/voronoi.hpp has it, and the validator). Where k > 3 generators are cocircular
/// the diagram has one vertex of degree k (never zero-length edges). next of a half-edge that
/// ends at infinity is the half-edge of the same face that comes back from infinity (the arc at
/// infinity closes the cycle of an unbounded face).
struct VoronoiDiagram {
    static constexpr std::uint32_t none = 0xffffffffu;
    struct HalfEdge {
        std::uint32_t origin = none;  ///< index into vertices, none = at infinity
        std::uint32_t next = none;    ///< next half-edge ccw around the same face
        std::uint32_t face = none;    ///< the generator (index into the input points) on its left
    };
    std::vector<Point2> vertices;
    std::vector<HalfEdge> half_edges;
    std::vector<std::uint32_t> face_edge;  ///< per generator, one half-edge of its region (none
                                           ///< for generators merged as duplicates)
};

/// A planar subdivision whose faces are polygons (pseudo-triangulations): each face lists its
/// vertices counter-clockwise (indices into Tin::vertices of MethodResult::tin).
using PolygonFaces = std::vector<std::vector<VertexIndex>>;

struct MethodResult {
    Tin tin;                 ///< the triangulation (vertices: the distinct input points)
    VoronoiDiagram voronoi;  ///< Voronoi methods only
    PolygonFaces faces;      ///< pseudo-triangulations only
    std::vector<Tin> all;    ///< enumeration: every triangulation found
    MethodCounters counters;
    /// Method-specific results for --stats as JSON members ("\"triangulations\": 10, ...");
    /// empty when there are none.
    std::string stats_json;
};

/// A method: @p input in, result out. @throws UsageError for a bad parameter, InputError for an
/// input the method documents it refuses (e.g. more than 12 points for enumeration), Cancelled.
using MethodFn = MethodResult (*)(const MethodInput& input,
                                  const MethodOptions& options,
                                  const Progress& progress);

}  // namespace dtm::methods
