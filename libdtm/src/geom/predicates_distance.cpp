// SPDX-License-Identifier: MIT
// compare_distance: the exact sign of |ab|^2 - |cd|^2.
//
// Filter: each squared distance computed in double carries a relative error of at most
// 4 eps + O(eps^2) (one rounding for each difference, each square and the sum, all of
// non-negative terms), so when the two computed values differ by more than 6 eps times their
// sum (plus an absolute guard for underflowed products) the computed sign is the true one.
// Otherwise, and for non-finite intermediates, the exact value is evaluated in big integers
// (geom/detail/bigint.hpp): slow, but only near-ties reach it (a regular grid's equal edges).
#include <cmath>

#include "dtm/geom/predicates.hpp"
#include "geom/detail/bigint.hpp"

namespace dtm::geom {
namespace {

int compare_distance_bigint(const double (&v)[8]) noexcept {
    for (const double x : v) {
        if (!std::isfinite(x)) {
            return 0;  // outside the contract (finite input)
        }
    }
    using detail::BigInt;
    const int base = detail::common_exponent(v, 8);
    BigInt total;
    for (int k = 0; k < 4; ++k) {
        // k = 0, 1: the x and y terms of |ab|^2; k = 2, 3: of |cd|^2, subtracted.
        const int i = k < 2 ? k : 4 + (k - 2);
        BigInt diff;
        detail::bigint_sub(detail::bigint_from_double(v[i], base),
                           detail::bigint_from_double(v[i + 2], base), diff);
        BigInt square;
        detail::bigint_mul(diff, diff, square);
        if (k < 2) {
            detail::bigint_add(total, square, total);
        } else {
            detail::bigint_sub(total, square, total);
        }
    }
    return total.sign;
}

}  // namespace

int compare_distance(double ax,
                     double ay,
                     double bx,
                     double by,
                     double cx,
                     double cy,
                     double dx,
                     double dy) noexcept {
    const double abx = ax - bx;
    const double aby = ay - by;
    const double cdx = cx - dx;
    const double cdy = cy - dy;
    const double ab = abx * abx + aby * aby;
    const double cd = cdx * cdx + cdy * cdy;
    const double diff = ab - cd;
    constexpr double bound = 6.0 * 0x1p-53;
    constexpr double guard = 0x1p-1000;
    if (std::abs(diff) > bound * (ab + cd) + guard) [[likely]] {
        return diff > 0.0 ? 1 : -1;
    }
    const double v[8] = {ax, ay, bx, by, cx, cy, dx, dy};
    return compare_distance_bigint(v);
}

}  // namespace dtm::geom
