// SPDX-License-Identifier: MIT
// Adaptive exact orient2d and incircle: the slow path behind the inline filters of
// dtm/geom/predicates.hpp.
//
// Method (Shewchuk 1997, "Adaptive precision floating-point arithmetic and fast robust
// geometric predicates", Discrete & Computational Geometry 18:305-363, sections 4.2-4.4):
//   stage A  (inline) plain floating-point determinant with an a-priori error bound;
//   stage B  exact determinant of the rounded coordinate differences, as an expansion;
//            exact outright when the differences were computed without rounding
//            (always the case for nearby points: Sterbenz);
//   stage C  first-order correction with the differences' rounding errors (tails);
//   stage D  the exact determinant including every tail.
// Each stage returns as soon as its error bound proves the sign. Expansion arithmetic is
// exact only without overflow and underflow, so inputs with extreme magnitudes are routed to
// an exact big-integer evaluation instead (predicates_bigint.cpp).
// This file is compiled with -ffp-contract=off: the error-free transformations need every
// product rounded separately.
#include "dtm/geom/predicates.hpp"

#include <atomic>
#include <cmath>

#include "geom/detail/bigint.hpp"
#include "geom/detail/expansion.hpp"

namespace dtm::geom::detail {

namespace {

constexpr double orient_bound_b = (2.0 + 12.0 * epsilon) * epsilon;
constexpr double orient_bound_c = (9.0 + 64.0 * epsilon) * epsilon * epsilon;
constexpr double incircle_bound_b = (4.0 + 48.0 * epsilon) * epsilon;
constexpr double incircle_bound_c = (44.0 + 576.0 * epsilon) * epsilon * epsilon;
constexpr double result_bound = (3.0 + 8.0 * epsilon) * epsilon;

int sign_of(double v) noexcept { return (v > 0.0) - (v < 0.0); }

/// True when expansion arithmetic on these coordinates cannot overflow or underflow: every
/// non-zero |v| lies in [min_abs, max_abs]. With min_abs = 2^k every coordinate, difference
/// and tail is a multiple of 2^(k-52), so a degree-n product is a multiple of 2^(n(k-52)),
/// which must stay above the smallest normal double 2^-1022; max_abs bounds the largest
/// degree-n term, which must stay well below 2^1024.
bool in_expansion_range(const double* v, int n, double min_abs, double max_abs) noexcept {
    for (int i = 0; i < n; ++i) {
        const double a = std::abs(v[i]);
        if (!(a <= max_abs) || (a != 0.0 && a < min_abs)) {
            return false;
        }
    }
    return true;
}

/// Degree 2: multiples of 2^-904 and below 2^1006.
constexpr double orient_min_abs = 0x1p-400;
constexpr double orient_max_abs = 0x1p+500;
/// Degree 4: multiples of 2^-1008 and below 2^1010.
constexpr double incircle_min_abs = 0x1p-200;
constexpr double incircle_max_abs = 0x1p+250;

/// Stage D of orient2d: b (the exact determinant of the rounded differences) plus every
/// product involving a tail, exactly.
template <bool Fma>
DTM_PREDICATES_INLINE int orient_stage_d(const double* b,
                                         double acx,
                                         double acy,
                                         double bcx,
                                         double bcy,
                                         double acxt,
                                         double acyt,
                                         double bcxt,
                                         double bcyt) noexcept {
    double u[4];
    double c1[8];
    double c2[12];
    double d[16];
    double s1 = 0.0;
    double s0 = 0.0;
    double t1 = 0.0;
    double t0 = 0.0;
    two_product<Fma>(acxt, bcy, s1, s0);
    two_product<Fma>(acyt, bcx, t1, t0);
    two_two_diff(s1, s0, t1, t0, u);
    const int c1len = expansion_sum(4, b, 4, u, c1);
    two_product<Fma>(acx, bcyt, s1, s0);
    two_product<Fma>(acy, bcxt, t1, t0);
    two_two_diff(s1, s0, t1, t0, u);
    const int c2len = expansion_sum(c1len, c1, 4, u, c2);
    two_product<Fma>(acxt, bcyt, s1, s0);
    two_product<Fma>(acyt, bcxt, t1, t0);
    two_two_diff(s1, s0, t1, t0, u);
    const int dlen = expansion_sum(c2len, c2, 4, u, d);
    return expansion_sign(dlen, d);
}

/// Stages B-D of orient2d (coordinates already checked to be in the expansion range).
template <bool Fma>
DTM_PREDICATES_INLINE int orient_stages(
    double ax, double ay, double bx, double by, double cx, double cy, double detsum) noexcept {
    const double acx = ax - cx;
    const double bcx = bx - cx;
    const double acy = ay - cy;
    const double bcy = by - cy;

    // Stage B: (acx * bcy - acy * bcx) exactly.
    double l1 = 0.0;
    double l0 = 0.0;
    double r1 = 0.0;
    double r0 = 0.0;
    two_product<Fma>(acx, bcy, l1, l0);
    two_product<Fma>(acy, bcx, r1, r0);
    double b[4];
    two_two_diff(l1, l0, r1, r0, b);
    double det = estimate(4, b);
    double bound = orient_bound_b * detsum;
    if (det >= bound || -det >= bound) {
        return sign_of(det);
    }

    const double acxt = two_diff_tail(ax, cx, acx);
    const double bcxt = two_diff_tail(bx, cx, bcx);
    const double acyt = two_diff_tail(ay, cy, acy);
    const double bcyt = two_diff_tail(by, cy, bcy);
    if (acxt == 0.0 && acyt == 0.0 && bcxt == 0.0 && bcyt == 0.0) {
        return expansion_sign(4, b);  // the differences were exact, so b is the determinant
    }

    // Stage C: first-order correction.
    bound = orient_bound_c * detsum + result_bound * std::abs(det);
    det += (acx * bcyt + bcy * acxt) - (acy * bcxt + bcx * acyt);
    if (det >= bound || -det >= bound) {
        return sign_of(det);
    }

    return orient_stage_d<Fma>(b, acx, acy, bcx, bcy, acxt, acyt, bcxt, bcyt);
}

/// out = (px^2 + py^2) * bc for a scalar pair (px, py) and the 4-component expansion bc.
template <bool Fma>
DTM_PREDICATES_INLINE int lift_times(const double* bc, double px, double py, double* out) noexcept {
    double x1[8];
    double x2[16];
    double y1[8];
    double y2[16];
    const int x1len = scale_expansion<Fma>(4, bc, px, x1);
    const int x2len = scale_expansion<Fma>(x1len, x1, px, x2);
    const int y1len = scale_expansion<Fma>(4, bc, py, y1);
    const int y2len = scale_expansion<Fma>(y1len, y1, py, y2);
    return expansion_sum(x2len, x2, y2len, y2, out);
}

/// (p1 p0) * (q1 q0) - (r1 r0) * (s1 s0) for four scalars: the exact 2x2 minor.
template <bool Fma>
DTM_PREDICATES_INLINE void exact_minor(
    double p, double q, double r, double s, double* out4) noexcept {
    double m1 = 0.0;
    double m0 = 0.0;
    double n1 = 0.0;
    double n0 = 0.0;
    two_product<Fma>(p, q, m1, m0);
    two_product<Fma>(r, s, n1, n0);
    two_two_diff(m1, m0, n1, n0, out4);
}

/// Exact incircle of the differences when every product and sum of the determinant's
/// lower levels happens to be exact in plain doubles, as on integer or binary-fraction grids
/// (where exact cocircularity is common). Returns 2 when some step was inexact.
template <bool Fma>
DTM_PREDICATES_INLINE int incircle_short(
    double adx, double ady, double bdx, double bdy, double cdx, double cdy) noexcept {
    bool exact = true;
    auto product = [&exact](double a, double b) noexcept {
        double p = 0.0;
        double e = 0.0;
        two_product<Fma>(a, b, p, e);
        exact = exact && e == 0.0;
        return p;
    };
    auto sum = [&exact](double a, double b) noexcept {
        double x = 0.0;
        double e = 0.0;
        two_sum(a, b, x, e);
        exact = exact && e == 0.0;
        return x;
    };
    const double ma = sum(product(bdx, cdy), -product(cdx, bdy));
    const double mb = sum(product(cdx, ady), -product(adx, cdy));
    const double mc = sum(product(adx, bdy), -product(bdx, ady));
    const double la = sum(product(adx, adx), product(ady, ady));
    const double lb = sum(product(bdx, bdx), product(bdy, bdy));
    const double lc = sum(product(cdx, cdx), product(cdy, cdy));
    if (!exact) {
        return 2;
    }
    double ta[2];
    double tb[2];
    double tc[2];
    double tab[4];
    double total[6];
    two_product<Fma>(la, ma, ta[1], ta[0]);
    two_product<Fma>(lb, mb, tb[1], tb[0]);
    two_product<Fma>(lc, mc, tc[1], tc[0]);
    const int ablen = expansion_sum(2, ta, 2, tb, tab);
    return expansion_sign(expansion_sum(ablen, tab, 2, tc, total), total);
}

/// Stage B of incircle: the exact determinant of the rounded differences into fin[96].
template <bool Fma>
DTM_PREDICATES_INLINE int incircle_stage_b(
    double adx, double ady, double bdx, double bdy, double cdx, double cdy, double* fin) noexcept {
    double bc[4];
    double ca[4];
    double ab[4];
    exact_minor<Fma>(bdx, cdy, cdx, bdy, bc);
    exact_minor<Fma>(cdx, ady, adx, cdy, ca);
    exact_minor<Fma>(adx, bdy, bdx, ady, ab);
    double adet[32];
    double bdet[32];
    double cdet[32];
    double abdet[64];
    const int alen = lift_times<Fma>(bc, adx, ady, adet);
    const int blen = lift_times<Fma>(ca, bdx, bdy, bdet);
    const int clen = lift_times<Fma>(ab, cdx, cdy, cdet);
    const int ablen = expansion_sum(alen, adet, blen, bdet, abdet);
    return expansion_sum(ablen, abdet, clen, cdet, fin);
}

/// A coordinate difference (x, y) and its rounding errors (xt, yt).
struct Rounded {
    double x;
    double y;
    double xt;
    double yt;
};

/// Stage C term of p: the part of lift(p) * cross(q, r) linear in the tails (Shewchuk 4.4).
DTM_PREDICATES_INLINE double first_order(const Rounded& p,
                                         const Rounded& q,
                                         const Rounded& r) noexcept {
    return (p.x * p.x + p.y * p.y) * ((q.x * r.yt + r.y * q.xt) - (q.y * r.xt + r.x * q.yt)) +
           2.0 * (p.x * p.xt + p.y * p.yt) * (q.x * r.y - q.y * r.x);
}

/// Stages B-D of incircle (coordinates already checked to be in the expansion range).
template <bool Fma>
DTM_PREDICATES_INLINE int incircle_stages(double ax,
                                          double ay,
                                          double bx,
                                          double by,
                                          double cx,
                                          double cy,
                                          double dx,
                                          double dy,
                                          double permanent) noexcept {
    const double adx = ax - dx;
    const double bdx = bx - dx;
    const double cdx = cx - dx;
    const double ady = ay - dy;
    const double bdy = by - dy;
    const double cdy = cy - dy;
    const double adxt = two_diff_tail(ax, dx, adx);
    const double adyt = two_diff_tail(ay, dy, ady);
    const double bdxt = two_diff_tail(bx, dx, bdx);
    const double bdyt = two_diff_tail(by, dy, bdy);
    const double cdxt = two_diff_tail(cx, dx, cdx);
    const double cdyt = two_diff_tail(cy, dy, cdy);
    const bool exact_differences =
        adxt == 0.0 && bdxt == 0.0 && cdxt == 0.0 && adyt == 0.0 && bdyt == 0.0 && cdyt == 0.0;
    if (exact_differences) {
        const int s = incircle_short<Fma>(adx, ady, bdx, bdy, cdx, cdy);
        if (s != 2) {
            return s;
        }
    }

    // Stage B: the determinant of the rounded differences, exactly.
    double fin[96];
    const int finlen = incircle_stage_b<Fma>(adx, ady, bdx, bdy, cdx, cdy, fin);
    double det = estimate(finlen, fin);
    double bound = incircle_bound_b * permanent;
    if (det >= bound || -det >= bound) {
        return sign_of(det);
    }

    if (exact_differences) {
        return expansion_sign(finlen, fin);  // exact differences: fin is the determinant
    }

    // Stage C: first-order correction with the tails.
    bound = incircle_bound_c * permanent + result_bound * std::abs(det);
    const Rounded a{adx, ady, adxt, adyt};
    const Rounded b{bdx, bdy, bdxt, bdyt};
    const Rounded c{cdx, cdy, cdxt, cdyt};
    det += (first_order(a, b, c) + first_order(b, c, a)) + first_order(c, a, b);
    if (det >= bound || -det >= bound) {
        return sign_of(det);
    }
    return incircle_exact(ax, ay, bx, by, cx, cy, dx, dy);
}

// Without -mfma the library targets every x86-64, where std::fma is a slow software routine.
// Most CPUs (since 2013) have the instruction, so the stages are compiled a second time for it
// and chosen at run time. Both versions are exact; only their speed differs.
#if defined(__FMA__) || defined(__FP_FAST_FMA)
#define DTM_PREDICATES_HAVE_FMA_STAGES 1
#define DTM_PREDICATES_FMA_TARGET
bool fma_available() noexcept { return true; }
#elif (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#define DTM_PREDICATES_HAVE_FMA_STAGES 1
#define DTM_PREDICATES_FMA_TARGET [[gnu::target("fma")]]
bool fma_available() noexcept {
    __builtin_cpu_init();
    return __builtin_cpu_supports("fma") != 0;
}
#else
bool fma_available() noexcept { return false; }
#endif

#if defined(DTM_PREDICATES_HAVE_FMA_STAGES)
DTM_PREDICATES_FMA_TARGET int orient_stages_fma(
    double ax, double ay, double bx, double by, double cx, double cy, double detsum) noexcept {
    return orient_stages<true>(ax, ay, bx, by, cx, cy, detsum);
}

DTM_PREDICATES_FMA_TARGET int incircle_stages_fma(double ax,
                                                  double ay,
                                                  double bx,
                                                  double by,
                                                  double cx,
                                                  double cy,
                                                  double dx,
                                                  double dy,
                                                  double permanent) noexcept {
    return incircle_stages<true>(ax, ay, bx, by, cx, cy, dx, dy, permanent);
}
#endif

/// False (the portable stages) until initialised, so early static-initialisation callers
/// stay exact. Relaxed atomic: a plain load on x86, and tests may switch it.
std::atomic<bool> use_fma_stages{fma_available()};

}  // namespace

bool use_fma_in_adaptive_stages(bool fma) noexcept {
    if (fma && !fma_available()) {
        return false;
    }
    use_fma_stages.store(fma, std::memory_order_relaxed);
    return true;
}

int orient2d_adaptive(
    double ax, double ay, double bx, double by, double cx, double cy, double detsum) noexcept {
    const double v[6] = {ax, ay, bx, by, cx, cy};
    if (!in_expansion_range(v, 6, orient_min_abs, orient_max_abs)) {
        return orient2d_bigint(ax, ay, bx, by, cx, cy);
    }
#if defined(DTM_PREDICATES_HAVE_FMA_STAGES)
    if (use_fma_stages.load(std::memory_order_relaxed)) {
        return orient_stages_fma(ax, ay, bx, by, cx, cy, detsum);
    }
#endif
    return orient_stages<false>(ax, ay, bx, by, cx, cy, detsum);
}

int incircle_adaptive(double ax,
                      double ay,
                      double bx,
                      double by,
                      double cx,
                      double cy,
                      double dx,
                      double dy,
                      double permanent) noexcept {
    const double v[8] = {ax, ay, bx, by, cx, cy, dx, dy};
    if (!in_expansion_range(v, 8, incircle_min_abs, incircle_max_abs)) {
        return incircle_bigint(ax, ay, bx, by, cx, cy, dx, dy);
    }
#if defined(DTM_PREDICATES_HAVE_FMA_STAGES)
    if (use_fma_stages.load(std::memory_order_relaxed)) {
        return incircle_stages_fma(ax, ay, bx, by, cx, cy, dx, dy, permanent);
    }
#endif
    return incircle_stages<false>(ax, ay, bx, by, cx, cy, dx, dy, permanent);
}

}  // namespace dtm::geom::detail
