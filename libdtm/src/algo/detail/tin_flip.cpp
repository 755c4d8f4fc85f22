// SPDX-License-Identifier: MIT
// Edge flips on a Tin and the criterion test of one edge (see tin_flip.hpp).
#include "algo/detail/tin_flip.hpp"

#include <array>

#include "algo/detail/exact_sum.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

constexpr int next(int i) noexcept { return i == 2 ? 0 : i + 1; }
constexpr int prev(int i) noexcept { return i == 0 ? 2 : i - 1; }

/// The vertex across the edge of triangle @p t that is shared with @p from (no_vertex if none).
VertexIndex across(const Tin& tin, TriangleIndex from, TriangleIndex t) noexcept {
    if (t == no_triangle) return no_vertex;
    const Triangle& tri = tin.triangles[t];
    for (int i = 0; i < 3; ++i) {
        if (tri.n[i] == from) return tri.v[i];
    }
    return no_vertex;
}

void relink(Tin& tin, TriangleIndex t, TriangleIndex from, TriangleIndex to) noexcept {
    if (t == no_triangle) return;
    for (TriangleIndex& n : tin.triangles[t].n) {
        if (n == from) {
            n = to;
            return;
        }
    }
}

}  // namespace

ConstrainedEdgeSet::ConstrainedEdgeSet(const Tin& tin) {
    edges_.reserve(tin.constraints.size());
    for (const ConstrainedEdge& e : tin.constraints) {
        edges_.emplace_back(std::min(e.a, e.b), std::max(e.a, e.b));
    }
    std::sort(edges_.begin(), edges_.end());
}

EdgeQuad edge_quad(const Tin& tin, TriangleIndex t, int slot) noexcept {
    EdgeQuad q;
    const Triangle& tri = tin.triangles[t];
    const TriangleIndex u = tri.n[slot];
    if (u == no_triangle) return q;
    const Triangle& ut = tin.triangles[u];
    int us = 0;
    while (us < 3 && ut.n[us] != t) ++us;
    if (us == 3) return q;
    q.valid = true;
    q.t = t;
    q.u = u;
    q.t_slot = slot;
    q.u_slot = us;
    q.c = tri.v[slot];
    q.a = tri.v[next(slot)];
    q.b = tri.v[prev(slot)];
    q.d = ut.v[us];
    return q;
}

bool quad_is_convex(const Tin& tin, const EdgeQuad& q) noexcept {
    const auto& p = tin.vertices;
    return geom::orient2d(p[q.c], p[q.a], p[q.d]) > 0 && geom::orient2d(p[q.d], p[q.b], p[q.c]) > 0;
}

bool flip_improves(const Tin& tin, const EdgeQuad& q, Criterion criterion) {
    const auto& p = tin.vertices;
    const Point3& a = p[q.a];
    const Point3& b = p[q.b];
    const Point3& c = p[q.c];
    const Point3& d = p[q.d];
    switch (criterion_kind(criterion)) {
        case CriterionKind::none:
            return false;
        case CriterionKind::triangle_max_min:
        case CriterionKind::triangle_min_max:
        case CriterionKind::edge_length:
            // Quad a, d, b, c (counter-clockwise): diagonal ab now, dc after the flip.
            return compare_quad_diagonals(criterion, a, d, b, c) > 0;
        case CriterionKind::edge_cost_sum:
            break;
    }
    // Data-dependent: the diagonal and the four sides change cost; compare the exact sums.
    const Triangle& tt = tin.triangles[q.t];
    const Triangle& ut = tin.triangles[q.u];
    const VertexIndex e_ca = across(tin, q.t, tt.n[prev(q.t_slot)]);  // beyond side c-a
    const VertexIndex e_bc = across(tin, q.t, tt.n[next(q.t_slot)]);  // beyond side b-c
    const VertexIndex e_ad = across(tin, q.u, ut.n[next(q.u_slot)]);  // beyond side a-d
    const VertexIndex e_db = across(tin, q.u, ut.n[prev(q.u_slot)]);  // beyond side d-b
    std::array<double, 5> before{};
    std::array<double, 5> after{};
    std::size_t n = 0;
    before[n] = edge_cost(criterion, a, b, c, d);
    after[n++] = edge_cost(criterion, c, d, b, a);
    if (e_ca != no_vertex) {
        before[n] = edge_cost(criterion, c, a, b, p[e_ca]);
        after[n++] = edge_cost(criterion, c, a, d, p[e_ca]);
    }
    if (e_bc != no_vertex) {
        before[n] = edge_cost(criterion, b, c, a, p[e_bc]);
        after[n++] = edge_cost(criterion, b, c, d, p[e_bc]);
    }
    if (e_ad != no_vertex) {
        before[n] = edge_cost(criterion, a, d, b, p[e_ad]);
        after[n++] = edge_cost(criterion, a, d, c, p[e_ad]);
    }
    if (e_db != no_vertex) {
        before[n] = edge_cost(criterion, d, b, a, p[e_db]);
        after[n++] = edge_cost(criterion, d, b, c, p[e_db]);
    }
    return exact_sum_difference_sign(std::span(after.data(), n), std::span(before.data(), n)) < 0;
}

bool edge_improvable(const Tin& tin,
                     const ConstrainedEdgeSet& constrained,
                     TriangleIndex t,
                     int slot,
                     Criterion criterion) {
    if (criterion == Criterion::delaunay) return false;
    const EdgeQuad q = edge_quad(tin, t, slot);
    if (!q.valid || constrained.contains(q.a, q.b) || !quad_is_convex(tin, q)) return false;
    return flip_improves(tin, q, criterion);
}

void flip(Tin& tin, const EdgeQuad& q) noexcept {
    Triangle& t = tin.triangles[q.t];
    Triangle& u = tin.triangles[q.u];
    const TriangleIndex n_bc = t.n[next(q.t_slot)];
    const TriangleIndex n_ca = t.n[prev(q.t_slot)];
    const TriangleIndex n_ad = u.n[next(q.u_slot)];
    const TriangleIndex n_db = u.n[prev(q.u_slot)];
    t.v = {q.c, q.a, q.d};
    t.n = {n_ad, q.u, n_ca};
    u.v = {q.d, q.b, q.c};
    u.n = {n_bc, q.t, n_db};
    relink(tin, n_ad, q.u, q.t);
    relink(tin, n_bc, q.t, q.u);
}

}  // namespace dtm::detail
