// SPDX-License-Identifier: MIT
/// @file
/// @brief Atomic outputs: write to a temporary sibling, then rename over the target on commit().
/// Destroyed without commit(), the temporary is removed and the target is left untouched.
/// AtomicOutput does it for one file, AtomicDirectory for a folder of products.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace dtm::io {

class AtomicOutput {
public:
    /// @param target the final path. The temporary lives in the same directory.
    explicit AtomicOutput(std::filesystem::path target);
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;
    ~AtomicOutput();

    /// Where to write. For multi-file formats (shapefile) companion files written next to it with
    /// the same stem are committed too.
    [[nodiscard]] const std::filesystem::path& temp_path() const noexcept { return temp_; }
    [[nodiscard]] const std::filesystem::path& target() const noexcept { return target_; }
    /// Renames the temporary (and its companions) onto the target. @throws Error on failure.
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path temp_;
    bool committed_ = false;
};

/// A folder of outputs written as a whole: every file goes into a hidden staging folder next to
/// the target (".<target name>.tmp-<pid>-<n>"); commit() carries the target's other files over
/// (hard links), flushes everything to the disk and swaps the staging folder with the target in
/// one atomic step (renameat2 RENAME_EXCHANGE), so at every instant the target holds either all
/// the old files or all the new ones. Files of the same names are replaced, other files are kept.
/// Where the file system cannot exchange (EINVAL, ENOSYS, EOPNOTSUPP) it falls back to a rename
/// pair, target -> ".<target name>.old" then staging -> target, which a crash between the two
/// leaves without a target: recover_directory() (run by the constructor, and by any reader that
/// wants to) renames the backup back. Destroyed without commit(), the staging folder and
/// everything in it are removed, so a failed or cancelled run leaves the target exactly as it was.
class AtomicDirectory {
public:
    /// @param target the final folder ("out" or "out/"). Creates its parent folders and the
    /// staging folder, after recover_directory(). @throws UsageError if @p target exists and is not
    /// a folder; Error if the staging folder cannot be created.
    explicit AtomicDirectory(std::filesystem::path target);
    AtomicDirectory(const AtomicDirectory&) = delete;
    AtomicDirectory& operator=(const AtomicDirectory&) = delete;
    ~AtomicDirectory();

    /// Where to write the file @p name (a file name, or a path in a subfolder the caller
    /// creates in the staging folder: "volume/volume.json") in the staging folder; the name is
    /// recorded, once, in the order of the calls, for commit(). A writer may write companions next
    /// to it (a shapefile's .shx, .dbf): only recorded names are moved.
    [[nodiscard]] std::filesystem::path add(const std::string& name);
    /// The names recorded by add(), in order.
    [[nodiscard]] const std::vector<std::string>& files() const noexcept { return files_; }
    [[nodiscard]] bool contains(const std::string& name) const noexcept;
    [[nodiscard]] const std::filesystem::path& staging() const noexcept { return staging_; }
    [[nodiscard]] const std::filesystem::path& target() const noexcept { return target_; }
    /// Swaps the staging folder (the recorded files and the target's other files) into place and
    /// removes the old folder. Unrecorded files in the staging folder are dropped. @throws Error
    /// if a file is missing, cannot be flushed to the disk (full disk) or cannot be moved.
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path staging_;
    std::vector<std::string> files_;
    bool committed_ = false;
};

/// The recovery rule of AtomicDirectory's fallback, for a later run or a reader: when @p target
/// is missing and its backup ".<name>.old" exists (a crash between the two renames), the backup
/// becomes the target again (the old products, complete); when both exist, the backup is
/// removed. Also removes the staging folders of processes that no longer run. Returns true when
/// it restored the backup. Never throws.
bool recover_directory(const std::filesystem::path& target) noexcept;

}  // namespace dtm::io
