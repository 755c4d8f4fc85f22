// SPDX-License-Identifier: MIT
// Exact duplicates across ranks (R-D3) against the serial merge (merge_input without snapping):
// the same vertices bit for bit (position, z by every DuplicateRule, z known or not), the same
// vertex of every input and the same merge report, for 1 to 64 in-process ranks.
#include "dtm/dist/duplicates.hpp"

#include <gtest/gtest.h>

#include <bit>

#include "algo/detail/input_merge.hpp"
#include "dtm/dist/in_process.hpp"
#include "support/dist_cases.hpp"

namespace dtm::dist {
namespace {

bool same_bits(const Point3& a, const Point3& b) {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

void expect_serial_merge(const TerrainInput& input, DuplicateRule rule, int ranks) {
    TriangulateOptions options;
    options.duplicates = rule;
    const detail::MergedInput serial = detail::merge_input(input, options);
    const std::vector<InputPoint> all = test::combined_input(input);
    ASSERT_EQ(all.size(), serial.points_in);
    std::vector<MergedShare> shares(static_cast<std::size_t>(ranks));
    run_in_process(ranks, [&](Comm& comm) {
        const std::size_t r = static_cast<std::size_t>(comm.rank());
        const std::size_t p = static_cast<std::size_t>(ranks);
        const std::span<const InputPoint> mine(all.data() + r * all.size() / p,
                                               (r + 1) * all.size() / p - r * all.size() / p);
        shares[r] = merge_exact_duplicates(comm, mine, rule);
    });
    std::vector<DuplicateMerge> merges;
    std::uint64_t vertices = 0;
    for (const MergedShare& s : shares) {
        ASSERT_EQ(s.total_vertices, serial.vertices.size());
        ASSERT_EQ(s.first_vertex, vertices);
        for (const Vertex& v : s.vertices) {
            ASSERT_LT(v.id, serial.vertices.size());
            EXPECT_TRUE(same_bits(v.p, serial.vertices[v.id])) << "vertex " << v.id;
            EXPECT_EQ(v.z_known, serial.z_known[v.id]) << "vertex " << v.id;
        }
        vertices += s.vertices.size();
        for (std::size_t i = 0; i < s.vertex_of_input.size(); ++i) {
            EXPECT_EQ(s.vertex_of_input[i], serial.vertex_of_input(s.first_input + i))
                << "input " << s.first_input + i;
        }
        merges.insert(merges.end(), s.merges.begin(), s.merges.end());
    }
    EXPECT_EQ(vertices, serial.vertices.size());
    ASSERT_EQ(merges.size(), serial.merges.size());
    for (std::size_t k = 0; k < merges.size(); ++k) {
        EXPECT_EQ(merges[k].kept_input, serial.merges[k].kept_input);
        EXPECT_EQ(merges[k].merged_input, serial.merges[k].merged_input);
        EXPECT_TRUE(same_bits(merges[k].kept, serial.merges[k].kept)) << "merge " << k;
        EXPECT_TRUE(same_bits(merges[k].merged, serial.merges[k].merged)) << "merge " << k;
    }
}

TEST(MergeExactDuplicates, EqualsTheSerialMergeForEveryRuleAndRankCount) {
    const TerrainInput input = test::duplicate_rich_input(3000, 5);
    for (DuplicateRule rule :
         {DuplicateRule::first, DuplicateRule::mean, DuplicateRule::min, DuplicateRule::max}) {
        for (int ranks : {1, 2, 3, 4, 7, 16, 64}) {
            SCOPED_TRACE("rule " + std::to_string(static_cast<int>(rule)) + ", " +
                         std::to_string(ranks) + " ranks");
            expect_serial_merge(input, rule, ranks);
        }
    }
}

TEST(MergeExactDuplicates, WithoutDuplicatesEveryInputIsItsOwnVertex) {
    TerrainInput input;
    for (int i = 0; i < 500; ++i) input.points.push_back({i * 1.5, i * 0.5, i * 0.1});
    expect_serial_merge(input, DuplicateRule::mean, 7);
    expect_serial_merge(TerrainInput{}, DuplicateRule::first, 4);
}

}  // namespace
}  // namespace dtm::dist
