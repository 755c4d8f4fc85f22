// SPDX-License-Identifier: MIT
// The distributed tree (R-D1): for 1 to 64 virtual ranks and any initial spread of the points,
// every leaf's point set is the serial kernel's subtree at the leaf's positions, every point is
// on exactly one rank, and the shares and byte counters do not depend on timing.
#include "dtm/dist/partition.hpp"

#include <gtest/gtest.h>

#include <map>
#include <mutex>

#include "dtm/core/error.hpp"
#include "dtm/dist/in_process.hpp"
#include "support/dist_cases.hpp"

namespace dtm::dist {
namespace {

struct Outcome {
    std::vector<Share> shares;
    std::vector<std::map<std::string, PhaseTraffic>> traffic;
};

Outcome partition(const std::vector<Point>& points,
                  int ranks,
                  bool strided,
                  const PartitionOptions& options = {},
                  unsigned jitter = 0) {
    Outcome run;
    run.shares.resize(static_cast<std::size_t>(ranks));
    run.traffic.resize(static_cast<std::size_t>(ranks));
    run_in_process(
        ranks,
        [&](Comm& comm) {
            auto share = partition_points(
                comm, test::initial_share(points, comm.rank(), ranks, strided), options, {});
            const auto r = static_cast<std::size_t>(comm.rank());
            run.shares[r] = std::move(share);
            run.traffic[r] = comm.traffic();
        },
        InProcessOptions{jitter, 7});
    return run;
}

/// Every leaf's ids equal the serial kernel's ids at [lo, hi); every point is placed once.
void expect_serial_tree(const Outcome& run,
                        const std::vector<Point>& points,
                        int ranks,
                        const std::vector<std::uint64_t>& serial,
                        const std::string& what) {
    const auto expected_leaves = tree_leaves(points.size(), ranks, 3);
    std::size_t placed = 0;
    for (int r = 0; r < ranks; ++r) {
        const Share& s = run.shares[static_cast<std::size_t>(r)];
        ASSERT_EQ(s.total, points.size()) << what;
        ASSERT_EQ(s.leaves.size(), expected_leaves.size()) << what;
        for (std::size_t i = 0; i < s.leaves.size(); ++i) {
            EXPECT_EQ(s.leaves[i].lo, expected_leaves[i].lo) << what;
            EXPECT_EQ(s.leaves[i].hi, expected_leaves[i].hi) << what;
            EXPECT_EQ(s.leaves[i].owner, expected_leaves[i].owner) << what;
        }
        ASSERT_EQ(s.offsets.size(), s.last_leaf - s.first_leaf + 1) << what;
        for (std::size_t i = s.first_leaf; i < s.last_leaf; ++i) {
            const Leaf& leaf = s.leaves[i];
            EXPECT_EQ(leaf.owner, r) << what;
            std::vector<std::uint64_t> got;
            for (std::size_t k = s.offsets[i - s.first_leaf]; k < s.offsets[i - s.first_leaf + 1];
                 ++k) {
                got.push_back(s.points[k].id);
            }
            std::vector<std::uint64_t> want(serial.begin() + static_cast<std::ptrdiff_t>(leaf.lo),
                                            serial.begin() + static_cast<std::ptrdiff_t>(leaf.hi));
            std::sort(got.begin(), got.end());
            std::sort(want.begin(), want.end());
            ASSERT_EQ(got, want) << what << ": leaf " << i << " [" << leaf.lo << ", " << leaf.hi
                                 << ") on rank " << r;
            placed += got.size();
        }
    }
    EXPECT_EQ(placed, points.size()) << what;
}

TEST(PartitionPoints, LeavesAreTheSerialSubtreesForEveryRankCount) {
    for (const auto& c : test::dist_cases(6000)) {
        const auto serial = test::serial_kernel_order(c.points);
        for (int ranks : {1, 2, 3, 4, 7, 16, 64}) {
            for (bool strided : {false, true}) {
                const std::string what = c.name + " on " + std::to_string(ranks) + " ranks" +
                                         (strided ? ", strided" : "");
                expect_serial_tree(partition(c.points, ranks, strided), c.points, ranks, serial,
                                   what);
            }
        }
    }
}

TEST(PartitionPoints, ManySelectionRoundsGiveTheSameTree) {
    // Tiny samples and gathers: the windows shrink over many rounds and still end at the median.
    PartitionOptions options;
    options.sample = 8;
    options.gather_below = 16;
    for (const auto& c : test::dist_cases(8000)) {
        if (c.points.size() < 1000) continue;
        const auto serial = test::serial_kernel_order(c.points);
        for (int ranks : {3, 16}) {
            const Outcome run = partition(c.points, ranks, true, options);
            expect_serial_tree(run, c.points, ranks, serial, c.name + " (many rounds)");
            EXPECT_GT(run.shares[0].stats.sample_rounds, 10U) << c.name;
        }
    }
}

TEST(PartitionPoints, RandomDelaysChangeNoShareAndNoCounter) {
    const auto c = test::dist_cases(5000).front();
    for (int ranks : {2, 7}) {
        const Outcome calm = partition(c.points, ranks, false);
        const Outcome jittery = partition(c.points, ranks, false, {}, 200);
        for (std::size_t r = 0; r < calm.shares.size(); ++r) {
            const auto& a = calm.shares[r];
            const auto& b = jittery.shares[r];
            ASSERT_EQ(a.points.size(), b.points.size());
            for (std::size_t i = 0; i < a.points.size(); ++i) {
                EXPECT_EQ(a.points[i].id, b.points[i].id);
            }
            EXPECT_EQ(a.offsets, b.offsets);
            for (const auto& [phase, t] : calm.traffic[r]) {
                EXPECT_EQ(t.bytes, jittery.traffic[r].at(phase).bytes) << phase;
                EXPECT_EQ(t.calls, jittery.traffic[r].at(phase).calls) << phase;
            }
        }
    }
}

TEST(PartitionPoints, CoincidentPointsAreRefusedOnEveryRank) {
    auto points = test::dist_cases(500).front().points;
    points.push_back({points[10].x, points[10].y, points.size()});
    try {
        partition(points, 4, true);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("points 10 and 500 coincide"), std::string::npos)
            << e.what();
    }
}

TEST(PartitionPoints, CancellationStopsEveryRank) {
    const auto points = test::dist_cases(3000).front().points;
    int calls = 0;
    std::mutex mutex;
    EXPECT_THROW(run_in_process(3,
                                [&](Comm& comm) {
                                    Progress progress([&](double, std::string_view) {
                                        const std::lock_guard lock(mutex);
                                        return comm.rank() != 1 || ++calls < 2;
                                    });
                                    partition_points(
                                        comm, test::initial_share(points, comm.rank(), 3, false),
                                        {}, progress);
                                }),
                 Cancelled);
}

TEST(TreeLeaves, OwnersAreContiguousAndBalanced) {
    for (int ranks : {1, 3, 4, 7, 64}) {
        const auto leaves = tree_leaves(1000003, ranks, 3);
        std::vector<std::uint64_t> per_rank(static_cast<std::size_t>(ranks), 0);
        for (std::size_t i = 0; i < leaves.size(); ++i) {
            if (i > 0) {
                EXPECT_EQ(leaves[i].lo, leaves[i - 1].hi);
                EXPECT_GE(leaves[i].owner, leaves[i - 1].owner);
            }
            per_rank[static_cast<std::size_t>(leaves[i].owner)] += leaves[i].hi - leaves[i].lo;
        }
        for (auto n : per_rank) {
            EXPECT_NEAR(static_cast<double>(n), 1000003.0 / ranks, 1000003.0 / ranks / 8 + 2);
        }
    }
    EXPECT_EQ(tree_leaves(5, 4, 3).size(), 2U);  // 2 + 3 points: base cases
}

}  // namespace
}  // namespace dtm::dist
