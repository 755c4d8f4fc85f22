// SPDX-License-Identifier: MIT
// Fail fast (issue 17.8): every subcommand that writes checks its outputs and option combinations
// before it reads any input. The input is a FIFO with no writer: a dtm that opened it would
// block, and a watcher thread that can open the FIFO's write end only while a reader has it open
// tells whether dtm ever did.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

struct Outcome {
    dtm::test::RunResult run;
    bool input_opened = false;
};

/// Runs dtm with @p args, where "{in}" stands for a FIFO input.
Outcome run_on_fifo(const dtm::test::ScratchDir& dir, std::vector<std::string> args) {
    const fs::path fifo = dir / "points.csv";
    if (!fs::exists(fifo)) {
        EXPECT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    }
    for (std::string& a : args) {
        if (a == "{in}") a = fifo.string();
    }
    std::atomic<bool> done{false};
    std::atomic<bool> opened{false};
    std::thread watcher([&] {
        while (!done) {
            const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // ENXIO: no reader
            if (fd >= 0) {
                opened = true;
                ::close(fd);  // the reader sees the end of the file and goes on
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    });
    Outcome out{dtm::test::run_dtm(args), false};
    done = true;
    watcher.join();
    out.input_opened = opened;
    return out;
}

void expect_fast_usage_error(const Outcome& o, const std::vector<std::string>& words) {
    EXPECT_EQ(o.run.exit_code, 2) << o.run.err;
    EXPECT_FALSE(o.input_opened) << "the input was opened before the output was checked";
    for (const std::string& w : words)
        EXPECT_NE(o.run.err.find(w), std::string::npos) << w << "\n" << o.run.err;
}

TEST(FailFast, AnUnknownOutputExtensionIsNamedWithTheKnownOnes) {
    const dtm::test::ScratchDir dir;
    const std::string foo = (dir / "x.foo").string();
    expect_fast_usage_error(run_on_fifo(dir, {"tin", "{in}", "-o", foo, "-q"}),
                            {"-o", "'.foo'", ".ply", ".2dm", ".vtp"});
    expect_fast_usage_error(run_on_fifo(dir, {"grid", "{in}", "--cell", "1", "-o", foo, "-q"}),
                            {"-o", "'.foo'", ".tif"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"contour", "{in}", "--interval", "1", "-o", foo, "-q"}),
        {"-o", "'.foo'", ".gpkg", ".shp"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"methods", "run", "lawson-flip", "{in}", "-o", foo, "-q"}),
        {"-o", "'.foo'", ".ply"});
    expect_fast_usage_error(run_on_fifo(dir, {"grid", "{in}", "--cell", "1", "-o",
                                              (dir / "d.tif").string(), "--hillshade", foo, "-q"}),
                            {"--hillshade", "'.foo'"});
}

TEST(FailFast, OptionCombinationsAreCheckedFirst) {
    const dtm::test::ScratchDir dir;
    expect_fast_usage_error(run_on_fifo(dir, {"grid", "{in}", "--cell", "1", "--cog", "-o",
                                              (dir / "d.asc").string(), "-q"}),
                            {"--cog"});
    expect_fast_usage_error(run_on_fifo(dir, {"grid", "{in}", "--cell", "1", "--extent", "1,2,x",
                                              "-o", (dir / "d.tif").string(), "-q"}),
                            {"--extent"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"contour", "{in}", "-o", (dir / "c.gpkg").string(), "-q"}),
        {"--interval"});
}

TEST(FailFast, AMissingOrUnwritableFolderIsReportedFirst) {
    const dtm::test::ScratchDir dir;
    expect_fast_usage_error(
        run_on_fifo(dir, {"tin", "{in}", "-o", (dir / "no" / "x.ply").string(), "-q"}),
        {"-o", "does not exist"});
    expect_fast_usage_error(run_on_fifo(dir, {"tin", "{in}", "-o", (dir / "t.ply").string(),
                                              "--report", (dir / "no" / "r.json").string(), "-q"}),
                            {"--report"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"build", "{in}", "-o", (dir / "points.csv" / "out").string(), "-q"}),
        {"-o"});

    // A folder this process cannot write in: mode 0555, or (for root, whom modes do not stop)
    // read-only sysfs.
    const fs::path locked = dir / "locked";
    fs::create_directory(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    fs::path unwritable = locked;
    if (::access(locked.c_str(), W_OK) == 0) unwritable = "/sys/fs";
    const int probe = ::open((unwritable / ".dtm-test-probe").c_str(), O_WRONLY | O_CREAT, 0600);
    if (probe >= 0) {
        ::close(probe);
        fs::remove(unwritable / ".dtm-test-probe");
        GTEST_SKIP() << "no unwritable folder here";
    }
    expect_fast_usage_error(
        run_on_fifo(dir, {"tin", "{in}", "-o", (unwritable / "x.ply").string(), "-q"}),
        {"-o", "cannot write in the folder"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"build", "{in}", "-o", (unwritable / "out").string(), "-q"}),
        {"-o", "cannot write in the folder"});
    fs::permissions(locked, fs::perms::owner_all);
}

TEST(FailFast, TheAnalysesCheckTheirOutputsFirst) {
    const dtm::test::ScratchDir dir;
    const std::string not_a_folder = (dir / "points.csv" / "out").string();  // under the FIFO
    expect_fast_usage_error(
        run_on_fifo(dir, {"volume", "{in}", "--plane", "0", "-o", not_a_folder, "-q"}), {"-o"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"build", "{in}", "--base", "{in}", "-o", not_a_folder, "-q"}), {"-o"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"profile", "{in}", "--line", "{in}", "-o", not_a_folder, "-q"}), {"-o"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"sections", "{in}", "--alignment", "{in}", "--interval", "10", "--width",
                          "20", "-o", not_a_folder, "-q"}),
        {"-o"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"check", "{in}", "{in}", "-o", (dir / "no" / "r.csv").string(), "-q"}),
        {"-o", "does not exist"});
    expect_fast_usage_error(
        run_on_fifo(dir, {"check", "{in}", "{in}", "-o", (dir / "r.csv").string(), "--stats",
                          (dir / "no" / "s.json").string(), "-q"}),
        {"--stats"});
}

}  // namespace
