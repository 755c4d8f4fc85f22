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
