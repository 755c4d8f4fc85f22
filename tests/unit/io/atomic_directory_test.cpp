// SPDX-License-Identifier: MIT
// AtomicDirectory's one-step switch and the recovery rule of its rename-pair fallback
// (libdtm/src/io/atomic_directory.cpp). tests/crash/build_kill_check.py kills real builds.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "dtm/io/atomic_file.hpp"
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

}  // namespace
