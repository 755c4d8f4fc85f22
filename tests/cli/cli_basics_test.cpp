// SPDX-License-Identifier: MIT
// The `dtm` binary's contract common to every subcommand: version, help, and exit codes for usage
// errors (2). Runs the real binary (DTM_BINARY) in a scratch directory.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/test_support.hpp"

using dtm::test::run_dtm;
using dtm::test::RunResult;
using dtm::test::ScratchDir;

namespace {

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST(CliBasics, VersionPrintsTheProjectVersionAndExitsZero) {
    const RunResult r = run_dtm({"--version"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "dtm " DTM_VERSION)) << r.out;
}

TEST(CliBasics, HelpListsEverySubcommandAndExitsZero) {
    const RunResult r = run_dtm({"--help"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    for (const char* command : {"tin", "info", "grid", "contour", "build"}) {
        EXPECT_TRUE(contains(r.out, command)) << "missing '" << command << "' in:\n" << r.out;
    }
}

TEST(CliBasics, SubcommandHelpExitsZero) {
    const RunResult r = run_dtm({"tin", "--help"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "--breaklines")) << r.out;
}

TEST(CliBasics, NoSubcommandIsAUsageErrorExitingTwo) {
    const RunResult r = run_dtm({});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_FALSE(r.err.empty());
}

TEST(CliBasics, UnknownSubcommandExitsTwoAndNamesIt) {
    const RunResult r = run_dtm({"triangulate-everything"});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, "triangulate-everything")) << r.err;
}

TEST(CliBasics, UnknownOptionExitsTwoAndNamesIt) {
    const ScratchDir dir;
    dtm::test::write_file(dir / "points.xyz", "0 0 1\n1 0 2\n0 1 3\n1 1 4\n");
    const RunResult r =
        run_dtm({"tin", "--no-such-option", "points.xyz", "-o", "tin.ply"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, "--no-such-option")) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "tin.ply"));
}

TEST(CliBasics, UnknownGlobalOptionExitsTwo) {
    const RunResult r = run_dtm({"--frobnicate"});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, "--frobnicate")) << r.err;
}

TEST(CliBasics, MissingInputFileExitsTwoAndNamesTheFile) {
    const ScratchDir dir;
    const RunResult r = run_dtm({"tin", "no_such_points.xyz", "-o", "tin.ply"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, "no_such_points.xyz")) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "tin.ply"));
}

TEST(CliBasics, MissingBreaklineFileExitsTwoAndNamesTheFile) {
    const ScratchDir dir;
    dtm::test::write_file(dir / "points.xyz", "0 0 1\n1 0 2\n0 1 3\n1 1 4\n");
    const RunResult r = run_dtm(
        {"tin", "points.xyz", "--breaklines", "no_such_lines.csv", "-o", "tin.ply"}, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, "no_such_lines.csv")) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "tin.ply"));
}

TEST(CliBasics, ErrorsArePrefixedWithTheProgramName) {
    const ScratchDir dir;
    const RunResult r = run_dtm({"tin", "no_such_points.xyz", "-o", "tin.ply"}, dir.path());
    EXPECT_TRUE(r.err.starts_with("dtm")) << r.err;
}

namespace {

/// A 10 x 10 grid of survey points with a sloping surface, as `x y z` text.
std::string grid_points() {
    std::string text;
    for (int i = 0; i < 100; ++i) {
        const int x = i % 10, y = i / 10;
        text += std::to_string(-750000 + 3 * x) + ".25 " + std::to_string(-1050000 + 3 * y) +
                ".5 " + std::to_string(300 + x + 2 * y) + "\n";
    }
    return text;
}

}  // namespace

TEST(CliBasics, ProgressIsOneLinePerStageWhenStderrIsNotATerminal) {
    const ScratchDir dir;
    dtm::test::write_file(dir / "points.xyz", grid_points());
    const RunResult r = run_dtm({"tin", "points.xyz", "-o", "tin.ply"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find('\r'), std::string::npos) << "no in-place redraw in a log: " << r.err;
    EXPECT_EQ(r.err.find('\033'), std::string::npos) << "no escape codes in a log: " << r.err;
    std::size_t lines = 0;
    for (std::size_t begin = 0; begin < r.err.size();) {
        const std::size_t end = r.err.find('\n', begin);
        ASSERT_NE(end, std::string::npos) << "unterminated line: " << r.err.substr(begin);
        const std::string line = r.err.substr(begin, end - begin);
        EXPECT_TRUE(line.starts_with("dtm")) << line;
        EXPECT_NE(line.find("%] "), std::string::npos) << line;
        ++lines;
        begin = end + 1;
    }
    EXPECT_GE(lines, 2u) << r.err;
}

TEST(CliBasics, QuietPrintsNothingOnStderr) {
    const ScratchDir dir;
    dtm::test::write_file(dir / "points.xyz", grid_points());
    const RunResult r = run_dtm({"tin", "points.xyz", "-o", "tin.ply", "--quiet"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_TRUE(std::filesystem::exists(dir / "tin.ply"));
}
