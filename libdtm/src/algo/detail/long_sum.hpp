// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: an exact sum of doubles (a long accumulator), independent of the order and
/// grouping of the terms (a fixed-point "long accumulator" after Kulisch: every double is an
/// integer multiple of 2^-1074, so 67 limbs of 32 bits hold any finite sum exactly). Partial sums
/// of ranks add limb by limb (integers), so a distributed run gets the serial run's value bit for
/// bit. value() rounds the exact sum to a double by a fixed rule (the same limbs give the same
/// double).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>

namespace dtm::detail {

__extension__ using LongSumWide = unsigned __int128;  // GCC and Clang

class LongSum {
public:
    static constexpr int limb_bits = 32;
    static constexpr int bias = 1088;  ///< bit 0 of limb 0 weighs 2^-bias (bias >= 1074)
    static constexpr std::size_t limb_count = 68;

    /// Adds @p term exactly; a non-finite term makes value() NaN.
    void add(double term) noexcept {
        if (!std::isfinite(term)) {
            finite_ = false;
            return;
        }
        if (term == 0.0) return;
        int exponent = 0;
        const double fraction = std::frexp(std::fabs(term), &exponent);  // in [0.5, 1)
        // term = mantissa * 2^(exponent - 53), mantissa < 2^53 an integer (subnormals too).
        auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
        int shift = exponent - 53 + bias;
        if (shift < 0) {  // only subnormals: their low bits are zero
            mantissa >>= -shift;
            shift = 0;
        }
        const auto wide = static_cast<LongSumWide>(mantissa) << (shift % limb_bits);
        const std::size_t at = static_cast<std::size_t>(shift / limb_bits);
        const std::int64_t sign = term < 0.0 ? -1 : 1;
        for (std::size_t i = 0; i < 3 && at + i < limb_count; ++i) {
            limbs_[at + i] +=
                sign * static_cast<std::int64_t>((wide >> (limb_bits * i)) & 0xffffffffU);
        }
        if (++pending_ == (std::uint64_t{1} << 30)) normalize();
    }

    /// Carries every limb into [0, 2^32) but the last, which keeps the sign.
    void normalize() noexcept {
        for (std::size_t i = 0; i + 1 < limb_count; ++i) {
            const std::int64_t carry = limbs_[i] >> limb_bits;  // floor division by 2^32
            limbs_[i] -= carry * (std::int64_t{1} << limb_bits);
            limbs_[i + 1] += carry;
        }
        pending_ = 0;
    }

    /// The limbs after normalize(), to add across ranks (integer sums) and take back with
    /// from_limbs(); the last entry is 0 or 1, whether a term was not finite.
    [[nodiscard]] std::array<std::int64_t, limb_count + 1> limbs() noexcept {
        normalize();
        std::array<std::int64_t, limb_count + 1> out{};
        for (std::size_t i = 0; i < limb_count; ++i) out[i] = limbs_[i];
        out[limb_count] = finite_ ? 0 : 1;
        return out;
    }
    void from_limbs(std::span<const std::int64_t, limb_count + 1> limbs) noexcept {
        for (std::size_t i = 0; i < limb_count; ++i) limbs_[i] = limbs[i];
        finite_ = limbs[limb_count] == 0;
        normalize();
    }

    /// The sum rounded to a double (within one unit in the last place; NaN after a non-finite
    /// term). A function of the exact sum only.
    [[nodiscard]] double value() const noexcept {
        if (!finite_) return std::nan("");
        LongSum copy = *this;
        copy.normalize();
        // From the most significant limb down: the first terms are exact, the rest round.
        double sum = 0.0;
        for (std::size_t i = limb_count; i-- > 0;) {
            if (copy.limbs_[i] == 0) continue;
            sum += std::ldexp(static_cast<double>(copy.limbs_[i]),
                              static_cast<int>(i) * limb_bits - bias);
        }
        return sum;
    }

private:
    std::array<std::int64_t, limb_count> limbs_{};
    std::uint64_t pending_ = 0;
    bool finite_ = true;
};

}  // namespace dtm::detail
