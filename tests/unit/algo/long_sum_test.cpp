// SPDX-License-Identifier: MIT
// detail::LongSum: exact (1e16 + 1 - 1e16 is 1, where a double sum gives 0 or 2), independent of
// the order of the terms, and partial sums added limb by limb (as across ranks) give the very
// same double as one sum; subnormals and the largest doubles are held too.
#include "algo/detail/long_sum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

namespace {

using dtm::detail::LongSum;

double sum_of(const std::vector<double>& terms) {
    LongSum s;
    for (const double t : terms) s.add(t);
    return s.value();
}

TEST(LongSum, IsExact) {
    EXPECT_EQ(sum_of({1e16, 1.0, -1e16}), 1.0);
    EXPECT_EQ(sum_of({std::numeric_limits<double>::denorm_min(), 1.0, -1.0}),
              std::numeric_limits<double>::denorm_min());
    const double big = std::numeric_limits<double>::max() / 4;
    EXPECT_EQ(sum_of({big, big, -big, 0.5, -big}), 0.5);
    EXPECT_TRUE(std::isnan(sum_of({1.0, std::numeric_limits<double>::infinity()})));
}

TEST(LongSum, OrderAndGroupingDoNotChangeTheValue) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> terms;
    for (int i = 0; i < 20000; ++i)
        terms.push_back(std::ldexp(u(rng), static_cast<int>(rng() % 60) - 30));
    const double whole = sum_of(terms);
    for (int round = 0; round < 3; ++round) {
        std::shuffle(terms.begin(), terms.end(), rng);
        EXPECT_EQ(sum_of(terms), whole);
        LongSum a, b;  // two "ranks", their limbs added as integers
        for (std::size_t i = 0; i < terms.size(); ++i) (i % 3 == 0 ? a : b).add(terms[i]);
        auto la = a.limbs();
        const auto lb = b.limbs();
        for (std::size_t i = 0; i < la.size(); ++i) la[i] += lb[i];
        LongSum total;
        total.from_limbs(la);
        EXPECT_EQ(total.value(), whole);
    }
}

}  // namespace
