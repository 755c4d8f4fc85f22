// SPDX-License-Identifier: MIT
// Stage D of incircle: the exact determinant with every coordinate difference kept as a
// two-component expansion (rounded difference + tail), multiplied out with scale-expansion
// and summed with fast expansion sum (Shewchuk 1997, sections 2.7-2.8). Reached only when the
// differences are inexact (points far apart relative to their magnitude, e.g. straddling
// zero) and stages A-C could not decide, so clarity beats speed here. Compiled with
// -ffp-contract=off.
#include "geom/detail/expansion.hpp"

namespace dtm::geom::detail {

namespace {

using Diff = ExactDiff;

template <int Cap>
int multiply(int elen, const double* e, int flen, const double* f, double* h) noexcept {
    return expansion_product<Cap>(elen, e, flen, f, h);
}

/// (px^2 + py^2) * (qx ry - qy rx), exactly. Returns the length of out (<= 512).
int lifted_term(const Diff& px,
                const Diff& py,
                const Diff& qx,
                const Diff& qy,
                const Diff& rx,
                const Diff& ry,
                double* out) noexcept {
    double xx[8];
    double yy[8];
    double lift[16];
    const int xxlen = multiply<8>(2, px.v, 2, px.v, xx);
    const int yylen = multiply<8>(2, py.v, 2, py.v, yy);
    const int liftlen = expansion_sum(xxlen, xx, yylen, yy, lift);

    double m[8];
    double n[8];
    double cross[16];
    const int mlen = multiply<8>(2, qx.v, 2, ry.v, m);
    const int nlen = multiply<8>(2, qy.v, 2, rx.v, n);
    for (int i = 0; i < nlen; ++i) {
        n[i] = -n[i];
    }
    const int crosslen = expansion_sum(mlen, m, nlen, n, cross);
    return multiply<512>(liftlen, lift, crosslen, cross, out);
}

}  // namespace

int incircle_exact(double ax,
                   double ay,
                   double bx,
                   double by,
                   double cx,
                   double cy,
                   double dx,
                   double dy) noexcept {
    const Diff adx = exact_diff(ax, dx);
    const Diff ady = exact_diff(ay, dy);
    const Diff bdx = exact_diff(bx, dx);
    const Diff bdy = exact_diff(by, dy);
    const Diff cdx = exact_diff(cx, dx);
    const Diff cdy = exact_diff(cy, dy);
    double ta[512];
    double tb[512];
    double tc[512];
    double tab[1024];
    double total[1536];
    const int alen = lifted_term(adx, ady, bdx, bdy, cdx, cdy, ta);
    const int blen = lifted_term(bdx, bdy, cdx, cdy, adx, ady, tb);
    const int clen = lifted_term(cdx, cdy, adx, ady, bdx, bdy, tc);
    const int ablen = expansion_sum(alen, ta, blen, tb, tab);
    const int len = expansion_sum(ablen, tab, clen, tc, total);
    return expansion_sign(len, total);
}

}  // namespace dtm::geom::detail
