// SPDX-License-Identifier: MIT
// Expansion arithmetic: scale-expansion and fast expansion sum with zero elimination
// (Shewchuk 1997, "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", Theorems 13 and 19). Compiled with -ffp-contract=off (see libdtm/CMakeLists.txt).
#include "geom/detail/expansion.hpp"

#include <cmath>

namespace dtm::geom::detail {

int scale_expansion(int elen, const double* e, double b, double* h) noexcept
{
    double bhi = 0.0;
    double blo = 0.0;
    split(b, bhi, blo);
    double q = 0.0;
    double hh = 0.0;
    int n = 0;
    two_product_presplit(e[0], b, bhi, blo, q, hh);
    if (hh != 0.0) {
        h[n++] = hh;
    }
    for (int i = 1; i < elen; ++i) {
        double p1 = 0.0;
        double p0 = 0.0;
        double sum = 0.0;
        two_product_presplit(e[i], b, bhi, blo, p1, p0);
        two_sum(q, p0, sum, hh);
        if (hh != 0.0) {
            h[n++] = hh;
        }
        fast_two_sum(p1, sum, q, hh);
        if (hh != 0.0) {
            h[n++] = hh;
        }
    }
    if (q != 0.0 || n == 0) {
        h[n++] = q;
    }
    return n;
}

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
