// SPDX-License-Identifier: MIT
// The in-process transport: every collective's result in source order, for 1 to 64 ranks,
// with and without random delays before the sends; the byte counters; failure of one rank.
#include "dtm/dist/comm.hpp"

#include <gtest/gtest.h>

#include <mutex>
#include <numeric>

#include "dtm/dist/in_process.hpp"

namespace dtm::dist {
namespace {

/// Rank r sends to rank d the bytes r, d, r + d repeated r + 1 times.
Bytes message(int from, int to) {
    Bytes b;
    for (int i = 0; i <= from; ++i) {
        b.push_back(static_cast<std::byte>(from));
        b.push_back(static_cast<std::byte>(to));
        b.push_back(static_cast<std::byte>(from + to));
    }
    return b;
}

void check_collectives(int ranks, unsigned jitter) {
    std::mutex mutex;
    std::vector<std::map<std::string, PhaseTraffic>> traffic(static_cast<std::size_t>(ranks));
    run_in_process(
        ranks,
        [&](Comm& comm) {
            const int me = comm.rank();
            ASSERT_EQ(comm.size(), ranks);
            comm.set_phase("exchange");
            std::vector<Bytes> out;
            for (int d = 0; d < ranks; ++d) out.push_back(message(me, d));
            const auto in = comm.alltoallv(std::move(out));
            ASSERT_EQ(static_cast<int>(in.size()), ranks);
            for (int s = 0; s < ranks; ++s)
                EXPECT_EQ(in[static_cast<std::size_t>(s)], message(s, me));

            comm.set_phase("reduce");
            std::int64_t v[3] = {me, -me, me * 10};
            comm.allreduce(v, Reduce::min);
            EXPECT_EQ(v[0], 0);
            EXPECT_EQ(v[1], -(ranks - 1));
            EXPECT_EQ(comm.allreduce(me, Reduce::max), ranks - 1);
            EXPECT_EQ(comm.allreduce(me + 1, Reduce::sum), ranks * (ranks + 1) / 2);
            EXPECT_EQ(comm.exscan_sum(me + 1), me * (me + 1) / 2);

            const auto all = comm.allgatherv(message(me, me));
            for (int s = 0; s < ranks; ++s)
                EXPECT_EQ(all[static_cast<std::size_t>(s)], message(s, s));
            Bytes b = me == ranks / 2 ? message(7, 7) : Bytes{};
            comm.bcast(b, ranks / 2);
            EXPECT_EQ(b, message(7, 7));
            comm.barrier();
            const std::lock_guard lock(mutex);
            traffic[static_cast<std::size_t>(me)] = comm.traffic();
        },
        InProcessOptions{jitter, 42});
    for (int r = 0; r < ranks; ++r) {
        const auto& t = traffic[static_cast<std::size_t>(r)];
        std::uint64_t expected = 0;
        for (int d = 0; d < ranks; ++d) expected += d == r ? 0 : message(r, d).size();
        ASSERT_TRUE(t.contains("exchange"));
        EXPECT_EQ(t.at("exchange").bytes, expected) << "rank " << r;
        EXPECT_EQ(t.at("exchange").calls, 1U);
        EXPECT_EQ(t.at("reduce").calls, 7U);
    }
}

TEST(InProcessComm, CollectivesDeliverInSourceOrder) {
    for (int ranks : {1, 2, 3, 4, 7, 16, 64}) check_collectives(ranks, 0);
}

TEST(InProcessComm, RandomDelaysChangeNothing) {
    for (int ranks : {2, 3, 7, 16}) check_collectives(ranks, 300);
}

TEST(InProcessComm, FailureOfOneRankIsRethrownAndStopsTheOthers) {
    EXPECT_THROW(run_in_process(4,
                                [](Comm& comm) {
                                    comm.barrier();
                                    if (comm.rank() == 2) throw InputError("rank two's input");
                                    for (int i = 0; i < 3; ++i) comm.barrier();
                                }),
                 InputError);
    EXPECT_THROW(run_in_process(0, [](Comm&) {}), std::invalid_argument);
}

TEST(InProcessComm, BytesRoundTrip) {
    const std::vector<double> values{1.5, -2.25, 1e300};
    const Bytes b = to_bytes(std::span<const double>(values));
    EXPECT_EQ(b.size(), 3 * sizeof(double));
    EXPECT_EQ(from_bytes<double>(b), values);
}

}  // namespace
}  // namespace dtm::dist
