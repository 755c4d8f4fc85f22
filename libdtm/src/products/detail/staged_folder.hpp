// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: an output folder staged in a hidden temporary sibling (".NAME.tmp-<pid>"),
/// whose files are moved into the real folder only by commit(); destroyed without commit, the
/// temporary goes and the folder is untouched.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "dtm/core/error.hpp"

namespace dtm::products::detail {

class StagedFolder {
public:
    explicit StagedFolder(std::filesystem::path out) : out_(std::move(out)) {
        namespace fs = std::filesystem;
        if (out_.filename().empty()) {
            out_ = out_.parent_path();
        }
        std::error_code ec;
        if (fs::exists(out_, ec) && !fs::is_directory(out_, ec)) {
            throw UsageError("-o " + out_.string() + " is a file, not a folder");
        }
        const fs::path parent = out_.parent_path().empty() ? fs::path(".") : out_.parent_path();
        temp_ = parent / ("." + out_.filename().string() + ".tmp-" + std::to_string(::getpid()));
        fs::create_directories(parent, ec);
        fs::remove_all(temp_, ec);
        if (!fs::create_directory(temp_, ec) || ec) {
            throw Error("cannot create the temporary folder " + temp_.string() + ": " +
                        ec.message());
        }
    }
    StagedFolder(const StagedFolder&) = delete;
    StagedFolder& operator=(const StagedFolder&) = delete;
    ~StagedFolder() {
        std::error_code ec;
        std::filesystem::remove_all(temp_, ec);
    }
    [[nodiscard]] const std::filesystem::path& path() const noexcept { return temp_; }

    /// Moves @p files from the temporary folder into the output folder.
    void commit(const std::vector<std::string>& files) const {
        std::error_code ec;
        std::filesystem::create_directories(out_, ec);
        if (ec) {
            throw Error("cannot create " + out_.string() + ": " + ec.message());
        }
        for (const std::string& name : files) {
            std::filesystem::rename(temp_ / name, out_ / name, ec);
            if (ec) {
                throw Error("cannot move " + name + " into " + out_.string() + ": " + ec.message());
            }
        }
    }

private:
    std::filesystem::path out_;
    std::filesystem::path temp_;
};

/// Writes @p text to @p path (inside a staged folder: no atomicity of its own).
inline void write_text_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) {
        throw Error("cannot write " + path.string());
    }
}

}  // namespace dtm::products::detail
