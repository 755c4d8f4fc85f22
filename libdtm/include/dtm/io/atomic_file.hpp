// SPDX-License-Identifier: MIT
/// @file
/// @brief Atomic outputs: write to a temporary sibling, then rename over the target on commit().
/// Destroyed without commit(), the temporary is removed and the target is left untouched.
#pragma once

#include <filesystem>
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

}  // namespace dtm::io
