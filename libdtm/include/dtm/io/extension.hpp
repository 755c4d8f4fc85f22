// SPDX-License-Identifier: MIT
/// @file
/// @brief The one file-extension helper every table (readers, TIN, grid and contour writers) uses.
#pragma once

#include <filesystem>
#include <string>

namespace dtm::io {

/// The extension of @p path in lower case, without the dot ("Plan.PLT" -> "plt"); empty if none.
[[nodiscard]] std::string lower_extension(const std::filesystem::path& path);

}  // namespace dtm::io
