// SPDX-License-Identifier: MIT
// Splits of polygons into pseudo-triangles and the criteria choosing among them
// (pseudo_split.hpp; thesis 001 §2.3, §3.1-3.3, Tables 3.1 and 3.2).
#include "methods/detail/pseudo_split.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "algo/detail/exact_sum.hpp"
#include "methods/detail/planar.hpp"

namespace dtm::methods::detail {
namespace {

double angle_at(const Point3& v, const Point3& a, const Point3& b) {
    const double ux = a.x - v.x;
    const double uy = a.y - v.y;
    const double wx = b.x - v.x;
    const double wy = b.y - v.y;
    return std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy);
}

Cycle sub_cycle(const Cycle& q, std::size_t from, std::size_t to) {
    Cycle out;
    for (std::size_t i = from;; i = (i + 1) % q.size()) {
        out.push_back(q[i]);
        if (i == to) break;
    }
    return out;
}

/// Segment a-b conflicts with the boundary of @p q: crosses an edge not incident to a or b, or
/// passes through a vertex (Table 3.1: a T-junction counts as crossing).
bool hits_boundary(std::span<const Point3> p,
                   const Cycle& q,
                   VertexIndex a,
                   VertexIndex b,
                   CountingPredicates& pred) {
    const std::size_t k = q.size();
    for (std::size_t m = 0; m < k; ++m) {
        const VertexIndex u = q[m];
        const VertexIndex v = q[(m + 1) % k];
        if (u != a && u != b && strictly_inside_segment(pred, p[a], p[b], p[u])) return true;
        if (u == a || u == b || v == a || v == b) continue;
        if (properly_cross(pred, p[a], p[b], p[u], p[v])) return true;
    }
    return false;
}

/// Straight angle at vertex @p v of cycle @p c (where it appears).
bool straight_at(std::span<const Point3> p,
                 const Cycle& c,
                 VertexIndex v,
                 CountingPredicates& pred) {
    const std::size_t k = c.size();
    for (std::size_t i = 0; i < k; ++i) {
        if (c[i] == v) return pred.orient(p[c[(i + k - 1) % k]], p[v], p[c[(i + 1) % k]]) == 0;
    }
    return false;
}

double value_of(const FaceAngles& a, PseudoCriterion criterion) {
    switch (criterion) {
        case PseudoCriterion::maxmin_angle:
            return a.min;
        case PseudoCriterion::minmax_angle:
            return a.max;
        case PseudoCriterion::maxmin_sum_angle:
        case PseudoCriterion::minmax_sum_angle:
            return a.sum;
        case PseudoCriterion::maxmin_angle_hull:
            return a.hull_min;
        case PseudoCriterion::minmax_angle_hull:
            return a.hull_max;
        default:
            return 0.0;
    }
}

bool larger_is_better(PseudoCriterion c) {
    return c == PseudoCriterion::maxmin_angle || c == PseudoCriterion::maxmin_sum_angle ||
           c == PseudoCriterion::maxmin_angle_hull || c == PseudoCriterion::max_length;
}

}  // namespace

std::optional<PseudoCriterion> parse_pseudo_criterion(std::string_view name) {
    static constexpr std::array<std::pair<std::string_view, PseudoCriterion>, 9> names{{
        {"random", PseudoCriterion::random},
        {"min-length", PseudoCriterion::min_length},
        {"max-length", PseudoCriterion::max_length},
        {"maxmin-angle", PseudoCriterion::maxmin_angle},
        {"minmax-angle", PseudoCriterion::minmax_angle},
        {"maxmin-sum-angle", PseudoCriterion::maxmin_sum_angle},
        {"minmax-sum-angle", PseudoCriterion::minmax_sum_angle},
        {"maxmin-angle-hull", PseudoCriterion::maxmin_angle_hull},
        {"minmax-angle-hull", PseudoCriterion::minmax_angle_hull},
    }};
    for (const auto& [n, c] : names) {
        if (n == name) return c;
    }
    return std::nullopt;
}

FaceAngles face_angles(std::span<const Point3> p, const Cycle& c, CountingPredicates& pred) {
    FaceAngles out;
    const std::size_t k = c.size();
    std::vector<std::pair<VertexIndex, double>> at;  // corner, angle
    for (std::size_t i = 0; i < k; ++i) {
        if (!is_corner(p, c, i, pred)) continue;
        at.emplace_back(c[i], angle_at(p[c[i]], p[c[(i + 1) % k]], p[c[(i + k - 1) % k]]));
    }
    if (at.empty()) return out;
    std::sort(at.begin(), at.end());
    out.min = out.max = at[0].second;
    for (const auto& [v, a] : at) {
        out.min = std::min(out.min, a);
        out.max = std::max(out.max, a);
        out.sum += a;
    }
    if (at.size() == 3) {
        const Point3& a = p[at[0].first];
        const Point3& b = p[at[1].first];
        const Point3& d = p[at[2].first];
        const double h0 = angle_at(a, b, d);
        const double h1 = angle_at(b, d, a);
        const double h2 = angle_at(d, a, b);
        out.hull_min = std::min({h0, h1, h2});
        out.hull_max = std::max({h0, h1, h2});
    }
    return out;
}

int compare_splits(std::span<const Point3> p,
                   const Split& a,
                   const Split& b,
                   PseudoCriterion criterion,
                   CountingPredicates& pred) {
    if (criterion == PseudoCriterion::random) return 0;
    if (criterion == PseudoCriterion::min_length || criterion == PseudoCriterion::max_length) {
        dtm::detail::ExactSum sum;  // sum(a) - sum(b)
        for (const auto& [u, v] : a.border) sum.add(std::hypot(p[v].x - p[u].x, p[v].y - p[u].y));
        for (const auto& [u, v] : b.border) {
            sum.subtract(std::hypot(p[v].x - p[u].x, p[v].y - p[u].y));
        }
        const int s = sum.sign();
        return criterion == PseudoCriterion::min_length ? -s : s;
    }
    auto vector_of = [&](const Split& s) {
        std::vector<double> v;
        for (const Cycle& c : s.faces) v.push_back(value_of(face_angles(p, c, pred), criterion));
        return v;
    };
    std::vector<double> va = vector_of(a);
    std::vector<double> vb = vector_of(b);
    // Worst first: ascending when larger is better, descending otherwise (lexicographic, 000 §2.3).
    const bool up = larger_is_better(criterion);
    if (up) {
        std::sort(va.begin(), va.end());
        std::sort(vb.begin(), vb.end());
    } else {
        std::sort(va.begin(), va.end(), std::greater<>());
        std::sort(vb.begin(), vb.end(), std::greater<>());
    }
    for (std::size_t i = 0; i < std::min(va.size(), vb.size()); ++i) {
        if (va[i] != vb[i]) return (va[i] > vb[i]) == up ? 1 : -1;
    }
    return 0;
}

std::size_t geodesic_tangent(std::span<const Point3> p,
                             const Cycle& c,
                             std::size_t corner,
                             const Point3& x,
                             CountingPredicates& pred) {
    const std::size_t k = c.size();
    auto at = [&](std::size_t i) -> const Point3& { return p[c[i % k]]; };
    const bool next_visible = pred.orient(at(corner), at(corner + 1), x) > 0;
    const bool prev_visible = pred.orient(at(corner + k - 1), at(corner), x) > 0;
    if (next_visible && prev_visible) return corner;
    // Walk the side that hides x, away from the corner, until an edge faces x; a side ends at
    // the next corner, which is then the tangent vertex.
    std::size_t j = corner;
    if (!next_visible) {
        for (std::size_t step = 0; step + 1 < k; ++step) {
            if (pred.orient(at(j), at(j + 1), x) > 0) break;
            j = (j + 1) % k;
            if (is_corner(p, c, j, pred)) break;
        }
        return j;
    }
    for (std::size_t step = 0; step + 1 < k; ++step) {
        if (pred.orient(at(j + k - 1), at(j), x) > 0) break;
        j = (j + k - 1) % k;
        if (is_corner(p, c, j, pred)) break;
    }
    return j;
}

bool is_pseudo_triangle(std::span<const Point3> p, const Cycle& c, CountingPredicates& pred) {
    if (c.size() < 3) return false;
    std::size_t convex = 0;
    for (std::size_t i = 0; i < c.size(); ++i) convex += is_corner(p, c, i, pred) ? 1 : 0;
    return convex == 3;
}

std::vector<Split> point_splits(std::span<const Point3> p,
                                const Cycle& c,
                                VertexIndex q,
                                CountingPredicates& pred) {
    std::vector<Split> out;
    const std::vector<std::size_t> cs = corners(p, c, pred);
    if (cs.size() != 3) return out;
    std::array<std::size_t, 3> w{};
    for (int i = 0; i < 3; ++i) w[i] = geodesic_tangent(p, c, cs[i], p[q], pred);
    for (int i = 0; i < 3; ++i) {
        const std::size_t wa = w[i];
        const std::size_t wb = w[(i + 1) % 3];
        if (wa == wb) continue;
        Split s;
        Cycle x{q};
        for (const VertexIndex v : sub_cycle(c, wa, wb)) x.push_back(v);
        Cycle y{q};
        for (const VertexIndex v : sub_cycle(c, wb, wa)) y.push_back(v);
        if (!is_pseudo_triangle(p, x, pred) || !is_pseudo_triangle(p, y, pred)) continue;
        s.faces = {std::move(x), std::move(y)};
        s.border = {{std::min(q, c[wa]), std::max(q, c[wa])},
                    {std::min(q, c[wb]), std::max(q, c[wb])}};
        out.push_back(std::move(s));
    }
    return out;
}

std::optional<Split> try_diagonal(std::span<const Point3> p,
                                  const Cycle& q,
                                  std::size_t i,
                                  std::size_t j,
                                  CountingPredicates& pred,
                                  bool allow_straight) {
    const std::size_t k = q.size();
    if (i == j || (i + 1) % k == j || (j + 1) % k == i) return std::nullopt;
    const Point3& v = p[q[i]];
    const Point3& prev = p[q[(i + k - 1) % k]];
    const Point3& next = p[q[(i + 1) % k]];
    const Point3& d = p[q[j]];
    // Table 3.2, with e1 towards the previous vertex and e2 towards the next one.
    const bool left_e1 = pred.orient(v, prev, d) > 0;
    const bool left_e2 = pred.orient(v, next, d) > 0;
    const bool reflex = pred.orient(prev, v, next) < 0;
    const bool inside = reflex ? (!left_e1 || left_e2) : (!left_e1 && left_e2);
    if (!inside || hits_boundary(p, q, q[i], q[j], pred)) return std::nullopt;
    Split s;
    s.faces = {sub_cycle(q, i, j), sub_cycle(q, j, i)};
    for (const Cycle& f : s.faces) {
        if (!is_pseudo_triangle(p, f, pred) ||
            (!allow_straight && (straight_at(p, f, q[i], pred) || straight_at(p, f, q[j], pred)))) {
            return std::nullopt;
        }
    }
    s.border = {{std::min(q[i], q[j]), std::max(q[i], q[j])}};
    return s;
}

std::vector<Split> brute_splits(std::span<const Point3> p,
                                const Cycle& q,
                                VertexIndex in,
                                CountingPredicates& pred) {
    std::vector<Split> out;
    const std::size_t k = q.size();
    if (in == no_vertex) {
        for (std::size_t i = 0; i + 2 < k; ++i) {
            for (std::size_t j = i + 2; j < k; ++j) {
                if (i == 0 && j == k - 1) continue;  // the wrap-around pair is an edge
                if (auto s = try_diagonal(p, q, i, j, pred)) out.push_back(std::move(*s));
            }
        }
        return out;
    }
    // Two common edges: segments from the interior point, in pairs (O(k^2) pairs, O(k) checks).
    std::vector<bool> clear(k);
    for (std::size_t i = 0; i < k; ++i) clear[i] = !hits_boundary(p, q, in, q[i], pred);
    for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = i + 1; j < k && clear[i]; ++j) {
            if (!clear[j]) continue;
            Cycle x{in};
            for (const VertexIndex v : sub_cycle(q, i, j)) x.push_back(v);
            Cycle y{in};
            for (const VertexIndex v : sub_cycle(q, j, i)) y.push_back(v);
            if (!is_pseudo_triangle(p, x, pred) || !is_pseudo_triangle(p, y, pred)) continue;
            Split s;
            s.faces = {std::move(x), std::move(y)};
            s.border = {{std::min(in, q[i]), std::max(in, q[i])},
                        {std::min(in, q[j]), std::max(in, q[j])}};
            out.push_back(std::move(s));
        }
    }
    return out;
}

}  // namespace dtm::methods::detail
