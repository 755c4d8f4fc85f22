// SPDX-License-Identifier: MIT
// Exact duplicate positions (algo/detail/exact_duplicates.hpp): the first index of every position
// as an ordered map finds it, on sizes with one and with many partitions, on one thread and on
// several (the same result).
#include "algo/detail/exact_duplicates.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <map>
#include <random>

namespace dtm::detail {
namespace {

std::vector<VertexIndex> expected_first(const std::vector<Point3>& pts) {
    std::map<std::pair<double, double>, VertexIndex> seen;
    std::vector<VertexIndex> first(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const double x = pts[i].x == 0.0 ? 0.0 : pts[i].x;  // -0.0 is 0.0
        const double y = pts[i].y == 0.0 ? 0.0 : pts[i].y;
        first[i] = seen.try_emplace({x, y}, static_cast<VertexIndex>(i)).first->second;
    }
    return first;
}

TEST(FirstOccurrences, EqualsAnOrderedMapForEverySizeAndThreadCount) {
    for (const std::size_t n : {0u, 1u, 2u, 100u, 9000u, 300000u}) {
        std::mt19937_64 rng(n);
        std::vector<Point3> pts(n);
        for (std::size_t i = 0; i < n; ++i) {
            // Half-metre lattice at S-JTSK offsets (about one repeat per point), some -0.0.
            const double x = static_cast<double>(rng() % 800) * 0.5 - 750000.0;
            const double y = i % 7 == 0 ? (i % 14 == 0 ? -0.0 : 0.0)
                                        : static_cast<double>(rng() % 800) * 0.5 - 1050000.0;
            pts[i] = {x, y, static_cast<double>(i)};
        }
        const std::vector<VertexIndex> want = expected_first(pts);
        for (const int threads : {1, 2}) {
            tbb::task_arena arena(threads);
            const BigArray<VertexIndex> got = arena.execute([&] { return first_occurrences(pts); });
            ASSERT_EQ(std::vector<VertexIndex>(got.begin(), got.end()), want)
                << "n " << n << " threads " << threads;
        }
    }
}

}  // namespace
}  // namespace dtm::detail
