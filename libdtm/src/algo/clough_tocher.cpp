// SPDX-License-Identifier: MIT
// The Clough-Tocher element in Bezier form.
//
// The triangle v0 v1 v2 is split at its centroid c into three sub-triangles (vi, vj, c); on each
// the surface is a cubic with ten Bezier ordinates (19 distinct ones in the whole triangle):
//
//                     v2                 f_i    the corner height
//                    /  \                e_ij   f_i + D_ij / 3, on edge vi vj next to vi
//                e20    e21              in_i   f_i + (D_ij + D_ik) / 9, towards c (the
//                /  in2   \                     corner's tangent plane)
//             e02   q2    e12            mid_k  the ordinate of sub-triangle (vi, vj, c) next to
//             / in0  s  in1\                    its outer edge: the derivative across edge
//           v0 -e01--e10-- v1                   vi vj is linear along it (the "reduced" element)
//                                        q_i    (in_i + mid_j + mid_k) / 3, s = mean of q_i:
//                                               C1 across the three inner edges
//
// D_ij is the derivative along the edge vector vj - vi at vi. The inner conditions are the
// C1 conditions of Bezier patches on a centroid split (all barycentric weights 1/3); the outer
// ordinate solves "the derivative along the edge normal is linear" on the row of ordinates
// next to the edge, which depends only on the edge's own data, so neighbours join C1.
//
// References: R. W. Clough and J. L. Tocher, "Finite element stiffness matrices for analysis of
// plate bending", 1965; G. Farin, "Triangular Bernstein-Bezier patches", CAGD 3(2), 1986
// (Bezier form and the C1 conditions); P. Lancaster and K. Salkauskas, "Curve and Surface
// Fitting", 1986 (the reduced element with linear normal derivatives).
#include "dtm/algo/clough_tocher.hpp"

#include <algorithm>
#include <cmath>

namespace dtm {
namespace {

double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

}  // namespace

CloughTocherPatch::CloughTocherPatch(const std::array<Point3, 3>& v, const CornerDerivatives& d) {
    ox_ = v[0].x;
    oy_ = v[0].y;
    const double bx = v[1].x - ox_, by = v[1].y - oy_;
    const double cx = v[2].x - ox_, cy = v[2].y - oy_;
    const double det = cross(bx, by, cx, cy);
    a1x_ = cy / det;
    a1y_ = -cx / det;
    a2x_ = -by / det;
    a2y_ = bx / det;
    for (int i = 0; i < 3; ++i) {
        const auto k = static_cast<std::size_t>(i);
        f_[k] = v[k].z;
        e_[k][0] = f_[k] + d[k][0] / 3.0;
        e_[k][1] = f_[k] + d[k][1] / 3.0;
        in_[k] = f_[k] + (d[k][0] + d[k][1]) / 9.0;
    }
    // Centroid relative to corner 0 (exact enough: only ratios of these enter below).
    const double gx = (bx + cx) / 3.0, gy = (by + cy) / 3.0;
    const double px[3] = {0.0, bx, cx}, py[3] = {0.0, by, cy};
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t i = (k + 1) % 3, j = (k + 2) % 3;
        const double ex = px[j] - px[i], ey = py[j] - py[i];  // the edge vi -> vj
        const double wx = gx - px[i], wy = gy - py[i];        // vi -> centroid
        const double nx = -ey, ny = ex;                       // inward normal of the edge
        // n = b e + c w in the sub-triangle (vi, vj, c); barycentric direction (a, b, c).
        const double dw = cross(ex, ey, wx, wy);
        const double b = cross(nx, ny, wx, wy) / dw;
        const double c = cross(ex, ey, nx, ny) / dw;
        const double a = -b - c;
        const double eij = e_[i][0], eji = e_[j][1];
        const double c20 = a * f_[i] + b * eij + c * in_[i];
        const double c02 = a * eji + b * f_[j] + c * in_[j];
        mid_[k] = (0.5 * (c20 + c02) - a * eij - b * eji) / c;
    }
    for (std::size_t i = 0; i < 3; ++i) {
        q_[i] = (in_[i] + mid_[(i + 1) % 3] + mid_[(i + 2) % 3]) / 3.0;
    }
    s_ = (q_[0] + q_[1] + q_[2]) / 3.0;
}

double CloughTocherPatch::at_barycentric(double l0, double l1, double l2) const {
    const double l[3] = {l0, l1, l2};
    const std::size_t k = l0 <= l1 ? (l0 <= l2 ? 0 : 2) : (l1 <= l2 ? 1 : 2);
    const std::size_t i = (k + 1) % 3, j = (k + 2) % 3;
    const double u = l[i] - l[k], v = l[j] - l[k], w = 3.0 * l[k];
    const double uu = u * u, vv = v * v, ww = w * w;
    return u * uu * f_[i] + v * vv * f_[j] + w * ww * s_ +
           3.0 * (uu * (v * e_[i][0] + w * in_[i]) + vv * (u * e_[j][1] + w * in_[j]) +
                  ww * (u * q_[i] + v * q_[j])) +
           6.0 * u * v * w * mid_[k];
}

double CloughTocherPatch::value(double x, double y) const {
    const double px = x - ox_, py = y - oy_;
    const double l1 = a1x_ * px + a1y_ * py;
    const double l2 = a2x_ * px + a2y_ * py;
    return at_barycentric(1.0 - l1 - l2, l1, l2);
}

double CloughTocherPatch::edge_value(int from, int to, double t) const {
    const auto a = static_cast<std::size_t>(from), b = static_cast<std::size_t>(to);
    const double eab = e_[a][(a + 1) % 3 == b ? 0 : 1];
    const double eba = e_[b][(b + 1) % 3 == a ? 0 : 1];
    const double s = 1.0 - t;
    return s * s * s * f_[a] + 3.0 * s * t * (s * eab + t * eba) + t * t * t * f_[b];
}

std::pair<double, double> CloughTocherPatch::bounds() const {
    double lo = s_, hi = s_;
    for (std::size_t i = 0; i < 3; ++i) {
        for (const double o : {f_[i], e_[i][0], e_[i][1], in_[i], mid_[i], q_[i]}) {
            lo = std::min(lo, o);
            hi = std::max(hi, o);
        }
    }
    return {lo, hi};
}

CornerDerivatives CubicSurface::derivatives(TriangleIndex t) const {
    const Triangle& tri = tin_.triangles[t];
    const std::uint8_t hard = gradients_.hard_edges[t];
    CornerDerivatives d{};
    for (std::size_t i = 0; i < 3; ++i) {
        const Point3& p = tin_.vertices[tri.v[i]];
        const std::uint32_t sector = gradients_.corner_sector[t][i];
        const Gradient& g = gradients_.gradient[sector];
        const double relief = gradients_.relief.empty() ? 0.0 : gradients_.relief[sector];
        for (std::size_t s = 0; s < 2; ++s) {
            const std::size_t j = (i + 1 + s) % 3;  // the other end of the edge
            const std::size_t k = (i + 2 - s) % 3;  // the edge is the one opposite corner k
            const Point3& q = tin_.vertices[tri.v[j]];
            const double rise = q.z - p.z;
            if ((hard >> k) & 1U) {
                d[i][s] = rise;
                continue;
            }
            // The derivative along the edge, bounded by three times the corner's relief
            // (Fritsch and Carlson's factor): inactive on sound data, it keeps a gradient made
            // steep by a defect (two nearby points far apart in height) from throwing a long
            // edge's cubic off.
            const double limit = 3.0 * std::max(std::abs(rise), relief);
            d[i][s] = std::clamp(g.dx * (q.x - p.x) + g.dy * (q.y - p.y), -limit, limit);
        }
    }
    return d;
}

CloughTocherPatch CubicSurface::patch(TriangleIndex t) const {
    const Triangle& tri = tin_.triangles[t];
    return CloughTocherPatch(
        {tin_.vertices[tri.v[0]], tin_.vertices[tri.v[1]], tin_.vertices[tri.v[2]]},
        derivatives(t));
}

}  // namespace dtm
