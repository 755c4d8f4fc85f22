// SPDX-License-Identifier: MIT
/// @file
/// @brief The super-triangle of the incremental methods, symbolic or finite: predicates on
/// vertex ids where ids n, n+1, n+2 are its corners S0, S1, S2 (counter-clockwise).
///
/// Symbolic (the default): the corners are points at infinity of different orders,
///   S0 = (-d^2, -d),   S1 = (d^4, -d^3),   S2 = (d^5, d^6),   d -> infinity,
/// and every predicate returns the sign its determinant has for all large enough d (the sign
/// of the leading coefficient of its polynomial in d). Those limits are simple and exact:
///   orient(a, b, S0) = sign(by - ay), else sign(ax - bx)
///   orient(a, b, S1) = sign(ay - by), else sign(ax - bx)
///   orient(a, b, S2) = sign(bx - ax), else sign(ay - by)   (never 0 for a != b)
///   orient(a, Si, Sj) = +1 for (i, j) = (0, 1), (1, 2), (2, 0): the triangle holds every point
///   incircle(a, b, c, S) = -orient(a, b, c); for collinear a, b, c with b between a and c
///     (after a cyclic rotation) it is orient(a, c, S), an identity of the determinant
///   incircle(a, b, Si, Sj) = -orient(a, b, Si) for i < j: the lift of Sj dominates (6 > 2*4-3)
///   incircle(a, S0, S1, S2) = -1
/// and all other argument orders follow by the determinants' antisymmetry. Every circle
/// through two real points and a corner grows without bound, so all hull edges of the input
/// survive the removal of the corners: the result is the Delaunay triangulation of the
/// points with the convex hull as its boundary (lecture 003's caveat resolved).
///
/// Finite: the lecture's literal corners (003 Alg. 1 steps 1-4: d = 100 * the larger extent of
/// the bounding box, p-1 = (xb - d, yb - d), p-2 = (xb, yb + d), p-3 = (xb + d, yb - d)) with
/// the ordinary exact predicates; kept to show that it can lose hull edges.
#pragma once

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "dtm/core/tin.hpp"
#include "methods/detail/counting_predicates.hpp"

namespace dtm::methods::detail {

class SuperTriangle {
public:
    enum class Mode { symbolic, finite };

    SuperTriangle(const std::vector<Point3>& points, CountingPredicates& predicates, Mode mode)
        : p_(points), pred_(predicates), n_(static_cast<VertexIndex>(points.size())), mode_(mode) {
        if (mode == Mode::finite) {
            Box2 box;
            for (const Point3& q : points) box.add(q);
            const double xb = 0.5 * (box.xmin + box.xmax);
            const double yb = 0.5 * (box.ymin + box.ymax);
            const double d = 100.0 * std::max(box.xmax - box.xmin, box.ymax - box.ymin);
            finite_ = {Point2{xb - d, yb - d}, Point2{xb + d, yb - d}, Point2{xb, yb + d}};
        }
    }

    [[nodiscard]] VertexIndex corner(int k) const noexcept {
        return n_ + static_cast<VertexIndex>(k);
    }
    [[nodiscard]] bool is_corner(VertexIndex v) const noexcept { return v >= n_; }
    [[nodiscard]] Mode mode() const noexcept { return mode_; }

    /// +1 if c is left of a->b, -1 right, 0 collinear.
    [[nodiscard]] int orient(VertexIndex a, VertexIndex b, VertexIndex c) {
        if (a < n_ && b < n_ && c < n_) return pred_.orient(p_[a], p_[b], p_[c]);
        return orient_with_corner(a, b, c);
    }

    /// +1 if d is strictly inside the circle through a, b, c (counter-clockwise), -1 outside,
    /// 0 on it.
    [[nodiscard]] int incircle(VertexIndex a, VertexIndex b, VertexIndex c, VertexIndex d) {
        if (a < n_ && b < n_ && c < n_ && d < n_) {
            return pred_.incircle(p_[a], p_[b], p_[c], p_[d]);
        }
        return incircle_with_corner(a, b, c, d);
    }

    /// Coordinates of a vertex: real points, or the finite corners.
    [[nodiscard]] Point2 xy(VertexIndex v) const noexcept {
        if (v < n_) return {p_[v].x, p_[v].y};
        return finite_[v - n_];
    }

private:
    // Out of line: a corner among the arguments is rare, the real points' test is inlined.
    [[gnu::noinline]] int orient_with_corner(VertexIndex a, VertexIndex b, VertexIndex c) {
        if (mode_ == Mode::finite) return pred_.orient(xy(a), xy(b), xy(c));
        // Rotations keep the sign: bring the corners to the end (one) or the real point to
        // the front (two).
        std::array<VertexIndex, 3> v{a, b, c};
        const int corners = (a >= n_) + (b >= n_) + (c >= n_);
        if (corners == 3) return permutation_sign(v);
        if (corners == 1) {
            while (v[2] < n_) rotate(v);
            return one_corner(v[0], v[1], v[2] - n_);
        }
        while (v[0] >= n_) rotate(v);
        return corners_ccw(v[1] - n_, v[2] - n_);
    }

    [[gnu::noinline]] int incircle_with_corner(VertexIndex a,
                                               VertexIndex b,
                                               VertexIndex c,
                                               VertexIndex d) {
        if (mode_ == Mode::finite) return pred_.incircle(xy(a), xy(b), xy(c), xy(d));
        // Stable sort by key (real points first, then corners by index), counting swaps.
        std::array<VertexIndex, 4> v{a, b, c, d};
        int sign = 1;
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j + 1 < 4 - i; ++j) {
                if (key(v[static_cast<std::size_t>(j)]) > key(v[static_cast<std::size_t>(j + 1)])) {
                    std::swap(v[static_cast<std::size_t>(j)], v[static_cast<std::size_t>(j + 1)]);
                    sign = -sign;
                }
            }
        }
        if (v[1] >= n_) return -sign;  // (a, S0, S1, S2)
        if (v[2] >= n_) return -sign * one_corner(v[0], v[1], v[2] - n_);
        // One corner: the three real points decide.
        const int o = pred_.orient(xy(v[0]), xy(v[1]), xy(v[2]));
        if (o != 0) return -sign * o;
        std::array<VertexIndex, 3> r{v[0], v[1], v[2]};  // collinear: the middle one second
        while (!between(r[0], r[1], r[2])) {
            const VertexIndex t = r[0];
            r[0] = r[1];
            r[1] = r[2];
            r[2] = t;
        }
        return sign * one_corner(r[0], r[2], v[3] - n_);
    }

    static void rotate(std::array<VertexIndex, 3>& v) noexcept {
        const VertexIndex t = v[2];
        v[2] = v[1];
        v[1] = v[0];
        v[0] = t;
    }
    [[nodiscard]] int key(VertexIndex v) const noexcept {
        return v < n_ ? -1 : static_cast<int>(v - n_);
    }
    /// orient(Si, Sj) seen from any real point: +1 for the counter-clockwise pairs.
    static int corners_ccw(VertexIndex i, VertexIndex j) noexcept {
        return (j == (i + 1) % 3) ? 1 : -1;
    }
    /// Sign of a permutation of (S0, S1, S2): the even ones are its rotations.
    [[nodiscard]] int permutation_sign(const std::array<VertexIndex, 3>& v) const noexcept {
        return corners_ccw(v[0] - n_, v[1] - n_);
    }
    /// orient(a, b, Sk) for real a != b.
    [[nodiscard]] int one_corner(VertexIndex a, VertexIndex b, VertexIndex k) const noexcept {
        const Point3& pa = p_[a];
        const Point3& pb = p_[b];
        auto sgn = [](double u, double w) { return (u > w) - (u < w); };
        switch (k) {
            case 0:
                return pb.y != pa.y ? sgn(pb.y, pa.y) : sgn(pa.x, pb.x);
            case 1:
                return pb.y != pa.y ? sgn(pa.y, pb.y) : sgn(pa.x, pb.x);
            default:
                return pb.x != pa.x ? sgn(pb.x, pa.x) : sgn(pa.y, pb.y);
        }
    }
    /// b lies between a and c on their common line (lexicographic order).
    [[nodiscard]] bool between(VertexIndex a, VertexIndex b, VertexIndex c) const noexcept {
        auto less = [this](VertexIndex u, VertexIndex w) {
            return p_[u].x < p_[w].x || (p_[u].x == p_[w].x && p_[u].y < p_[w].y);
        };
        return (less(a, b) && less(b, c)) || (less(c, b) && less(b, a));
    }

    const std::vector<Point3>& p_;
    CountingPredicates& pred_;
    VertexIndex n_;
    Mode mode_;
    std::array<Point2, 3> finite_{};
};

}  // namespace dtm::methods::detail
