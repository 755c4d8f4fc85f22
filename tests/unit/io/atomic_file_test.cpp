// SPDX-License-Identifier: MIT
#include "dtm/io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using dtm::test::read_file;
using dtm::test::ScratchDir;
using dtm::test::write_file;

namespace {

std::vector<std::string> names_in(const fs::path& directory) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

TEST(AtomicOutput, TemporaryIsAHiddenSiblingKeepingTheExtension) {
    const ScratchDir dir;
    const dtm::io::AtomicOutput output(dir / "tin.ply");
    EXPECT_EQ(output.temp_path().parent_path(), dir.path());
    const std::string name = output.temp_path().filename().string();
    EXPECT_TRUE(name.starts_with(".tin.tmp-")) << name;
    EXPECT_EQ(output.temp_path().extension(), ".ply");
    EXPECT_NE(output.temp_path(), output.target());
}

TEST(AtomicOutput, TwoOutputsForTheSameTargetGetDifferentTemporaries) {
    const ScratchDir dir;
    const dtm::io::AtomicOutput first(dir / "a.ply");
    const dtm::io::AtomicOutput second(dir / "a.ply");
    EXPECT_NE(first.temp_path(), second.temp_path());
}

TEST(AtomicOutput, CommitReplacesTheTargetAndLeavesNoTemporary) {
    const ScratchDir dir;
    write_file(dir / "out.txt", "old");
    {
        dtm::io::AtomicOutput output(dir / "out.txt");
        write_file(output.temp_path(), "new");
        EXPECT_EQ(read_file(dir / "out.txt"), "old") << "target changed before commit";
        output.commit();
    }
    EXPECT_EQ(read_file(dir / "out.txt"), "new");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.txt"});
}

TEST(AtomicOutput, DestroyedWithoutCommitLeavesTheTargetUntouchedAndRemovesTemporaries) {
    const ScratchDir dir;
    write_file(dir / "roads.shp", "old shp");
    {
        const dtm::io::AtomicOutput output(dir / "roads.shp");
        write_file(output.temp_path(), "partial");
        fs::path companion = output.temp_path();
        companion.replace_extension(".dbf");
        write_file(companion, "partial dbf");
    }
    EXPECT_EQ(read_file(dir / "roads.shp"), "old shp");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"roads.shp"});
}

TEST(AtomicOutput, CommitMovesCompanionFilesWithTheSameStem) {
    const ScratchDir dir;
    write_file(dir / "unrelated.dbf", "keep");
    {
        dtm::io::AtomicOutput output(dir / "tin.shp");
        write_file(output.temp_path(), "shp");
        for (const char* extension : {".shx", ".dbf", ".prj"}) {
            fs::path companion = output.temp_path();
            companion.replace_extension(extension);
            write_file(companion, extension);
        }
        output.commit();
    }
    EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"tin.dbf", "tin.prj", "tin.shp",
                                                              "tin.shx", "unrelated.dbf"}));
    EXPECT_EQ(read_file(dir / "tin.prj"), ".prj");
    EXPECT_EQ(read_file(dir / "unrelated.dbf"), "keep");
}

TEST(AtomicOutput, CompanionsOfAnotherTemporaryAreNotTaken) {
    const ScratchDir dir;
    dtm::io::AtomicOutput mine(dir / "tin.shp");
    const dtm::io::AtomicOutput other(dir / "tin.shp");
    write_file(mine.temp_path(), "mine");
    fs::path other_companion = other.temp_path();
    other_companion.replace_extension(".dbf");
    write_file(other_companion, "other");
    mine.commit();
    EXPECT_FALSE(fs::exists(dir / "tin.dbf"));
    EXPECT_TRUE(fs::exists(other_companion));
}

TEST(AtomicOutput, TargetWithoutExtensionCommits) {
    const ScratchDir dir;
    dtm::io::AtomicOutput output(dir / "README");
    write_file(output.temp_path(), "text");
    output.commit();
    EXPECT_EQ(read_file(dir / "README"), "text");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"README"});
}

TEST(AtomicOutput, CommitWithoutAWrittenFileThrows) {
    const ScratchDir dir;
    dtm::io::AtomicOutput output(dir / "never.ply");
    EXPECT_THROW(output.commit(), dtm::Error);
    EXPECT_FALSE(fs::exists(dir / "never.ply"));
}

TEST(AtomicOutput, MissingDirectoryIsAUsageErrorNamingIt) {
    const ScratchDir dir;
    try {
        const dtm::io::AtomicOutput output(dir / "no" / "such" / "tin.ply");
        FAIL() << "no exception";
    } catch (const dtm::UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("such"), std::string::npos) << e.what();
    }
}

TEST(AtomicOutput, RelativeTargetInTheCurrentDirectoryWorks) {
    const ScratchDir dir;
    const fs::path previous = fs::current_path();
    fs::current_path(dir.path());
    {
        dtm::io::AtomicOutput output("plain.txt");
        EXPECT_EQ(output.temp_path().parent_path(), fs::path("."));
        write_file(output.temp_path(), "x");
        output.commit();
    }
    fs::current_path(previous);
    EXPECT_EQ(read_file(dir / "plain.txt"), "x");
}
