// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: Neumaier's compensated summation (Neumaier 1974, "Rundungsfehleranalyse
/// einiger Verfahren zur Summation endlicher Summen"): the error of a long sum stays at a few
/// units in the last place of the result, whatever the number and order of the terms.
#pragma once

#include <cmath>

namespace dtm::detail {

class CompensatedSum {
public:
    void add(double value) noexcept {
        const double t = sum_ + value;
        if (std::fabs(sum_) >= std::fabs(value)) {
            compensation_ += (sum_ - t) + value;
        } else {
            compensation_ += (value - t) + sum_;
        }
        sum_ = t;
    }
    /// Adds another compensated sum (both parts, so nothing of its compensation is lost).
    void add(const CompensatedSum& other) noexcept {
        add(other.sum_);
        add(other.compensation_);
    }
    [[nodiscard]] double value() const noexcept { return sum_ + compensation_; }

private:
    double sum_ = 0.0;
    double compensation_ = 0.0;
};

}  // namespace dtm::detail
