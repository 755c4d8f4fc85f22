// SPDX-License-Identifier: MIT
// Counting repeated xy positions (the input summary's duplicate count).
#include "dtm/algo/duplicates.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>

#include "support/terrain_fixtures.hpp"

namespace dtm {
namespace {

TEST(CountRepeatedPositions, CountsEveryPointAfterTheFirstAtAPositionWhateverItsHeight) {
    const std::vector<Point3> points{{0, 0, 1}, {1, 0, 2}, {0, 0, 3},     {-0.0, 0, 4},
                                     {1, 0, 2}, {0, 1, 5}, {1, 1e-300, 6}};
    // (0,0) three times (-0.0 equals 0.0), (1,0) twice; (1, 1e-300) is another position.
    EXPECT_EQ(count_repeated_positions(points), 3u);
    EXPECT_EQ(count_repeated_positions({}), 0u);
}

TEST(CountRepeatedPositions, AgreesWithAnOrderedMapOnManyRandomRepeats) {
    std::vector<Point3> points = test::random_points(50000, 9, test::sjtsk_e, test::sjtsk_n);
    std::mt19937 rng(3);
    for (int i = 0; i < 20000; ++i) points.push_back(points[rng() % points.size()]);
    std::map<std::pair<double, double>, int> seen;
    std::size_t expected = 0;
    for (const Point3& p : points) expected += seen[{p.x, p.y}]++ > 0 ? 1 : 0;
    EXPECT_EQ(count_repeated_positions(points), expected);
}

}  // namespace
}  // namespace dtm
