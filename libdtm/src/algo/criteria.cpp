// SPDX-License-Identifier: MIT
// Optimality criteria of a triangulation.
//
// Thesis 000 §2.2 (../shared/docs/sources/thesis-planar-triangulation-methods.md) gives seven
// criteria for choosing one of the two diagonals of a convex quadrilateral, §2.3 the local
// optimum (every quadrilateral optimal) and the global one by lexicographically compared sorted
// quality vectors; the slides 004 add the inscribed-circle radius. Two data-dependent criteria
// for terrain come from N. Dyn, D. Levin and S. Rippa, "Data dependent triangulations for
// piecewise linear interpolation", IMA J. Numer. Anal. 10 (1990) 137-154: ABN (angle between the
// normals of the two triangles at an edge) and JND (jump of the normal derivative across it),
// summed over the interior edges (their l1 measure).
//
// Values are computed in double from the corners in a canonical order (sorted by x, then y), so a
// triangle or an edge always gets the same value whichever way it is handed in; the decisions that
// can be exact are: maxmin-angle by the incircle predicate (Lawson's theorem: for a strictly
// convex, non-cocircular quadrilateral the Delaunay diagonal is the max-min-angle one, a
// cocircular one is a tie), shortest-diagonal by geom::compare_distances, and the data-dependent
// sums by exact summation of the computed costs.
#include "dtm/algo/criteria.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "algo/detail/exact_sum.hpp"
#include "algo/detail/tin_flip.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

constexpr std::array kCriteria{
    Criterion::delaunay,          Criterion::maxmin_angle,        Criterion::minmax_angle,
    Criterion::shortest_diagonal, Criterion::maxmin_circumradius, Criterion::minmax_circumradius,
    Criterion::maxmin_area,       Criterion::maxmin_height,       Criterion::maxmin_inradius,
    Criterion::normals_angle,     Criterion::normal_jump,
};

constexpr std::array<std::string_view, kCriteria.size()> kNames{
    "delaunay",          "maxmin-angle",        "minmax-angle",
    "shortest-diagonal", "maxmin-circumradius", "minmax-circumradius",
    "maxmin-area",       "maxmin-height",       "maxmin-inradius",
    "normals-angle",     "normal-jump",
};

bool before(const Point3& p, const Point3& q) noexcept {
    return p.x < q.x || (p.x == q.x && p.y < q.y);
}

/// The three corners sorted (canonical order of a triangle).
std::array<Point3, 3> canonical(const Point3& a, const Point3& b, const Point3& c) {
    std::array<Point3, 3> t{a, b, c};
    std::sort(t.begin(), t.end(), before);
    return t;
}

double length(const Point3& p, const Point3& q) noexcept {
    return std::hypot(q.x - p.x, q.y - p.y);
}

/// Angle at p between p->q and p->r, in [0, pi].
double angle_at(const Point3& p, const Point3& q, const Point3& r) noexcept {
    const double ux = q.x - p.x;
    const double uy = q.y - p.y;
    const double vx = r.x - p.x;
    const double vy = r.y - p.y;
    return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
}

struct Gradient {
    double x = 0.0;
    double y = 0.0;
};

/// Gradient of the plane through the triangle (canonical corner order).
Gradient gradient(const Point3& a, const Point3& b, const Point3& c) {
    const auto t = canonical(a, b, c);
    const double ux = t[1].x - t[0].x;
    const double uy = t[1].y - t[0].y;
    const double uz = t[1].z - t[0].z;
    const double vx = t[2].x - t[0].x;
    const double vy = t[2].y - t[0].y;
    const double vz = t[2].z - t[0].z;
    const double det = ux * vy - uy * vx;
    if (det == 0.0) return {};
    return {(uz * vy - vz * uy) / det, (ux * vz - vx * uz) / det};
}

/// Edge cost with the edge's endpoints in canonical order: p < q, l left of p->q, r right.
double edge_cost_canonical(
    Criterion criterion, const Point3& p, const Point3& q, const Point3& l, const Point3& r) {
    const Gradient g1 = gradient(p, q, l);
    const Gradient g2 = gradient(q, p, r);
    if (criterion == Criterion::normals_angle) {
        // Normals (-gx, -gy, 1); angle = atan2(|n1 x n2|, n1 . n2).
        const double cx = -g1.y * 1.0 - 1.0 * -g2.y;
        const double cy = 1.0 * -g2.x - -g1.x * 1.0;
        const double cz = -g1.x * -g2.y - -g1.y * -g2.x;
        const double dot = g1.x * g2.x + g1.y * g2.y + 1.0;
        return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot);
    }
    // Jump of the derivative in the direction normal to the edge (the jump is normal to it).
    const double ex = q.x - p.x;
    const double ey = q.y - p.y;
    const double len = std::hypot(ex, ey);
    return std::abs((g1.x - g2.x) * -ey / len + (g1.y - g2.y) * ex / len);
}

}  // namespace

std::span<const Criterion> all_criteria() { return kCriteria; }

std::string_view criterion_name(Criterion criterion) {
    return kNames[static_cast<std::size_t>(criterion)];
}

std::optional<Criterion> parse_criterion(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i) {
        if (kNames[i] == name) return kCriteria[i];
    }
    return std::nullopt;
}

CriterionKind criterion_kind(Criterion criterion) {
    switch (criterion) {
        case Criterion::delaunay:
            return CriterionKind::none;
        case Criterion::maxmin_angle:
        case Criterion::maxmin_circumradius:
        case Criterion::maxmin_area:
        case Criterion::maxmin_height:
        case Criterion::maxmin_inradius:
            return CriterionKind::triangle_max_min;
        case Criterion::minmax_angle:
        case Criterion::minmax_circumradius:
            return CriterionKind::triangle_min_max;
        case Criterion::shortest_diagonal:
            return CriterionKind::edge_length;
        case Criterion::normals_angle:
        case Criterion::normal_jump:
            return CriterionKind::edge_cost_sum;
    }
    return CriterionKind::none;
}

bool is_data_dependent(Criterion criterion) {
    return criterion_kind(criterion) == CriterionKind::edge_cost_sum;
}

double triangle_quality(Criterion criterion, const Point3& a, const Point3& b, const Point3& c) {
    const auto t = canonical(a, b, c);
    const double ab = length(t[0], t[1]);
    const double bc = length(t[1], t[2]);
    const double ca = length(t[2], t[0]);
    const double twice_area =
        std::abs((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x));
    switch (criterion) {
        case Criterion::maxmin_angle:
        case Criterion::minmax_angle: {
            const double a0 = angle_at(t[0], t[1], t[2]);
            const double a1 = angle_at(t[1], t[2], t[0]);
            const double a2 = angle_at(t[2], t[0], t[1]);
            return criterion == Criterion::maxmin_angle ? std::min({a0, a1, a2})
                                                        : std::max({a0, a1, a2});
        }
        case Criterion::maxmin_circumradius:
        case Criterion::minmax_circumradius:
            return ab * bc * ca / (2.0 * twice_area);
        case Criterion::maxmin_area:
            return 0.5 * twice_area;
        case Criterion::maxmin_height:
            return twice_area / std::max({ab, bc, ca});
        case Criterion::maxmin_inradius:
            return twice_area / (ab + bc + ca);
        default:
            return 0.0;
    }
}

double edge_cost(
    Criterion criterion, const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    if (!is_data_dependent(criterion)) return 0.0;
    // Edge a->b with c on its left (triangle a, b, c) and d on its right (triangle b, a, d).
    return before(a, b) ? edge_cost_canonical(criterion, a, b, c, d)
                        : edge_cost_canonical(criterion, b, a, d, c);
}

int compare_quad_diagonals(
    Criterion criterion, const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    switch (criterion_kind(criterion)) {
        case CriterionKind::none:
        case CriterionKind::edge_cost_sum:
            return 0;
        case CriterionKind::edge_length:
            return -geom::compare_distances(b, d, a, c);
        case CriterionKind::triangle_max_min:
        case CriterionKind::triangle_min_max:
            break;
    }
    if (criterion == Criterion::maxmin_angle) {
        // d inside the circle through a, b, c (counter-clockwise): bd is the Delaunay diagonal.
        return geom::incircle(a, b, c, d);
    }
    std::array<double, 2> now{triangle_quality(criterion, a, b, c),
                              triangle_quality(criterion, a, c, d)};
    std::array<double, 2> then{triangle_quality(criterion, a, b, d),
                               triangle_quality(criterion, b, c, d)};
    const int better = compare_quality(then, now, criterion);  // sorts copies
    return better;
}

int compare_quality(std::span<const double> a, std::span<const double> b, Criterion criterion) {
    const CriterionKind kind = criterion_kind(criterion);
    if (kind == CriterionKind::none) return 0;
    if (kind == CriterionKind::edge_cost_sum) {
        return -detail::exact_sum_difference_sign(a, b);
    }
    // Worst first: ascending for max-min, descending for the others.
    std::vector<double> x(a.begin(), a.end());
    std::vector<double> y(b.begin(), b.end());
    const bool ascending = kind == CriterionKind::triangle_max_min;
    if (ascending) {
        std::sort(x.begin(), x.end());
        std::sort(y.begin(), y.end());
    } else {
        std::sort(x.begin(), x.end(), std::greater<>());
        std::sort(y.begin(), y.end(), std::greater<>());
    }
    const std::size_t n = std::min(x.size(), y.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (x[i] != y[i]) {
            const bool a_larger = x[i] > y[i];
            return (a_larger == ascending) ? 1 : -1;
        }
    }
    return 0;
}

std::vector<double> quality_vector(const Tin& tin, Criterion criterion) {
    std::vector<double> out;
    const auto& p = tin.vertices;
    switch (criterion_kind(criterion)) {
        case CriterionKind::none:
            return out;
        case CriterionKind::triangle_max_min:
        case CriterionKind::triangle_min_max:
            out.reserve(tin.triangles.size());
            for (const Triangle& t : tin.triangles) {
                out.push_back(triangle_quality(criterion, p[t.v[0]], p[t.v[1]], p[t.v[2]]));
            }
            break;
        case CriterionKind::edge_length:
        case CriterionKind::edge_cost_sum:
            for (TriangleIndex i = 0; i < tin.triangles.size(); ++i) {
                const Triangle& t = tin.triangles[i];
                for (int s = 0; s < 3; ++s) {
                    const VertexIndex a = t.v[(s + 1) % 3];
                    const VertexIndex b = t.v[(s + 2) % 3];
                    const TriangleIndex n = t.n[s];
                    if (n != no_triangle && n < i) continue;  // each edge once
                    if (criterion == Criterion::shortest_diagonal) {
                        out.push_back(length(p[a], p[b]));
                        continue;
                    }
                    if (n == no_triangle) continue;  // border edges have no cost
                    const detail::EdgeQuad q = detail::edge_quad(tin, i, s);
                    out.push_back(edge_cost(criterion, p[q.a], p[q.b], p[q.c], p[q.d]));
                }
            }
            break;
    }
    if (criterion_kind(criterion) == CriterionKind::triangle_max_min) {
        std::sort(out.begin(), out.end());
    } else {
        std::sort(out.begin(), out.end(), std::greater<>());
    }
    return out;
}

std::vector<std::pair<VertexIndex, VertexIndex>> improvable_edges(const Tin& tin,
                                                                  Criterion criterion,
                                                                  std::size_t limit) {
    std::vector<std::pair<VertexIndex, VertexIndex>> out;
    if (criterion == Criterion::delaunay) return out;
    const detail::ConstrainedEdgeSet constrained(tin);
    for (TriangleIndex i = 0; i < tin.triangles.size() && out.size() < limit; ++i) {
        const Triangle& t = tin.triangles[i];
        for (int s = 0; s < 3 && out.size() < limit; ++s) {
            if (t.n[s] == no_triangle || t.n[s] < i) continue;
            if (detail::edge_improvable(tin, constrained, i, s, criterion)) {
                const VertexIndex a = t.v[(s + 1) % 3];
                const VertexIndex b = t.v[(s + 2) % 3];
                out.emplace_back(std::min(a, b), std::max(a, b));
            }
        }
    }
    return out;
}

std::size_t count_improvable_edges(const Tin& tin, Criterion criterion) {
    return improvable_edges(tin, criterion, static_cast<std::size_t>(-1)).size();
}

QualitySummary summarize_quality(std::span<const double> vector) {
    QualitySummary s;
    s.count = vector.size();
    if (vector.empty()) return s;
    s.worst = vector.front();
    double sum = 0.0;
    double compensation = 0.0;
    for (const double v : vector) {
        const double y = v - compensation;
        const double t = sum + y;
        compensation = (t - sum) - y;
        sum = t;
    }
    s.sum = sum;
    s.mean = sum / static_cast<double>(vector.size());
    return s;
}

}  // namespace dtm
