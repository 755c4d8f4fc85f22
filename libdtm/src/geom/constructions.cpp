// SPDX-License-Identifier: MIT
// Computed constructions (dtm/geom/constructions.hpp).
#include "dtm/geom/constructions.hpp"

#include <cmath>

namespace dtm::geom {

int nearest_right_angle(const Point2& a, const Point2& b, const Point2& c) noexcept {
    const Point2* p[3] = {&a, &b, &c};
    int k = 0;
    double best = 2.0;
    for (int m = 0; m < 3; ++m) {
        const Point2& o = *p[m];
        const Point2& u = *p[(m + 1) % 3];
        const Point2& w = *p[(m + 2) % 3];
        const double ux = u.x - o.x, uy = u.y - o.y, wx = w.x - o.x, wy = w.y - o.y;
        const double norm = std::sqrt((ux * ux + uy * uy) * (wx * wx + wy * wy));
        const double cosine = norm > 0.0 ? std::abs(ux * wx + uy * wy) / norm : 1.0;
        if (cosine < best) {
            best = cosine;
            k = m;
        }
    }
    return k;
}

Point2 circumcentre(const Point2& a, const Point2& b, const Point2& c) noexcept {
    // Relative to the corner k with the angle nearest pi/2: centre = (-J2/J4 + xk, J3/J4 + yk)
    // with the other two corners i, j (eq. 8-11).
    const Point2* p[3] = {&a, &b, &c};
    const int k = nearest_right_angle(a, b, c);
    const Point2& pk = *p[k];
    const Point2& pi = *p[(k + 1) % 3];
    const Point2& pj = *p[(k + 2) % 3];
    const double xi = pi.x - pk.x, yi = pi.y - pk.y, xj = pj.x - pk.x, yj = pj.y - pk.y;
    const double wi = 0.5 * (xi * xi + yi * yi), wj = 0.5 * (xj * xj + yj * yj);
    const double j2 = yi * wj - wi * yj;
    const double j3 = xi * wj - wi * xj;
    const double j4 = xi * yj - yi * xj;
    return {-j2 / j4 + pk.x, j3 / j4 + pk.y};
}

}  // namespace dtm::geom
