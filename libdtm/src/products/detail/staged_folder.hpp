// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: the analyses' output folders, staged in an io::AtomicDirectory, and their
/// text files.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"

namespace dtm::products::detail {

/// Records @p files (written into folder.staging()) and moves them into the target folder.
inline void commit_files(io::AtomicDirectory& folder, const std::vector<std::string>& files) {
    for (const std::string& name : files) (void)folder.add(name);
    folder.commit();
}

/// Writes @p text to @p path (inside a staged folder: no atomicity of its own).
inline void write_text_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw Error("cannot write " + path.string());
}

}  // namespace dtm::products::detail
