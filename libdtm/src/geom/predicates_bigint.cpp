// SPDX-License-Identifier: MIT
// Last-resort exact predicates in fixed-capacity big integers.
//
// The adaptive predicates (predicates.cpp) rely on expansion arithmetic, which is exact only
// while no partial product overflows or underflows. When an input coordinate is huge or tiny
// they come here: all coordinates are written as integers times one common power of two
// (scaling by a power of two does not change the sign of a homogeneous determinant), and the
// determinant is evaluated with schoolbook integer arithmetic. Slow but simple and exact for
// every finite double; terrain coordinates never reach it.
#include <cassert>
#include <cmath>
#include <cstdint>

#include "geom/detail/bigint.hpp"

namespace dtm::geom::detail {

namespace {

void trim(BigInt& a) noexcept {
    while (a.size > 0 && a.limb[static_cast<std::size_t>(a.size - 1)] == 0) {
        --a.size;
    }
    if (a.size == 0) {
        a.sign = 0;
    }
}

int compare_magnitude(const BigInt& a, const BigInt& b) noexcept {
    if (a.size != b.size) {
        return a.size < b.size ? -1 : 1;
    }
    for (int i = a.size - 1; i >= 0; --i) {
        const auto k = static_cast<std::size_t>(i);
        if (a.limb[k] != b.limb[k]) {
            return a.limb[k] < b.limb[k] ? -1 : 1;
        }
    }
    return 0;
}

/// r = |a| + |b| with the given sign.
void add_magnitude(const BigInt& a, const BigInt& b, int sign, BigInt& r) noexcept {
    const int n = a.size > b.size ? a.size : b.size;
    assert(n < BigInt::capacity);
    std::uint64_t carry = 0;
    for (int i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const std::uint64_t x = i < a.size ? a.limb[k] : 0U;
        const std::uint64_t y = i < b.size ? b.limb[k] : 0U;
        const std::uint64_t t = x + y + carry;
        r.limb[k] = static_cast<std::uint32_t>(t);
        carry = t >> 32U;
    }
    r.limb[static_cast<std::size_t>(n)] = static_cast<std::uint32_t>(carry);
    r.size = n + 1;
    r.sign = sign;
    trim(r);
}

/// r = |a| - |b| (requires |a| >= |b|) with the given sign.
void sub_magnitude(const BigInt& a, const BigInt& b, int sign, BigInt& r) noexcept {
    std::int64_t borrow = 0;
    for (int i = 0; i < a.size; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const std::int64_t y = i < b.size ? static_cast<std::int64_t>(b.limb[k]) : 0;
        std::int64_t t = static_cast<std::int64_t>(a.limb[k]) - y - borrow;
        borrow = t < 0 ? 1 : 0;
        t += borrow * (std::int64_t{1} << 32);
        r.limb[k] = static_cast<std::uint32_t>(t);
    }
    r.size = a.size;
    r.sign = sign;
    trim(r);
}

/// r = a + s*b, s = +1 or -1. r may alias a or b (limbs are read before they are written).
void add_signed(const BigInt& a, const BigInt& b, int s, BigInt& r) noexcept {
    const int bsign = b.sign * s;
    if (b.sign == 0) {
        r = a;
    } else if (a.sign == 0) {
        r = b;
        r.sign = bsign;
    } else if (a.sign == bsign) {
        add_magnitude(a, b, a.sign, r);
    } else if (compare_magnitude(a, b) >= 0) {
        sub_magnitude(a, b, a.sign, r);
    } else {
        sub_magnitude(b, a, bsign, r);
    }
}

bool all_finite(const double* v, int n) noexcept {
    for (int i = 0; i < n; ++i) {
        if (!std::isfinite(v[i])) {
            return false;
        }
    }
    return true;
}

}  // namespace

int common_exponent(const double* values, int n) noexcept {
    int lowest = 0;
    bool any = false;
    for (int i = 0; i < n; ++i) {
        if (values[i] != 0.0) {
            int e = 0;
            (void)std::frexp(values[i], &e);
            if (!any || e - 53 < lowest) {
                lowest = e - 53;
            }
            any = true;
        }
    }
    return lowest;
}

BigInt bigint_from_double(double v, int base_exponent) noexcept {
    BigInt r;
    if (v == 0.0 || !std::isfinite(v)) {
        return r;
    }
    int e = 0;
    const double f = std::frexp(std::abs(v), &e);
    const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
    const int shift = e - 53 - base_exponent;
    assert(shift >= 0);
    const auto word = static_cast<std::size_t>(shift / 32);
    const int bit = shift % 32;
    const std::uint64_t low = m << bit;
    const std::uint64_t high = bit == 0 ? 0U : m >> (64 - bit);
    r.limb[word] = static_cast<std::uint32_t>(low);
    r.limb[word + 1] = static_cast<std::uint32_t>(low >> 32U);
    r.limb[word + 2] = static_cast<std::uint32_t>(high);
    r.size = static_cast<int>(word) + 3;
    r.sign = v > 0.0 ? 1 : -1;
    trim(r);
    return r;
}

void bigint_add(const BigInt& a, const BigInt& b, BigInt& r) noexcept { add_signed(a, b, 1, r); }

void bigint_sub(const BigInt& a, const BigInt& b, BigInt& r) noexcept { add_signed(a, b, -1, r); }

void bigint_mul(const BigInt& a, const BigInt& b, BigInt& r) noexcept {
    assert(&r != &a && &r != &b);
    if (a.sign == 0 || b.sign == 0) {
        r.size = 0;
        r.sign = 0;
        return;
    }
    const int n = a.size + b.size;
    assert(n <= BigInt::capacity);
    for (int i = 0; i < n; ++i) {
        r.limb[static_cast<std::size_t>(i)] = 0;
    }
    for (int i = 0; i < a.size; ++i) {
        std::uint64_t carry = 0;
        const std::uint64_t x = a.limb[static_cast<std::size_t>(i)];
        for (int j = 0; j < b.size; ++j) {
            const auto k = static_cast<std::size_t>(i + j);
            const std::uint64_t t = r.limb[k] + x * b.limb[static_cast<std::size_t>(j)] + carry;
            r.limb[k] = static_cast<std::uint32_t>(t);
            carry = t >> 32U;
        }
        r.limb[static_cast<std::size_t>(i + b.size)] = static_cast<std::uint32_t>(carry);
    }
    r.size = n;
    r.sign = a.sign * b.sign;
    trim(r);
}

int orient2d_bigint(double ax, double ay, double bx, double by, double cx, double cy) noexcept {
    const double v[6] = {ax, ay, bx, by, cx, cy};
    if (!all_finite(v, 6)) {
        return 0;  // outside the contract (finite input); never read garbage
    }
    const int base = common_exponent(v, 6);
    BigInt acx;
    BigInt acy;
    BigInt bcx;
    BigInt bcy;
    const BigInt icx = bigint_from_double(cx, base);
    const BigInt icy = bigint_from_double(cy, base);
    bigint_sub(bigint_from_double(ax, base), icx, acx);
    bigint_sub(bigint_from_double(ay, base), icy, acy);
    bigint_sub(bigint_from_double(bx, base), icx, bcx);
    bigint_sub(bigint_from_double(by, base), icy, bcy);
    BigInt left;
    BigInt right;
    bigint_mul(acx, bcy, left);
    bigint_mul(acy, bcx, right);
    bigint_sub(left, right, left);
    return left.sign;
}

namespace {

/// lift(p) * (q.x r.y - q.y r.x) for differences p, q, r taken from d.
void lifted_term(const BigInt& px,
                 const BigInt& py,
                 const BigInt& qx,
                 const BigInt& qy,
                 const BigInt& rx,
                 const BigInt& ry,
                 BigInt& out) noexcept {
    BigInt t1;
    BigInt t2;
    BigInt lift;
    bigint_mul(px, px, t1);
    bigint_mul(py, py, t2);
    bigint_add(t1, t2, lift);
    bigint_mul(qx, ry, t1);
    bigint_mul(qy, rx, t2);
    bigint_sub(t1, t2, t1);
    bigint_mul(lift, t1, out);
}

}  // namespace

int incircle_bigint(double ax,
                    double ay,
                    double bx,
                    double by,
                    double cx,
                    double cy,
                    double dx,
                    double dy) noexcept {
    const double v[8] = {ax, ay, bx, by, cx, cy, dx, dy};
    if (!all_finite(v, 8)) {
        return 0;  // outside the contract (finite input); never read garbage
    }
    const int base = common_exponent(v, 8);
    const BigInt idx = bigint_from_double(dx, base);
    const BigInt idy = bigint_from_double(dy, base);
    BigInt adx;
    BigInt ady;
    BigInt bdx;
    BigInt bdy;
    BigInt cdx;
    BigInt cdy;
    bigint_sub(bigint_from_double(ax, base), idx, adx);
    bigint_sub(bigint_from_double(ay, base), idy, ady);
    bigint_sub(bigint_from_double(bx, base), idx, bdx);
    bigint_sub(bigint_from_double(by, base), idy, bdy);
    bigint_sub(bigint_from_double(cx, base), idx, cdx);
    bigint_sub(bigint_from_double(cy, base), idy, cdy);
    BigInt sum;
    BigInt term;
    lifted_term(adx, ady, bdx, bdy, cdx, cdy, sum);
    lifted_term(bdx, bdy, cdx, cdy, adx, ady, term);
    bigint_add(sum, term, sum);
    lifted_term(cdx, cdy, adx, ady, bdx, bdy, term);
    bigint_add(sum, term, sum);
    return sum.sign;
}

}  // namespace dtm::geom::detail
