// SPDX-License-Identifier: MIT
// Branch-free median selection of the divide and conquer (algo/detail/median_split.hpp): the same
// split as std::nth_element for every size and rank, whatever the input order.
#include "algo/detail/median_split.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace dtm::detail {
namespace {

struct Item {
    double x;
    double y;
    unsigned id;
};

/// Lexicographic (x, y): a strict total order on distinct positions, with many equal x.
struct ByXY {
    bool operator()(const Item& a, const Item& b) const noexcept {
        return (a.x < b.x) | ((a.x == b.x) & (a.y < b.y));
    }
};

std::vector<Item> items(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::vector<Item> v(n);
    for (std::size_t i = 0; i < n; ++i) {
        // x on a coarse lattice (ties broken by y), y distinct.
        v[i] = {static_cast<double>(rng() % 97), static_cast<double>(i) * 0.5 - 7.0,
                static_cast<unsigned>(i)};
    }
    std::shuffle(v.begin(), v.end(), rng);
    return v;
}

TEST(SelectKth, PutsExactlyTheKSmallestFirstForEverySizeAndRank) {
    SelectScratch<Item> scratch;
    // Sizes below the std::nth_element fallback, between it and the scratch capacity, and above
    // it (the in-place pass); ranks at the ends and in the middle.
    for (const std::size_t n : {1u, 2u, 5u, 1000u, 1025u, 5000u, 16384u, 16385u, 70000u}) {
        for (const std::size_t k : {std::size_t{0}, std::size_t{1}, n / 3, n / 2, n - 1, n}) {
            std::vector<Item> v = items(n, static_cast<unsigned>(n + k));
            std::vector<Item> expected = v;
            std::sort(expected.begin(), expected.end(), ByXY{});
            select_kth(v.data(), n, k, ByXY{}, scratch);
            std::vector<unsigned> left, want;
            for (std::size_t i = 0; i < k; ++i) left.push_back(v[i].id);
            for (std::size_t i = 0; i < k; ++i) want.push_back(expected[i].id);
            std::sort(left.begin(), left.end());
            std::sort(want.begin(), want.end());
            ASSERT_EQ(left, want) << "n " << n << " k " << k;
            // Nothing was lost or duplicated on the other side either.
            std::vector<unsigned> all;
            for (const Item& item : v) all.push_back(item.id);
            std::sort(all.begin(), all.end());
            for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(all[i], i) << "n " << n << " k " << k;
        }
    }
}

}  // namespace
}  // namespace dtm::detail
