// SPDX-License-Identifier: MIT
// Expansion arithmetic: fast expansion sum with zero elimination (Shewchuk 1997, "Adaptive
// precision floating-point arithmetic and fast robust geometric predicates", Theorem 13);
// scale-expansion (Theorem 19) is inline in geom/detail/expansion.hpp. Compiled with -ffp-contract=off (see libdtm/CMakeLists.txt).
#include "geom/detail/expansion.hpp"

#include <cmath>

namespace dtm::geom::detail {

int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) noexcept
{
    // Merge the components by increasing magnitude, accumulating as we go: the running sum q
    // is always at least as large as anything merged so far.
    int i = 0;
    int j = 0;
    auto next = [&]() noexcept {
        if (j >= flen || (i < elen && std::abs(e[i]) < std::abs(f[j]))) {
            return e[i++];
        }
        return f[j++];
    };
    const int total = elen + flen;
    double q = next();
    double hh = 0.0;
    int n = 0;
    if (total > 1) {
        fast_two_sum(next(), q, q, hh);
        if (hh != 0.0) {
            h[n++] = hh;
        }
    }
    while (i + j < total) {
        two_sum(q, next(), q, hh);
        if (hh != 0.0) {
            h[n++] = hh;
        }
    }
    if (q != 0.0 || n == 0) {
        h[n++] = q;
    }
    return n;
}

}  // namespace dtm::geom::detail
