// SPDX-License-Identifier: MIT
/// @file
/// @brief The exact sign of a sum of doubles (Shewchuk's grow-expansion with zero elimination):
/// the data-dependent criteria compare sums of edge costs exactly, so a flip is taken only when
/// it lowers the true sum of the computed costs and the flip loop cannot cycle.
#pragma once

#include <cmath>
#include <span>
#include <vector>

namespace dtm::detail {

/// An unevaluated exact sum of doubles; components non-overlapping, increasing magnitude.
class ExactSum {
public:
    void add(double v) {
        // Knuth's two-sum of the running value with each component (no multiplication, so
        // contraction into an FMA cannot change it).
        double q = v;
        std::size_t out = 0;
        for (const double h : parts_) {
            const double x = q + h;
            const double b_virtual = x - q;
            const double a_virtual = x - b_virtual;
            const double err = (h - b_virtual) + (q - a_virtual);
            q = x;
            if (err != 0.0) parts_[out++] = err;
        }
        parts_.resize(out);
        if (q != 0.0) parts_.push_back(q);
    }
    void subtract(double v) { add(-v); }
    /// -1, 0 or +1: the sign of the exact sum.
    [[nodiscard]] int sign() const noexcept {
        for (auto it = parts_.rbegin(); it != parts_.rend(); ++it) {
            if (*it > 0.0) return 1;
            if (*it < 0.0) return -1;
        }
        return 0;
    }

private:
    std::vector<double> parts_;
};

/// Sign of sum(@p plus) - sum(@p minus), exact for finite values.
[[nodiscard]] inline int exact_sum_difference_sign(std::span<const double> plus,
                                                   std::span<const double> minus) {
    ExactSum s;
    for (const double v : plus) s.add(v);
    for (const double v : minus) s.subtract(v);
    return s.sign();
}

}  // namespace dtm::detail
