// SPDX-License-Identifier: MIT
/// @file
/// @brief Fixed-capacity signed big integers, for the predicates' last-resort exact path.
///
/// Expansion arithmetic is exact only while no product overflows or underflows. For inputs
/// with extreme magnitudes (beyond about 2^250 or below 2^-200) the predicates instead
/// write every coordinate as an integer multiple of a common power of two and evaluate the
/// determinant in integers. Any double is m * 2^e with |m| < 2^53 and -1126 <= e <= 971, so
/// such an integer needs at most 2150 bits and a degree-4 determinant at most ~8610 bits.
#pragma once

#include <array>
#include <cstdint>

namespace dtm::geom::detail {

/// Signed magnitude integer with 32-bit limbs, least significant first. No allocation.
struct BigInt {
    static constexpr int capacity = 272;  // 8704 bits: room for incircle's degree-4 terms
    std::array<std::uint32_t, capacity> limb{};
    int size = 0;  ///< limbs in use; 0 means the value is zero
    int sign = 0;  ///< -1, 0, +1
};

/// The integer v / 2^base_exponent; v must be a finite multiple of 2^base_exponent.
[[nodiscard]] BigInt bigint_from_double(double v, int base_exponent) noexcept;
/// Exponent e such that every finite v in values is an integer multiple of 2^e.
[[nodiscard]] int common_exponent(const double* values, int n) noexcept;

void bigint_add(const BigInt& a, const BigInt& b, BigInt& r) noexcept;
void bigint_sub(const BigInt& a, const BigInt& b, BigInt& r) noexcept;
void bigint_mul(const BigInt& a, const BigInt& b, BigInt& r) noexcept;

/// Exact orient2d / incircle signs by big-integer evaluation. Slow, valid for all finite input.
[[nodiscard]] int orient2d_bigint(
    double ax, double ay, double bx, double by, double cx, double cy) noexcept;
[[nodiscard]] int incircle_bigint(double ax,
                                  double ay,
                                  double bx,
                                  double by,
                                  double cx,
                                  double cy,
                                  double dx,
                                  double dy) noexcept;

}  // namespace dtm::geom::detail
