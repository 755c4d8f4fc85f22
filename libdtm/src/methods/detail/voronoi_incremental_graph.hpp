// SPDX-License-Identifier: MIT
/// @file
/// @brief The planar graph both incremental Voronoi methods grow (000 §3.5, §3.6): the Voronoi
/// diagram of the generators inserted so far plus three auxiliary generators whose triangle
/// contains them all, closed by a large curve (the outer face) through the ends of the three
/// rays between the auxiliary regions. Every region of a real generator is bounded and every
/// vertex has degree 3; inserting a generator is Sugihara and Iri's procedure A: given the tree
/// T of vertices to delete, split each edge leaving T, join the new vertices into a cycle (the
/// new region) and delete T.
///
/// The auxiliary generators are real points, placed so far away that they change nothing
/// between real generators: beyond any circle through three of them and any empty circle that
/// certifies a hull edge. With coordinates multiples of 2^e0 and within a span 2^s, twice a
/// triangle's area is at least 2^(2 e0), so a circumradius is below 2^(3 s - 2 e0 + 1) and the
/// lens of an empty circle through a hull edge shrinks below the nearest point's height once
/// its centre is 2^(4 s - 2 e0) away; the generators go to distance 2^(4 s - 2 e0 + 6). (The
/// lecture's finite super-triangle of 100 times the extent, 003, is not enough; see
/// docs/algorithms/methods.md.)
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "dtm/methods/method.hpp"
#include "methods/detail/counting_predicates.hpp"
#include "methods/detail/voronoi_output.hpp"

namespace dtm::methods::detail {

/// Sugihara and Iri's H(pi, pj, pk, pl) for counter-clockwise pi, pj, pk (000 §3.6.2 eq. 1),
/// negative when pl is inside their circle, evaluated in doubles by method 2 (eq. 7-10):
/// relative to the corner whose angle is nearest a right angle.
[[nodiscard]] double sugihara_iri_h(const Point2& pi,
                                    const Point2& pj,
                                    const Point2& pk,
                                    const Point2& pl) noexcept;

/// Vertex labels of procedure B (and the classic trace's memo): unknown, in T, out of T.
enum class Label : std::uint8_t { unknown = 0, in = 1, out = 2 };

class IncrementalVoronoi {
public:
    /// Appends the three auxiliary generators to @p sites.xy. @throws InputError when the
    /// coordinates span too many binary orders of magnitude to place them (beyond 2^1000).
    IncrementalVoronoi(Sites& sites, CountingPredicates& predicates);

    /// Probability with which each in-circle sign is replaced by its opposite (0: exact).
    void set_faults(double probability, std::uint64_t seed);
    [[nodiscard]] std::uint64_t faults_injected() const noexcept { return faults_; }

    /// The insertion order: the real generators along a Hilbert curve.
    [[nodiscard]] std::vector<std::uint32_t> insertion_order() const;

    /// The real generator nearest to @p g's point among those inserted (greedy walk over the
    /// regions from the last one located); no_index before the first insertion.
    [[nodiscard]] std::uint32_t nearest(const Point2& p);

    /// Sign of the in-circle test of vertex v against point p: > 0 when p is strictly inside
    /// the circle of v's generators (possibly corrupted, see set_faults). Vertices on the outer
    /// curve are never inside.
    [[nodiscard]] int inside(std::uint32_t v, const Point2& p);
    /// Sugihara and Iri's H (000 §3.6.3, method 2), evaluated in doubles: negative inside. Only
    /// ever used to rank vertices (lower-priority numerical information).
    [[nodiscard]] double h_value(std::uint32_t v, const Point2& p) const;

    /// Procedure A: the region of generator @p g replaces the tree of vertices labelled `in`
    /// (listed in @p tree). @throws Error when the labels do not describe a tree whose boundary
    /// closes (only possible with corrupted signs in the classic method).
    void insert(std::uint32_t g, const std::vector<std::uint32_t>& tree);

    // Navigation. Half-edge h runs from origin(h) to origin(h ^ 1) with face(h) on its left.
    [[nodiscard]] std::uint32_t origin(std::uint32_t h) const { return he_[h].origin; }
    [[nodiscard]] std::uint32_t dest(std::uint32_t h) const { return he_[h ^ 1u].origin; }
    [[nodiscard]] std::uint32_t next(std::uint32_t h) const { return he_[h].next; }
    [[nodiscard]] std::uint32_t face(std::uint32_t h) const { return he_[h].face; }
    /// The next half-edge out of the same vertex clockwise / counter-clockwise.
    [[nodiscard]] std::uint32_t cw(std::uint32_t h) const { return he_[h ^ 1u].next; }
    [[nodiscard]] std::uint32_t ccw(std::uint32_t h) const { return cw(cw(h)); }
    [[nodiscard]] std::uint32_t out(std::uint32_t v) const { return vout_[v]; }
    [[nodiscard]] std::uint32_t face_edge(std::uint32_t f) const { return face_edge_[f]; }
    [[nodiscard]] bool on_curve(std::uint32_t v) const;
    [[nodiscard]] std::uint32_t outer_face() const { return real_ + 3; }

    /// Labels for the current insertion; reset by clear_labels in time proportional to the
    /// number set.
    [[nodiscard]] Label label(std::uint32_t v) const { return label_[v]; }
    void set_label(std::uint32_t v, Label l);
    [[nodiscard]] bool incident(std::uint32_t f) const { return incident_[f] != 0; }
    void set_incident(std::uint32_t f);
    void clear_labels();

    [[nodiscard]] std::uint64_t walk_steps() const noexcept { return walk_steps_; }
    [[nodiscard]] std::size_t peak_bytes() const;
    /// The graph for finish_voronoi (consumes this object's half-edges).
    [[nodiscard]] VoronoiGraph release();
    /// The full graph, auxiliary regions and outer face included (for the topology checks).
    [[nodiscard]] const std::vector<VoronoiDiagram::HalfEdge>& half_edges() const { return he_; }
    [[nodiscard]] std::uint32_t vertex_count() const {
        return static_cast<std::uint32_t>(vout_.size());
    }

private:
    const Sites& sites_;
    CountingPredicates& pred_;
    std::uint32_t real_;
    std::vector<VoronoiDiagram::HalfEdge> he_;
    std::vector<std::uint32_t> vout_;  ///< per vertex, one half-edge out of it
    std::vector<std::uint32_t> face_edge_;
    std::vector<std::uint32_t> free_edges_, free_vertices_;
    std::vector<Label> label_;
    std::vector<std::uint8_t> incident_;
    std::vector<std::uint32_t> labelled_, incident_list_;
    std::vector<std::uint32_t> boundary_;
    std::vector<std::uint32_t> region_stamp_;
    std::uint32_t insertions_ = 0;
    std::uint32_t last_ = no_index;
    std::uint64_t walk_steps_ = 0;
    double fault_probability_ = 0.0;
    std::mt19937_64 fault_rng_;
    std::uint64_t faults_ = 0;

    std::uint32_t new_edge();
    std::uint32_t new_vertex();
    void start_graph();
    /// The generators around vertex v, counter-clockwise.
    void generators(std::uint32_t v, std::uint32_t g[3]) const;
};

/// How a method chooses the tree T of vertices to delete for generator @p g at point @p p:
/// labels them Label::in (others it decided on Label::out) and lists them in @p tree.
using ChooseTree = void (*)(IncrementalVoronoi& graph,
                            std::uint32_t g,
                            const Point2& p,
                            std::vector<std::uint32_t>& tree);

/// The common driver of the incremental methods: distinct points, auxiliary generators,
/// insertion along the Hilbert order, procedure A with the method's T, the result. Parameters:
/// faults=P (probability of corrupting each in-circle sign; then the result's Tin has no
/// triangles and the diagram is topological only).
[[nodiscard]] MethodResult run_incremental(const MethodInput& input,
                                           const MethodOptions& options,
                                           const Progress& progress,
                                           const char* name,
                                           ChooseTree choose);

}  // namespace dtm::methods::detail
