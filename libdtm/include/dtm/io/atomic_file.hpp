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
/// the target (".<target name>.tmp-<pid>-<n>"), and commit() moves them into the target folder
/// (created if needed), replacing files of the same names and leaving other files there alone.
/// Destroyed without commit(), the staging folder and everything in it are removed, so a failed
/// or cancelled run leaves the target folder exactly as it was.
class AtomicDirectory {
public:
    /// @param target the final folder ("out" or "out/"). Creates its parent folders and the
    /// staging folder. @throws UsageError if @p target exists and is not a folder; Error if the
    /// staging folder cannot be created.
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
    /// Moves every recorded file into the target folder (renames within one file system) and
    /// removes the staging folder. @throws Error if a file is missing or cannot be moved.
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path staging_;
    std::vector<std::string> files_;
    bool committed_ = false;
};

}  // namespace dtm::io
