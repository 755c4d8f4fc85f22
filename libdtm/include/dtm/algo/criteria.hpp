// SPDX-License-Identifier: MIT
/// @file
/// @brief Optimality criteria of a triangulation (thesis 000 §2.2-2.3, slides 004, Dyn, Levin and
/// Rippa 1990) behind one interface: the decision for one convex quadrilateral, the local
/// optimality check of a whole TIN, per-triangle (or per-edge) quality vectors and their
/// lexicographic comparison. `dtm tin --optimize` (optimize.hpp) flips edges by them.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// The criteria. `delaunay` is the plain constrained Delaunay TIN (no optimisation).
enum class Criterion : std::uint8_t {
    delaunay,
    maxmin_angle,         ///< Lawson: largest smallest angle (= Delaunay, decided by incircle)
    minmax_angle,         ///< Barnhill and Little: smallest largest angle
    shortest_diagonal,    ///< the shorter diagonal of each convex quadrilateral
    maxmin_circumradius,  ///< largest smallest circumradius
    minmax_circumradius,  ///< smallest largest circumradius
    maxmin_area,          ///< largest smallest triangle area
    maxmin_height,        ///< largest smallest altitude
    maxmin_inradius,      ///< largest smallest inscribed-circle radius (slides 004)
    normals_angle,        ///< data-dependent: least sum of angles between adjacent normals
    normal_jump,          ///< data-dependent: least sum of jumps of the normal derivative
};

/// How a criterion measures a whole triangulation (thesis 000 §2.3 for the first two).
enum class CriterionKind : std::uint8_t {
    none,              ///< delaunay: nothing to measure
    triangle_max_min,  ///< per-triangle value, sorted ascending, larger vector is better
    triangle_min_max,  ///< per-triangle value, sorted descending, smaller vector is better
    edge_length,       ///< per-edge length, sorted descending, smaller vector is better
    edge_cost_sum,     ///< per-interior-edge cost (needs z), smaller exact sum is better
};

/// Every criterion, `delaunay` first, in the order of the enum.
[[nodiscard]] std::span<const Criterion> all_criteria();
/// The CLI name: "delaunay", "maxmin-angle", ..., "normal-jump".
[[nodiscard]] std::string_view criterion_name(Criterion criterion);
/// The criterion named @p name, or nothing.
[[nodiscard]] std::optional<Criterion> parse_criterion(std::string_view name);
[[nodiscard]] CriterionKind criterion_kind(Criterion criterion);
/// True for normals-angle and normal-jump (they read z).
[[nodiscard]] bool is_data_dependent(Criterion criterion);

/// The per-triangle value of a triangle criterion (radians for angles, CRS units for lengths,
/// square units for areas); computed from the corners in a canonical order, so the same triangle
/// always gives the same value. 0 for non-triangle criteria.
[[nodiscard]] double triangle_quality(Criterion criterion,
                                      const Point3& a,
                                      const Point3& b,
                                      const Point3& c);

/// The cost of the edge shared by triangles (a, b, c) and (b, a, d) (both counter-clockwise) under
/// a data-dependent criterion: the angle between their normals (radians) or the jump of the
/// derivative across the edge (|grad1 - grad2|, unitless slope). Symmetric in the two triangles.
[[nodiscard]] double edge_cost(
    Criterion criterion, const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// The two triangulations of the convex quadrilateral a, b, c, d (counter-clockwise): diagonal ac
/// (triangles abc, acd) or bd (abd, bcd). Returns +1 if the criterion strictly prefers bd, -1 if
/// it strictly prefers ac, 0 on a tie, for a triangle or edge-length criterion (the 7 of 000 §2.2
/// and inradius; R10). Exact for maxmin-angle (incircle) and shortest-diagonal (exact distance
/// comparison). @pre a, b, c, d strictly convex.
[[nodiscard]] int compare_quad_diagonals(
    Criterion criterion, const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// Edges of @p tin that a flip would strictly improve under @p criterion: interior, not
/// constrained, convex quadrilateral, better after the flip (R11). Locally optimal = empty. Each
/// edge is reported once as (smaller vertex, larger vertex); at most @p limit are listed (all
/// are counted in the return value of count_improvable_edges).
[[nodiscard]] std::vector<std::pair<VertexIndex, VertexIndex>> improvable_edges(
    const Tin& tin, Criterion criterion, std::size_t limit = 20);
[[nodiscard]] std::size_t count_improvable_edges(const Tin& tin, Criterion criterion);

/// The quality vector of a triangulation under @p criterion: per-triangle values (triangle
/// kinds), edge lengths (edge_length), or interior-edge costs (edge_cost_sum), sorted worst
/// first (ascending for max-min, descending otherwise). Empty for delaunay.
[[nodiscard]] std::vector<double> quality_vector(const Tin& tin, Criterion criterion);

/// Compares two quality vectors of the same criterion: +1 if @p a is strictly better, -1 if
/// strictly worse, 0 if equal. Lexicographic (R12) for the triangle and edge-length kinds; the
/// exact sum for edge_cost_sum.
[[nodiscard]] int compare_quality(std::span<const double> a,
                                  std::span<const double> b,
                                  Criterion criterion);

/// A summary for reports: the worst entry of the quality vector, the mean and the sum.
struct QualitySummary {
    double worst = 0.0;
    double mean = 0.0;
    double sum = 0.0;
    std::size_t count = 0;
};
[[nodiscard]] QualitySummary summarize_quality(std::span<const double> vector);

}  // namespace dtm
