// SPDX-License-Identifier: MIT
/// @file
/// @brief The Clough-Tocher C1 cubic on one triangle, and the C1 surface of a whole TIN.
#pragma once

#include <array>
#include <utility>

#include "dtm/algo/gradients.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// Directional derivatives of the surface at the corners of a triangle, along its edges and
/// scaled by the edge vectors: d[i][0] = grad_i . (v[i+1] - v[i]), d[i][1] = grad_i . (v[i+2] -
/// v[i]) (indices mod 3).
using CornerDerivatives = std::array<std::array<double, 2>, 3>;

/// The Clough-Tocher macro element on one counter-clockwise triangle: split at its centroid
/// into three sub-triangles, a cubic Bezier patch on each, C1 inside the triangle, interpolating
/// the corner heights and the corner derivatives. Along each edge it is the cubic Hermite curve
/// of the edge's end heights and end derivatives, and the derivative across the edge varies
/// linearly along it; so two triangles that share an edge, its end heights and end gradients
/// join C1. Reproduces every quadratic whose exact gradients are given.
class CloughTocherPatch {
public:
    CloughTocherPatch() = default;
    CloughTocherPatch(const std::array<Point3, 3>& corners, const CornerDerivatives& d);

    /// Height at (x, y) (meant for points in the triangle; outside it extrapolates).
    [[nodiscard]] double value(double x, double y) const;
    /// Height on the edge from corner @p from to corner @p to at parameter t in [0, 1] from
    /// corner @p from: the edge's cubic, the same bits from either triangle of the edge when
    /// both start at the same vertex.
    [[nodiscard]] double edge_value(int from, int to, double t) const;
    /// Smallest and largest Bezier ordinate: every height of the patch lies between them.
    [[nodiscard]] std::pair<double, double> bounds() const;

private:
    [[nodiscard]] double at_barycentric(double l0, double l1, double l2) const;

    double ox_ = 0.0, oy_ = 0.0;                ///< corner 0
    double a1x_ = 0.0, a1y_ = 0.0;              ///< l1 = a1 . (p - corner 0)
    double a2x_ = 0.0, a2y_ = 0.0;              ///< l2 = a2 . (p - corner 0)
    std::array<double, 3> f_{};                 ///< corner heights
    std::array<std::array<double, 2>, 3> e_{};  ///< edge ordinates next to corner i (to i+1, i+2)
    std::array<double, 3> in_{};                ///< ordinates next to corner i towards the centroid
    std::array<double, 3> mid_{};  ///< ordinate of the sub-triangle on the edge opposite i
    std::array<double, 3> q_{};    ///< ordinates next to the centroid towards corner i
    double s_ = 0.0;               ///< the centroid
};

/// The C1 surface of a TIN: the Clough-Tocher patch of every triangle, from the sector
/// gradients of estimate_gradients(). Along a hard breakline edge the surface is the straight
/// 3-D segment of the breakline, and the patches on its two sides take their cross slopes from
/// their own sides: the surface creases along the breakline. Every vertex height is
/// interpolated exactly. A cheap view: @p tin and @p gradients must outlive it; @p tin may be a
/// renumbered copy of the TIN the gradients were estimated on (same triangles).
class CubicSurface {
public:
    CubicSurface(const Tin& tin, const TinGradients& gradients)
        : tin_(tin), gradients_(gradients) {}
    CubicSurface(const Tin& tin, TinGradients&& gradients) = delete;  // it keeps a reference

    [[nodiscard]] CornerDerivatives derivatives(TriangleIndex t) const;
    [[nodiscard]] CloughTocherPatch patch(TriangleIndex t) const;

private:
    const Tin& tin_;
    const TinGradients& gradients_;
};

}  // namespace dtm
