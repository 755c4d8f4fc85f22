// SPDX-License-Identifier: MIT
/// @file
/// @brief Helpers shared by every test executable: fixture paths, scratch directories and running
/// the `dtm` binary.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace dtm::test {

/// Path of a small fixture committed under tests/data/.
[[nodiscard]] std::filesystem::path data_path(std::string_view relative);

/// Path of a file in the real third-party data set (/work/shared/data layout, see its INDEX.md).
/// Tests must GTEST_SKIP() when shared_data_available(relative) is false.
[[nodiscard]] std::filesystem::path shared_data_path(std::string_view relative);
[[nodiscard]] bool shared_data_available(std::string_view relative = {});

/// A fresh empty directory under the system temporary directory, removed on destruction.
class ScratchDir {
public:
    ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    ~ScratchDir();
    [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }
    [[nodiscard]] std::filesystem::path operator/(std::string_view name) const {
        return path_ / name;
    }

private:
    std::filesystem::path path_;
};

/// Exit code and captured output of one run of the dtm binary.
struct RunResult {
    int exit_code = -1;  ///< the process exit status, or 128 + signal if it was killed
    std::string out;     ///< everything written to stdout
    std::string err;     ///< everything written to stderr
};

/// Runs the dtm binary (DTM_BINARY) with @p args, no shell involved, stdin from /dev/null, in
/// @p working_dir if non-empty. Throws std::runtime_error if the process cannot be started.
[[nodiscard]] RunResult run_dtm(const std::vector<std::string>& args,
                                const std::filesystem::path& working_dir = {});

/// Reads a whole file as bytes (empty if it does not exist).
[[nodiscard]] std::string read_file(const std::filesystem::path& path);
/// Writes @p bytes to @p path, replacing it.
void write_file(const std::filesystem::path& path, std::string_view bytes);

}  // namespace dtm::test
