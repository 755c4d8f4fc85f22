// SPDX-License-Identifier: MIT
#include "dtm/core/error.hpp"

#include <utility>

namespace dtm {
namespace {
std::string located(const std::filesystem::path& file,
                    std::size_t line,
                    std::size_t column,
                    const std::string& what) {
    std::string text = file.string();
    if (line > 0) text += ":" + std::to_string(line);
    if (column > 0) text += ":" + std::to_string(column);
    return text.empty() ? what : text + ": " + what;
}
}  // namespace

InputError::InputError(std::filesystem::path file,
                       std::size_t line,
                       std::size_t column,
                       const std::string& what)
    : Error(located(file, line, column, what)),
      file_(std::move(file)),
      line_(line),
      column_(column) {}

InputError::InputError(const std::string& what) : Error(what) {}

OptionError::OptionError(std::string field, const std::string& what)
    : UsageError(what), field_(std::move(field)) {}

}  // namespace dtm
