// SPDX-License-Identifier: MIT
/// @file
/// @brief Floating-point expansion arithmetic (Shewchuk 1997, sections 2.2-2.8).
///
/// An expansion is an unevaluated sum of doubles, stored smallest magnitude first, whose
/// components do not overlap; its value is exact and its sign is the sign of its last
/// (largest) component. The building blocks are error-free transformations: two_sum and
/// two_product return the rounded result and the exact rounding error.
///
/// These functions are only correct when the compiler evaluates every operation as written,
/// in double precision and without contracting a*b+c into an FMA: the translation units
/// that include this header are compiled with -ffp-contract=off (libdtm/CMakeLists.txt),
/// and FMA is used only explicitly, when the target has it in hardware.
/// Callers also guarantee that no intermediate overflows or underflows (see predicates.cpp).
#pragma once

#include <cmath>
#include <cstdlib>

/// Inline even into functions compiled for another target (the FMA dispatch in
/// predicates.cpp), so the caller's instruction set is used.
#if defined(__GNUC__) || defined(__clang__)
#define DTM_PREDICATES_INLINE [[gnu::always_inline]] inline
#else
#define DTM_PREDICATES_INLINE inline
#endif

namespace dtm::geom::detail {

/// x + y == a + b exactly, x = fl(a + b). Requires |a| >= |b| (or a == 0).
DTM_PREDICATES_INLINE void fast_two_sum(double a, double b, double& x, double& y) noexcept {
    x = a + b;
    const double b_virtual = x - a;
    y = b - b_virtual;
}

/// x + y == a + b exactly, x = fl(a + b). Knuth's branch-free six-operation form.
DTM_PREDICATES_INLINE void two_sum(double a, double b, double& x, double& y) noexcept {
    x = a + b;
    const double b_virtual = x - a;
    const double a_virtual = x - b_virtual;
    const double b_round = b - b_virtual;
    const double a_round = a - a_virtual;
    y = a_round + b_round;
}

/// The rounding error of x = fl(a - b): a - b == x + result exactly.
DTM_PREDICATES_INLINE double two_diff_tail(double a, double b, double x) noexcept {
    const double b_virtual = a - x;
    const double a_virtual = x + b_virtual;
    const double b_round = b_virtual - b;
    const double a_round = a - a_virtual;
    return a_round + b_round;
}

/// x + y == a - b exactly, x = fl(a - b).
DTM_PREDICATES_INLINE void two_diff(double a, double b, double& x, double& y) noexcept {
    x = a - b;
    y = two_diff_tail(a, b, x);
}

/// True when the compilation target itself has FMA (then every build uses it).
#if defined(__FMA__) || defined(__FP_FAST_FMA)
inline constexpr bool compile_time_fma = true;
#else
inline constexpr bool compile_time_fma = false;
#endif

/// Dekker's split: a == hi + lo, each with at most 26 significant bits.
DTM_PREDICATES_INLINE void split(double a, double& hi, double& lo) noexcept {
    constexpr double splitter = 134217729.0;  // 2^27 + 1
    const double c = splitter * a;
    const double a_big = c - a;
    hi = c - a_big;
    lo = a - hi;
}

/// x + y == a * b exactly, x = fl(a * b); b is given pre-split (Dekker, Veltkamp) for the
/// non-FMA form. Fma = true uses one fused multiply-add: only instantiate it where the
/// hardware instruction is available (otherwise std::fma is a slow library call).
template <bool Fma>
DTM_PREDICATES_INLINE void two_product_presplit(
    double a, double b, double bhi, double blo, double& x, double& y) noexcept {
    x = a * b;
    if constexpr (Fma) {
        y = std::fma(a, b, -x);
    } else {
        double ahi = 0.0;
        double alo = 0.0;
        split(a, ahi, alo);
        const double err1 = x - ahi * bhi;
        const double err2 = err1 - alo * bhi;
        const double err3 = err2 - ahi * blo;
        y = alo * blo - err3;
    }
}

/// x + y == a * b exactly, x = fl(a * b).
template <bool Fma>
DTM_PREDICATES_INLINE void two_product(double a, double b, double& x, double& y) noexcept {
    double bhi = 0.0;
    double blo = 0.0;
    if constexpr (!Fma) {
        split(b, bhi, blo);
    }
    two_product_presplit<Fma>(a, b, bhi, blo, x, y);
}

/// (a1 + a0) - (b1 + b0) as the four-component expansion x[0..3] (zeros kept).
DTM_PREDICATES_INLINE void two_two_diff(
    double a1, double a0, double b1, double b0, double* x) noexcept {
    double i = 0.0;
    double j = 0.0;
    double k = 0.0;
    double u = 0.0;
    double v = 0.0;
    // Two_One_Diff(a1, a0, b0) then Two_One_Diff(result, b1).
    two_diff(a0, b0, i, x[0]);
    two_sum(a1, i, j, k);
    two_diff(k, b1, i, x[1]);
    two_sum(j, i, u, v);
    x[2] = v;
    x[3] = u;
}

/// h = e * b. Returns the length of h (at most 2 * elen; zeros removed, at least 1).
template <bool Fma>
DTM_PREDICATES_INLINE int scale_expansion(int elen, const double* e, double b, double* h) noexcept {
    double bhi = 0.0;
    double blo = 0.0;
    if constexpr (!Fma) {
        split(b, bhi, blo);
    }
    double q = 0.0;
    double hh = 0.0;
    int n = 0;
    two_product_presplit<Fma>(e[0], b, bhi, blo, q, hh);
    if (hh != 0.0) {
        h[n++] = hh;
    }
    for (int i = 1; i < elen; ++i) {
        double p1 = 0.0;
        double p0 = 0.0;
        double sum = 0.0;
        two_product_presplit<Fma>(e[i], b, bhi, blo, p1, p0);
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

/// h = e + f for strongly non-overlapping e, f (fast expansion sum with zero elimination,
/// Theorem 13). Returns the length (<= elen + flen, >= 1).
inline int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) noexcept {
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

/// h = e * f for expansions e (elen <= 16), f; Cap >= 2 * elen * flen. Returns the length of
/// h. A plain product by scale-expansion and summing, for the rare exact stages.
template <int Cap>
int expansion_product(int elen, const double* e, int flen, const double* f, double* h) noexcept {
    double part[2 * 16];
    double acc[Cap];
    int hlen = scale_expansion<compile_time_fma>(elen, e, f[0], h);
    for (int j = 1; j < flen; ++j) {
        const int plen = scale_expansion<compile_time_fma>(elen, e, f[j], part);
        for (int i = 0; i < hlen; ++i) {
            acc[i] = h[i];
        }
        hlen = expansion_sum(hlen, acc, plen, part, h);
    }
    return hlen;
}

/// An exact coordinate difference a - b as a two-component expansion: tail, rounded value.
struct ExactDiff {
    double v[2];
};

inline ExactDiff exact_diff(double a, double b) noexcept {
    ExactDiff d{};
    two_diff(a, b, d.v[1], d.v[0]);
    return d;
}

/// Approximate value of an expansion (sum of its components, largest last).
inline double estimate(int n, const double* e) noexcept {
    double q = e[0];
    for (int i = 1; i < n; ++i) {
        q += e[i];
    }
    return q;
}

/// Exact sign of an expansion with no overlapping components: the sign of its largest
/// non-zero component.
inline int expansion_sign(int n, const double* e) noexcept {
    for (int i = n - 1; i >= 0; --i) {
        if (e[i] > 0.0) {
            return 1;
        }
        if (e[i] < 0.0) {
            return -1;
        }
    }
    return 0;
}

/// Selects the two-product of the adaptive stages B-D: fused multiply-add (chosen by default
/// when the CPU has it) or Dekker splitting (portable). For tests, so that both variants run on
/// any machine. Returns false, changing nothing, if FMA is asked for but unavailable.
bool use_fma_in_adaptive_stages(bool fma) noexcept;

/// Exact incircle sign by full expansion arithmetic, tails included (stage D; in
/// predicates_exact.cpp). Valid while the coordinates are in the expansion-safe range.
[[nodiscard]] int incircle_exact(double ax,
                                 double ay,
                                 double bx,
                                 double by,
                                 double cx,
                                 double cy,
                                 double dx,
                                 double dy) noexcept;

}  // namespace dtm::geom::detail
