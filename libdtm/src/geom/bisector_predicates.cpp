// SPDX-License-Identifier: MIT
// Exact bisector predicates (dtm/geom/bisector_predicates.hpp).
//
// Each predicate first evaluates its polynomial in doubles while carrying a running bound on
// the absolute error (forward error analysis: every operation adds its rounding, at most
// epsilon = 2^-53 of its result, to the propagated bounds of its operands). When the value
// exceeds the bound its sign is certain. Otherwise, and whenever a coordinate lies outside
// [2^-200, 2^200] (where products could underflow and the relative bounds fail), the
// polynomial is evaluated exactly in big integers after scaling every coordinate to an integer
// by one common power of two (which does not change the sign of a homogeneous polynomial).
// This file is compiled with -ffp-contract=off (libdtm/CMakeLists.txt): the bounds assume
// every product is rounded on its own.
#include "dtm/geom/bisector_predicates.hpp"

#include <cmath>

#include "dtm/geom/predicates.hpp"
#include "geom/detail/bigint.hpp"

namespace dtm::geom {
namespace {

using detail::BigInt;

constexpr double eps = 0x1p-53;
constexpr double min_abs = 0x1p-200;
constexpr double max_abs = 0x1p+200;

/// A double with a bound on its distance from the exact value it stands for.
struct Approx {
    double v = 0.0;
    double e = 0.0;
};

Approx sub(Approx a, Approx b) noexcept {
    const double v = a.v - b.v;
    return {v, a.e + b.e + eps * std::abs(v)};
}

Approx add(Approx a, Approx b) noexcept {
    const double v = a.v + b.v;
    return {v, a.e + b.e + eps * std::abs(v)};
}

Approx mul(Approx a, Approx b) noexcept {
    const double v = a.v * b.v;
    return {v, std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e + eps * std::abs(v)};
}

/// The sign of @p a if the bound proves it, else 2. The bound itself was computed in rounded
/// arithmetic; the factor covers those roundings with a wide margin.
int certain_sign(Approx a) noexcept {
    const double bound = a.e * (1.0 + 0x1p-20);
    if (a.v > bound) return 1;
    if (a.v < -bound) return -1;
    return 2;
}

bool in_range(const double* v, int n) noexcept {
    for (int i = 0; i < n; ++i) {
        const double a = std::abs(v[i]);
        if (!(a <= max_abs) || (a != 0.0 && a < min_abs)) return false;
    }
    return true;
}

/// |x - g|^2 - |x - h|^2 with its error bound.
Approx power_difference(const Point2& x, const Point2& g, const Point2& h) noexcept {
    const Approx gx = sub({x.x, 0}, {g.x, 0});
    const Approx gy = sub({x.y, 0}, {g.y, 0});
    const Approx hx = sub({x.x, 0}, {h.x, 0});
    const Approx hy = sub({x.y, 0}, {h.y, 0});
    return sub(add(mul(gx, gx), mul(gy, gy)), add(mul(hx, hx), mul(hy, hy)));
}

/// Big-integer evaluation of the same quantities over coordinates scaled by 2^-base.
struct Exact {
    int base;
    [[nodiscard]] BigInt of(double v) const noexcept { return detail::bigint_from_double(v, base); }
    [[nodiscard]] BigInt diff(double a, double b) const noexcept {
        BigInt r;
        detail::bigint_sub(of(a), of(b), r);
        return r;
    }
    [[nodiscard]] static BigInt square_sum(const BigInt& x, const BigInt& y) noexcept {
        BigInt xx;
        BigInt yy;
        BigInt r;
        detail::bigint_mul(x, x, xx);
        detail::bigint_mul(y, y, yy);
        detail::bigint_add(xx, yy, r);
        return r;
    }
    [[nodiscard]] BigInt power_difference(const Point2& x,
                                          const Point2& g,
                                          const Point2& h) const noexcept {
        const BigInt dg = square_sum(diff(x.x, g.x), diff(x.y, g.y));
        const BigInt dh = square_sum(diff(x.x, h.x), diff(x.y, h.y));
        BigInt r;
        detail::bigint_sub(dg, dh, r);
        return r;
    }
};

}  // namespace

int dot_sign(double ax,
             double ay,
             double bx,
             double by,
             double cx,
             double cy,
             double dx,
             double dy) noexcept {
    const double v[8] = {ax, ay, bx, by, cx, cy, dx, dy};
    if (in_range(v, 8)) {
        const Approx ux = sub({bx, 0}, {ax, 0});
        const Approx uy = sub({by, 0}, {ay, 0});
        const Approx wx = sub({dx, 0}, {cx, 0});
        const Approx wy = sub({dy, 0}, {cy, 0});
        const int s = certain_sign(add(mul(ux, wx), mul(uy, wy)));
        if (s != 2) return s;
    }
    const Exact exact{detail::common_exponent(v, 8)};
    BigInt xx;
    BigInt yy;
    BigInt r;
    detail::bigint_mul(exact.diff(bx, ax), exact.diff(dx, cx), xx);
    detail::bigint_mul(exact.diff(by, ay), exact.diff(dy, cy), yy);
    detail::bigint_add(xx, yy, r);
    return r.sign;
}

int crossing_order(
    const Point2& a, const Point2& b, const Point2& g, const Point2& h, const Point2& k) noexcept {
    // X = a + t (b - a) with F_h(X) = 0, F_h(x) = |x-g|^2 - |x-h|^2 affine along the segment:
    // F_k(X) = (F_h(a) F_k(b) - F_k(a) F_h(b)) / (F_h(a) - F_h(b)), and the denominator has the
    // sign of F_h(a) (a and b are strictly on opposite sides).
    const int side_a = compare_distances(a, g, a, h);
    const double v[10] = {a.x, a.y, b.x, b.y, g.x, g.y, h.x, h.y, k.x, k.y};
    if (in_range(v, 10)) {
        const Approx hb = power_difference(b, g, h);
        const Approx ha = power_difference(a, g, h);
        const Approx ka = power_difference(a, g, k);
        const Approx kb = power_difference(b, g, k);
        const int s = certain_sign(sub(mul(ha, kb), mul(ka, hb)));
        if (s != 2) return s * side_a;
    }
    const Exact exact{detail::common_exponent(v, 10)};
    BigInt left;
    BigInt right;
    BigInt r;
    detail::bigint_mul(exact.power_difference(a, g, h), exact.power_difference(b, g, k), left);
    detail::bigint_mul(exact.power_difference(a, g, k), exact.power_difference(b, g, h), right);
    detail::bigint_sub(left, right, r);
    return r.sign * side_a;
}

}  // namespace dtm::geom
