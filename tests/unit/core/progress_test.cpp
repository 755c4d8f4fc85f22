// SPDX-License-Identifier: MIT
// Progress: throttling of the callback, sub() ranges nested several deep, cancellation asked for
// by the callback or from another thread, and a silent default handle.
#include "dtm/core/progress.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "dtm/core/error.hpp"

namespace {

struct Call {
    double fraction;
    std::string what;
};

/// A Progress recording every callback.
std::pair<dtm::Progress, std::shared_ptr<std::vector<Call>>> recording(bool keep_going = true) {
    auto calls = std::make_shared<std::vector<Call>>();
    dtm::Progress progress([calls, keep_going](double f, std::string_view what) {
        calls->push_back({f, std::string(what)});
        return keep_going;
    });
    return {progress, calls};
}

TEST(Progress, DefaultHandleIsSilentAndNeverCancels) {
    const dtm::Progress progress;
    EXPECT_NO_THROW(progress.report(0.5, "x"));
    EXPECT_NO_THROW(progress.check());
    progress.cancel();  // no shared state: nothing to cancel
    EXPECT_NO_THROW(progress.check());
    EXPECT_NO_THROW(progress.sub(0.2, 0.4).report(1.0));
}

TEST(Progress, SmallStepsOfOneStageAreThrottledToAboutHalfAPercent) {
    auto [progress, calls] = recording();
    for (int i = 0; i <= 10000; ++i) progress.report(i / 10000.0, "stage");
    // one call per 0.5 % at most, plus the final 1.0 which always goes through
    EXPECT_LE(calls->size(), 202U);
    EXPECT_GE(calls->size(), 190U);
    EXPECT_DOUBLE_EQ(calls->back().fraction, 1.0);
    for (std::size_t i = 1; i < calls->size(); ++i) {
        EXPECT_GE((*calls)[i].fraction, (*calls)[i - 1].fraction);
    }
}

TEST(Progress, ANewStageIsAlwaysReported) {
    auto [progress, calls] = recording();
    progress.report(0.100, "reading");
    progress.report(0.101, "reading");  // throttled
    progress.report(0.101, "triangulating");
    ASSERT_EQ(calls->size(), 2U);
    EXPECT_EQ((*calls)[1].what, "triangulating");
}

TEST(Progress, FractionsAreClampedToTheUnitRange) {
    auto [progress, calls] = recording();
    progress.report(-3.0, "a");
    progress.report(7.0, "b");
    ASSERT_EQ(calls->size(), 2U);
    EXPECT_EQ((*calls)[0].fraction, 0.0);
    EXPECT_EQ((*calls)[1].fraction, 1.0);
}

TEST(Progress, SubRangesNestAndMapOntoTheOverallRange) {
    auto [progress, calls] = recording();
    const dtm::Progress reading = progress.sub(0.2, 0.6);     // [0.2, 0.6]
    const dtm::Progress second_file = reading.sub(0.5, 1.0);  // [0.4, 0.6]
    const dtm::Progress block = second_file.sub(0.25, 0.75);  // [0.45, 0.55]
    block.report(0.0, "a");
    block.report(1.0, "b");
    second_file.report(1.0, "c");
    reading.report(0.0, "d");
    ASSERT_EQ(calls->size(), 4U);
    EXPECT_NEAR((*calls)[0].fraction, 0.45, 1e-12);
    EXPECT_NEAR((*calls)[1].fraction, 0.55, 1e-12);
    EXPECT_NEAR((*calls)[2].fraction, 0.60, 1e-12);
    EXPECT_NEAR((*calls)[3].fraction, 0.20, 1e-12);
}

TEST(Progress, CallbackReturningFalseCancelsEveryHolder) {
    auto [progress, calls] = recording(false);
    const dtm::Progress child = progress.sub(0.5, 1.0);
    EXPECT_THROW(child.report(0.1, "x"), dtm::Cancelled);
    EXPECT_THROW(progress.check(), dtm::Cancelled);
    EXPECT_THROW(child.sub(0.0, 0.1).check(), dtm::Cancelled);
}

TEST(Progress, CancelFromAnotherThreadStopsAWorkerAtItsNextCheck) {
    auto [progress, calls] = recording();
    std::atomic<bool> started{false};
    std::atomic<bool> stopped{false};
    std::thread worker([&, progress = progress.sub(0.0, 0.5)] {
        started = true;
        try {
            for (;;) {
                progress.check();
                std::this_thread::sleep_for(std::chrono::microseconds(50));
            }
        } catch (const dtm::Cancelled&) {
            stopped = true;
        }
    });
    while (!started) std::this_thread::yield();
    progress.cancel();
    worker.join();
    EXPECT_TRUE(stopped);
    EXPECT_THROW(progress.report(1.0, "after"), dtm::Cancelled);
}

TEST(Progress, ReportsFromManyThreadsAreSerialised) {
    std::atomic<int> inside{0};
    std::atomic<int> overlap{0};
    std::atomic<int> count{0};
    const dtm::Progress progress([&](double, std::string_view) {
        if (inside.fetch_add(1) != 0) ++overlap;
        ++count;
        inside.fetch_sub(1);
        return true;
    });
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            const std::string stage = "stage " + std::to_string(t);
            for (int i = 0; i < 2000; ++i) progress.report(i / 2000.0, i % 2 ? stage : "other");
        });
    }
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(overlap.load(), 0);
    EXPECT_GT(count.load(), 0);
}

}  // namespace
