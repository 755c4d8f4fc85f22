// SPDX-License-Identifier: MIT
// Exact slow paths of orient3d and compare_distances (dtm/geom/predicates.hpp), behind their
// inline stage-A filters. Each evaluates its determinant exactly: every coordinate difference
// as a two-component expansion (rounded value + tail), multiplied out and summed with
// expansion arithmetic (Shewchuk 1997, sections 2.5-2.8). Reached only when the filter cannot
// decide (coplanar or nearly coplanar points, equal or nearly equal distances), so one exact
// stage replaces Shewchuk's B and C. Outside the range where expansions cannot overflow or
// underflow, the determinants are evaluated in big integers (geom/detail/bigint.hpp).
// Compiled with -ffp-contract=off.
#include <cmath>

#include "dtm/geom/predicates.hpp"
#include "geom/detail/bigint.hpp"
#include "geom/detail/expansion.hpp"

namespace dtm::geom::detail {
namespace {

/// Degree-3 products of values in [2^-280, 2^330] are multiples of 2^-996 and below 2^996.
constexpr double orient3d_min_abs = 0x1p-280;
constexpr double orient3d_max_abs = 0x1p+330;
/// Degree 2, as orient2d: multiples of 2^-904 and below 2^1006.
constexpr double distance_min_abs = 0x1p-400;
constexpr double distance_max_abs = 0x1p+500;

bool in_range(const double* v, int n, double min_abs, double max_abs) noexcept {
    for (int i = 0; i < n; ++i) {
        const double a = std::abs(v[i]);
        if (!(a <= max_abs) || (a != 0.0 && a < min_abs)) return false;
    }
    return true;
}

bool all_finite(const double* v, int n) noexcept {
    for (int i = 0; i < n; ++i) {
        if (!std::isfinite(v[i])) return false;
    }
    return true;
}

/// z * (px qy - py qx) for exact differences, exactly. Returns the length of out (<= 64).
int cross_times(const ExactDiff& px,
                const ExactDiff& py,
                const ExactDiff& qx,
                const ExactDiff& qy,
                const ExactDiff& z,
                double* out) noexcept {
    double m[8];
    double n[8];
    double cross[16];
    const int mlen = expansion_product<8>(2, px.v, 2, qy.v, m);
    const int nlen = expansion_product<8>(2, py.v, 2, qx.v, n);
    for (int i = 0; i < nlen; ++i) n[i] = -n[i];
    const int crosslen = expansion_sum(mlen, m, nlen, n, cross);
    return expansion_product<64>(crosslen, cross, 2, z.v, out);
}

int orient3d_expansion(const double* a,
                       const double* b,
                       const double* c,
                       const double* d) noexcept {
    ExactDiff ad[3];
    ExactDiff bd[3];
    ExactDiff cd[3];
    for (int k = 0; k < 3; ++k) {
        ad[k] = exact_diff(a[k], d[k]);
        bd[k] = exact_diff(b[k], d[k]);
        cd[k] = exact_diff(c[k], d[k]);
    }
    double ta[64];
    double tb[64];
    double tc[64];
    double tab[128];
    double total[192];
    const int alen = cross_times(bd[0], bd[1], cd[0], cd[1], ad[2], ta);
    const int blen = cross_times(cd[0], cd[1], ad[0], ad[1], bd[2], tb);
    const int clen = cross_times(ad[0], ad[1], bd[0], bd[1], cd[2], tc);
    const int ablen = expansion_sum(alen, ta, blen, tb, tab);
    return expansion_sign(expansion_sum(ablen, tab, clen, tc, total), total);
}

/// The same determinant in big integers (all twelve coordinates on one power of two).
int orient3d_bigint(const double* a, const double* b, const double* c, const double* d) noexcept {
    double v[12];
    for (int k = 0; k < 3; ++k) {
        v[k] = a[k];
        v[3 + k] = b[k];
        v[6 + k] = c[k];
        v[9 + k] = d[k];
    }
    const int base = common_exponent(v, 12);
    BigInt ad[3];
    BigInt bd[3];
    BigInt cd[3];
    for (int k = 0; k < 3; ++k) {
        const BigInt dk = bigint_from_double(d[k], base);
        bigint_sub(bigint_from_double(a[k], base), dk, ad[k]);
        bigint_sub(bigint_from_double(b[k], base), dk, bd[k]);
        bigint_sub(bigint_from_double(c[k], base), dk, cd[k]);
    }
    auto term = [](const BigInt& px, const BigInt& py, const BigInt& qx, const BigInt& qy,
                   const BigInt& z, BigInt& out) {
        BigInt t1;
        BigInt t2;
        bigint_mul(px, qy, t1);
        bigint_mul(py, qx, t2);
        bigint_sub(t1, t2, t1);
        bigint_mul(t1, z, out);
    };
    BigInt sum;
    BigInt t;
    term(bd[0], bd[1], cd[0], cd[1], ad[2], sum);
    term(cd[0], cd[1], ad[0], ad[1], bd[2], t);
    bigint_add(sum, t, sum);
    term(ad[0], ad[1], bd[0], bd[1], cd[2], t);
    bigint_add(sum, t, sum);
    return sum.sign;
}

int distances_bigint(const double* v) noexcept {
    const int base = common_exponent(v, 8);
    BigInt diff[4];
    for (int k = 0; k < 4; ++k) {
        // (a - b) x, (a - b) y, (c - d) x, (c - d) y
        const int p = k < 2 ? k : k + 2;
        bigint_sub(bigint_from_double(v[p], base), bigint_from_double(v[p + 2], base), diff[k]);
    }
    BigInt sq[4];
    for (int k = 0; k < 4; ++k) bigint_mul(diff[k], diff[k], sq[k]);
    BigInt l1;
    BigInt l2;
    bigint_add(sq[0], sq[1], l1);
    bigint_add(sq[2], sq[3], l2);
    bigint_sub(l1, l2, l1);
    return l1.sign;
}

}  // namespace

int orient3d_exact(const double* a, const double* b, const double* c, const double* d) noexcept {
    double v[12];
    for (int k = 0; k < 3; ++k) {
        v[k] = a[k];
        v[3 + k] = b[k];
        v[6 + k] = c[k];
        v[9 + k] = d[k];
    }
    if (!all_finite(v, 12)) return 0;  // outside the contract (finite input)
    if (!in_range(v, 12, orient3d_min_abs, orient3d_max_abs)) {
        return orient3d_bigint(a, b, c, d);
    }
    return orient3d_expansion(a, b, c, d);
}

int compare_distances_exact(double ax,
                            double ay,
                            double bx,
                            double by,
                            double cx,
                            double cy,
                            double dx,
                            double dy) noexcept {
    const double v[8] = {ax, ay, bx, by, cx, cy, dx, dy};
    if (!all_finite(v, 8)) return 0;
    if (!in_range(v, 8, distance_min_abs, distance_max_abs)) return distances_bigint(v);
    const ExactDiff d[4] = {exact_diff(ax, bx), exact_diff(ay, by), exact_diff(cx, dx),
                            exact_diff(cy, dy)};
    double sq[4][8];
    int len[4];
    for (int k = 0; k < 4; ++k) len[k] = expansion_product<8>(2, d[k].v, 2, d[k].v, sq[k]);
    for (int k = 2; k < 4; ++k) {
        for (int i = 0; i < len[k]; ++i) sq[k][i] = -sq[k][i];
    }
    double s01[16];
    double s23[16];
    double total[32];
    const int l01 = expansion_sum(len[0], sq[0], len[1], sq[1], s01);
    const int l23 = expansion_sum(len[2], sq[2], len[3], sq[3], s23);
    return expansion_sign(expansion_sum(l01, s01, l23, s23, total), total);
}

}  // namespace dtm::geom::detail
