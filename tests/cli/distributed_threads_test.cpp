// SPDX-License-Identifier: MIT
// Threads per rank under mpirun: the machine's cores shared among the job's ranks on it.
#include <gtest/gtest.h>

#include "distributed.hpp"

namespace dtm::cli {
namespace {

TEST(DistributedThreads, CoresAreSharedAmongTheRanksOfOneMachine) {
    EXPECT_EQ(threads_per_rank(2, 2), 1u);  // CI: -np 2 on 2 cores
    EXPECT_EQ(threads_per_rank(2, 4), 1u);  // oversubscribed: never below one
    EXPECT_EQ(threads_per_rank(64, 4), 16u);
    EXPECT_EQ(threads_per_rank(7, 2), 3u);
    EXPECT_EQ(threads_per_rank(8, 0), 8u);  // the launcher does not say: all of them
    EXPECT_EQ(threads_per_rank(0, 0), 1u);
}

}  // namespace
}  // namespace dtm::cli
