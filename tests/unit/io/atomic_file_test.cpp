// SPDX-License-Identifier: MIT
#include "dtm/io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

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

TEST(AtomicDirectory, StagingIsAHiddenSiblingAndTheTargetAppearsOnlyOnCommit) {
    const ScratchDir dir;
    dtm::io::AtomicDirectory out(dir / "products/");
    EXPECT_EQ(out.target(), dir / "products");
    EXPECT_EQ(out.staging().parent_path(), dir.path());
    EXPECT_TRUE(out.staging().filename().string().starts_with(".products.tmp-")) << out.staging();
    write_file(out.add("a.txt"), "a");
    write_file(out.add("b.txt"), "b");
    EXPECT_FALSE(fs::exists(dir / "products")) << "target created before commit";
    EXPECT_EQ(out.files(), (std::vector<std::string>{"a.txt", "b.txt"}));
    out.commit();
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"products"});
    EXPECT_EQ(names_in(dir / "products"), (std::vector<std::string>{"a.txt", "b.txt"}));
    EXPECT_EQ(read_file(dir / "products" / "b.txt"), "b");
}

TEST(AtomicDirectory, CommitReplacesFilesOfTheSameNameAndKeepsTheOthers) {
    const ScratchDir dir;
    fs::create_directories(dir / "out");
    write_file(dir / "out" / "a.txt", "old a");
    write_file(dir / "out" / "keep.txt", "keep");
    {
        dtm::io::AtomicDirectory out(dir / "out");
        write_file(out.add("a.txt"), "new a");
        EXPECT_EQ(read_file(dir / "out" / "a.txt"), "old a");
        out.commit();
    }
    EXPECT_EQ(read_file(dir / "out" / "a.txt"), "new a");
    EXPECT_EQ(read_file(dir / "out" / "keep.txt"), "keep");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out"}) << "staging left behind";
}

TEST(AtomicDirectory, WithoutCommitNothingChangesAndNoStagingIsLeft) {
    const ScratchDir dir;
    fs::create_directories(dir / "out");
    write_file(dir / "out" / "a.txt", "old");
    {
        dtm::io::AtomicDirectory out(dir / "out");
        write_file(out.add("a.txt"), "half-written");
        write_file(out.add("b.txt"), "new");
    }
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out"});
    EXPECT_EQ(names_in(dir / "out"), std::vector<std::string>{"a.txt"});
    EXPECT_EQ(read_file(dir / "out" / "a.txt"), "old");
}

TEST(AtomicDirectory, NamesAreRecordedOnceInOrderAndCompanionsStayBehind) {
    const ScratchDir dir;
    dtm::io::AtomicDirectory out(dir / "out");
    const fs::path first = out.add("z.txt");
    EXPECT_EQ(out.add("z.txt"), first);
    write_file(first, "z");
    write_file(out.add("a.txt"), "a");
    write_file(out.staging() / "unlisted.txt", "x");
    EXPECT_EQ(out.files(), (std::vector<std::string>{"z.txt", "a.txt"}));
    EXPECT_TRUE(out.contains("a.txt"));
    EXPECT_FALSE(out.contains("unlisted.txt"));
    out.commit();
    EXPECT_EQ(names_in(dir / "out"), (std::vector<std::string>{"a.txt", "z.txt"}));
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out"});
}

TEST(AtomicDirectory, FilesInASubfolderMoveWithItAndReplaceTheOldSubfolder) {
    const ScratchDir dir;
    fs::create_directories(dir / "out" / "volume");
    write_file(dir / "out" / "volume" / "old.json", "old");
    {
        dtm::io::AtomicDirectory out(dir / "out");
        fs::create_directory(out.staging() / "volume");
        write_file(out.add("volume/volume.json"), "new");
        write_file(out.add("a.txt"), "a");
        out.commit();
    }
    EXPECT_EQ(names_in(dir / "out"), (std::vector<std::string>{"a.txt", "volume"}));
    EXPECT_EQ(names_in(dir / "out" / "volume"), std::vector<std::string>{"volume.json"});
    EXPECT_EQ(read_file(dir / "out" / "volume" / "volume.json"), "new");
}

TEST(AtomicDirectory, MissingFileFailsTheCommit) {
    const ScratchDir dir;
    dtm::io::AtomicDirectory out(dir / "out");
    (void)out.add("never-written.txt");
    EXPECT_THROW(out.commit(), dtm::Error);
}

TEST(AtomicDirectory, TargetThatIsAFileIsUsageError) {
    const ScratchDir dir;
    write_file(dir / "out", "a file");
    EXPECT_THROW(dtm::io::AtomicDirectory{dir / "out"}, dtm::UsageError);
    EXPECT_EQ(read_file(dir / "out"), "a file");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out"});
}

TEST(AtomicDirectory, TwoStagingsForTheSameTargetAreDistinct) {
    const ScratchDir dir;
    const dtm::io::AtomicDirectory first(dir / "out");
    const dtm::io::AtomicDirectory second(dir / "out");
    EXPECT_NE(first.staging(), second.staging());
}

// The one-step switch and the recovery rule of the rename-pair fallback
// (src/io/atomic_directory.cpp); tests/crash/build_kill_check.py kills real builds.
TEST(AtomicDirectory, TheTargetIsSwappedWholeKeepingOtherFilesAndFolders) {
    const ScratchDir dir;
    fs::create_directories(dir / "out" / "mine");
    write_file(dir / "out" / "a.txt", "old a");
    write_file(dir / "out" / "mine" / "notes.txt", "notes");
    const auto inode = fs::hard_link_count(dir / "out" / "mine" / "notes.txt");
    {
        dtm::io::AtomicDirectory out(dir / "out");
        write_file(out.add("a.txt"), "new a");
        write_file(out.add("b.txt"), "new b");
        out.commit();
    }
    EXPECT_EQ(names_in(dir / "out"), (std::vector<std::string>{"a.txt", "b.txt", "mine"}));
    EXPECT_EQ(read_file(dir / "out" / "a.txt"), "new a");
    EXPECT_EQ(read_file(dir / "out" / "mine" / "notes.txt"), "notes");
    EXPECT_EQ(fs::hard_link_count(dir / "out" / "mine" / "notes.txt"), inode)
        << "the old folder's link was not removed";
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out"});
}

TEST(AtomicDirectory, ASymlinkedTargetStaysASymlinkAndItsFolderIsSwapped) {
    const ScratchDir dir;
    fs::create_directories(dir / "real");
    write_file(dir / "real" / "a.txt", "old");
    fs::create_directory_symlink(dir / "real", dir / "link");
    {
        dtm::io::AtomicDirectory out(dir / "link");
        write_file(out.add("a.txt"), "new");
        out.commit();
    }
    EXPECT_TRUE(fs::is_symlink(dir / "link"));
    EXPECT_EQ(read_file(dir / "real" / "a.txt"), "new");
}

TEST(RecoverDirectory, AMissingTargetGetsItsBackupBack) {
    const ScratchDir dir;
    fs::create_directories(dir / ".out.old");
    write_file(dir / ".out.old" / "a.txt", "old");
    EXPECT_TRUE(dtm::io::recover_directory(dir / "out"));
    EXPECT_EQ(read_file(dir / "out" / "a.txt"), "old");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out"});
}

TEST(RecoverDirectory, ABackupBesideTheTargetIsRemoved) {
    const ScratchDir dir;
    fs::create_directories(dir / ".out.old");
    fs::create_directories(dir / "out");
    write_file(dir / "out" / "a.txt", "new");
    EXPECT_FALSE(dtm::io::recover_directory(dir / "out"));
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out"});
    EXPECT_EQ(read_file(dir / "out" / "a.txt"), "new");
}

TEST(RecoverDirectory, StagingOfDeadProcessesIsRemovedAndOursIsKept) {
    const ScratchDir dir;
    const pid_t child = fork();
    if (child == 0) _exit(0);
    ASSERT_GT(child, 0);
    waitpid(child, nullptr, 0);  // a pid that no longer runs
    const std::string dead = ".out.tmp-" + std::to_string(child) + "-0";
    fs::create_directories(dir / dead);
    fs::create_directories(dir / (".other.tmp-" + std::to_string(child) + "-0"));
    const dtm::io::AtomicDirectory live(dir / "out");
    EXPECT_FALSE(fs::exists(dir / dead));
    EXPECT_TRUE(fs::exists(live.staging()));
    EXPECT_TRUE(fs::exists(dir / (".other.tmp-" + std::to_string(child) + "-0")))
        << "another target's staging";
}

TEST(AtomicDirectory, TheConstructorAppliesTheRecoveryRule) {
    const ScratchDir dir;
    fs::create_directories(dir / ".out.old");
    write_file(dir / ".out.old" / "a.txt", "old");
    {
        const dtm::io::AtomicDirectory out(dir / "out");  // destroyed without commit
    }
    EXPECT_EQ(read_file(dir / "out" / "a.txt"), "old");
}
