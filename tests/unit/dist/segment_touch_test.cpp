// SPDX-License-Identifier: MIT
// The segment grid finds exactly the segments a brute-force test finds (crowded chains, a long
// diagonal, S-JTSK magnitudes); the exact test itself on touching, collinear and disjoint cases.
#include "dist/segment_touch.hpp"

#include <gtest/gtest.h>

#include <random>

namespace dtm::dist {
namespace {

TEST(SegmentTouch, ClosedSetsExactly) {
    const std::array<XY, 3> t{XY{0, 0}, XY{4, 0}, XY{0, 4}};
    EXPECT_TRUE(segment_touches({{1, 1}, {9, 9}}, t, false));       // from inside out
    EXPECT_TRUE(segment_touches({{2, 2}, {5, 5}}, t, false));       // touches the hypotenuse
    EXPECT_FALSE(segment_touches({{2.5, 2.5}, {5, 5}}, t, false));  // just beyond it
    EXPECT_TRUE(segment_touches({{-1, 5}, {5, -1}}, t, false));     // crosses through
    EXPECT_TRUE(segment_touches({{4, 0}, {8, 0}}, t, false));       // meets a corner
    EXPECT_FALSE(segment_touches({{5, 0}, {8, 0}}, t, false));      // collinear, apart
    const std::array<XY, 3> hull{XY{0, 0}, XY{4, 0}, XY{}};
    EXPECT_TRUE(segment_touches({{4, 0}, {8, 0}}, hull, true));
    EXPECT_FALSE(segment_touches({{5, 0}, {8, 0}}, hull, true));
    EXPECT_TRUE(segment_touches({{2, -1}, {2, 1}}, hull, true));
    EXPECT_FALSE(segment_touches({{2, 0.5}, {2, 1}}, hull, true));
}

TEST(SegmentTouch, GridFindsWhatBruteForceFinds) {
    for (const double offset : {0.0, -750000.0}) {
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> u(0.0, 1000.0);
        std::vector<TouchSegment> segments;
        for (int i = 0; i < 400; ++i) {  // a crowded chain, and scattered short segments
            const double x = offset + i * 2.5;
            segments.push_back(
                {{x, offset + 500.0 + (i % 3)}, {x + 2.5, offset + 500.0 + ((i + 1) % 3)}});
            const XY p{offset + u(rng), offset + u(rng)};
            segments.push_back({p, {p.x + 3.0, p.y - 2.0}});
        }
        segments.push_back({{offset, offset}, {offset + 1000.0, offset + 1000.0}});
        const SegmentGrid grid(segments);
        std::vector<std::uint32_t> got;
        std::size_t hits = 0;
        for (int k = 0; k < 20000; ++k) {
            const XY a{offset + u(rng) * 1.1 - 50.0, offset + u(rng) * 1.1 - 50.0};
            const double size = k % 100 == 0 ? 300.0 : 4.0;
            std::array<XY, 3> t{a, XY{a.x + size, a.y}, XY{a.x, a.y + size}};
            const bool hull = k % 7 == 0;
            got.clear();
            grid.touching(t, hull, got);
            std::vector<std::uint32_t> want;
            for (std::uint32_t i = 0; i < segments.size(); ++i) {
                if (segment_touches(segments[i], t, hull)) want.push_back(i);
            }
            ASSERT_EQ(got, want) << k;
            hits += want.size();
        }
        EXPECT_GT(hits, 1000U);
    }
}

}  // namespace
}  // namespace dtm::dist
