// SPDX-License-Identifier: MIT
#include "dtm/io/extension.hpp"

#include <algorithm>
#include <cctype>

namespace dtm::io {

std::string lower_extension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    if (!extension.empty()) extension.erase(0, 1);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace dtm::io
