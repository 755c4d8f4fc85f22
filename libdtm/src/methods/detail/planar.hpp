// SPDX-License-Identifier: MIT
/// @file
/// @brief Exact planar tests built on orient2d: angular order around a point, proper crossings,
/// a point inside a segment. Shared by the greedy, monotone, enumeration and pseudo methods.
/// Each takes the method's predicates object (CountingPredicates), so the calls are counted.
#pragma once

namespace dtm::methods::detail {

/// 0 for directions in [0, pi) from the positive x axis, 1 for [pi, 2 pi). Exact (the sign of a
/// difference of doubles is exact).
template <class C, class P>
[[nodiscard]] inline int half_plane(const C& c, const P& p) noexcept {
    const double dy = p.y - c.y;
    const double dx = p.x - c.x;
    return (dy > 0.0 || (dy == 0.0 && dx > 0.0)) ? 0 : 1;
}

/// True if the direction c->p comes strictly before c->q counter-clockwise from the positive x
/// axis. Equal directions compare equal (neither before the other).
template <class Pred, class C, class P, class Q>
[[nodiscard]] inline bool angle_before(Pred& pred, const C& c, const P& p, const Q& q) noexcept {
    const int hp = half_plane(c, p);
    const int hq = half_plane(c, q);
    if (hp != hq) return hp < hq;
    return pred.orient(c, p, q) > 0;
}

/// Segments ab and cd cross at a single point interior to both.
template <class Pred, class P>
[[nodiscard]] inline bool properly_cross(
    Pred& pred, const P& a, const P& b, const P& c, const P& d) noexcept {
    const int o1 = pred.orient(a, b, c);
    const int o2 = pred.orient(a, b, d);
    if (o1 == 0 || o2 == 0 || o1 == o2) return false;
    const int o3 = pred.orient(c, d, a);
    const int o4 = pred.orient(c, d, b);
    return o3 != 0 && o4 != 0 && o3 != o4;
}

/// p lies in the relative interior of segment ab (a != b).
template <class Pred, class P, class Q>
[[nodiscard]] inline bool strictly_inside_segment(Pred& pred,
                                                  const P& a,
                                                  const P& b,
                                                  const Q& p) noexcept {
    if (pred.orient(a, b, p) != 0) return false;
    if (a.x != b.x) return (a.x < p.x && p.x < b.x) || (b.x < p.x && p.x < a.x);
    return (a.y < p.y && p.y < b.y) || (b.y < p.y && p.y < a.y);
}

/// Segments ab and cd share a point that is not a common endpoint: a proper crossing, a
/// T-junction (an endpoint inside the other) or a collinear overlap. Both non-degenerate.
template <class Pred, class P>
[[nodiscard]] inline bool segments_conflict(
    Pred& pred, const P& a, const P& b, const P& c, const P& d) noexcept {
    return properly_cross(pred, a, b, c, d) || strictly_inside_segment(pred, a, b, c) ||
           strictly_inside_segment(pred, a, b, d) || strictly_inside_segment(pred, c, d, a) ||
           strictly_inside_segment(pred, c, d, b) ||
           ((a.x == c.x && a.y == c.y && b.x == d.x && b.y == d.y) ||
            (a.x == d.x && a.y == d.y && b.x == c.x && b.y == c.y));
}

}  // namespace dtm::methods::detail
