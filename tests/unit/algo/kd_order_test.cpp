// SPDX-License-Identifier: MIT
// The divide and conquer's point order in rank space (algo/detail/kd_order.hpp): exactly the
// order of recursive median selection (std::nth_element, strips sorted by x) for every size,
// first cut and point distribution, ties in x or y and coordinates of every magnitude included.
#include "algo/detail/kd_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace dtm::detail {
namespace {

/// The definition: recursive median selection.
void reference_order(KernelPoint* a, std::size_t n, int cut) {
    if (n <= strip_size) {
        std::sort(a, a + n, Before<0>{});
        return;
    }
    if (cut == 0) {
        std::nth_element(a, a + n / 2, a + n, Before<0>{});
    } else {
        std::nth_element(a, a + n / 2, a + n, Before<1>{});
    }
    reference_order(a, n / 2, 1 - cut);
    reference_order(a + n / 2, n - n / 2, 1 - cut);
}

std::vector<KernelPoint> distinct(std::vector<KernelPoint> v) {
    std::sort(v.begin(), v.end(), Before<0>{});
    v.erase(std::unique(v.begin(), v.end(),
                        [](const KernelPoint& p, const KernelPoint& q) {
                            return p.x == q.x && p.y == q.y;
                        }),
            v.end());
    for (std::size_t i = 0; i < v.size(); ++i) v[i].id = static_cast<std::uint32_t>(i);
    return v;
}

std::vector<KernelPoint> points(const std::string& kind, std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<KernelPoint> v;
    for (std::size_t i = 0; i < n; ++i) {
        double x = u(rng);
        double y = u(rng);
        if (kind == "lattice") {  // equal x and equal y everywhere
            x = std::floor(x * 200.0);
            y = std::floor(y * 200.0);
        } else if (kind == "sjtsk") {  // large offsets, millimetres
            x = -750000.0 + std::round(x * 2e6) / 1000.0;
            y = -1050000.0 + std::round(y * 2e6) / 1000.0;
        } else if (kind == "column") {  // all on one vertical line but a few
            x = i % 97 == 0 ? x : 5.0;
        } else if (kind == "signs") {  // around zero, with -0.0 and 0.0 and tiny magnitudes
            x = (x - 0.5) * std::pow(10.0, static_cast<double>(rng() % 40) - 20.0);
            y = i % 5 == 0 ? (i % 10 == 0 ? -0.0 : 0.0) : y - 0.5;
        } else if (kind == "outlier") {  // one far point: the keys of the rest all tie
            x = i == 0 ? 1e300 : x * 1e-9;
            y = i == 1 ? -1e300 : y;
        }
        v.push_back({{x, y}, 0});
    }
    std::vector<KernelPoint> d = distinct(std::move(v));
    std::shuffle(d.begin(), d.end(), rng);
    return d;
}

TEST(KdOrder, EqualsRecursiveMedianSelection) {
    SubtreeScratch scratch;
    for (const std::string kind : {"uniform", "lattice", "sjtsk", "column", "signs", "outlier"}) {
        for (const std::size_t n :
             {1u, 2u, 3u, 16u, 17u, 33u, 100u, 1000u, 4097u, 12345u, 16384u}) {
            for (const int cut : {0, 1}) {
                std::vector<KernelPoint> v = points(kind, n, static_cast<unsigned>(n * 2 + cut));
                std::vector<KernelPoint> want = v;
                reference_order(want.data(), want.size(), cut);
                order_subtree(v.data(), v.size(), cut, scratch);
                ASSERT_EQ(v.size(), want.size());
                for (std::size_t i = 0; i < v.size(); ++i) {
                    ASSERT_EQ(v[i].id, want[i].id)
                        << kind << " n " << n << " cut " << cut << " at " << i;
                }
            }
        }
    }
}

}  // namespace
}  // namespace dtm::detail
