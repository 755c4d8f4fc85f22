// SPDX-License-Identifier: MIT
/// @file
/// @brief The command-line spelling of the options the library names in its messages. The
/// library speaks of an option as `field` (the member of its options struct, in backquotes:
/// "`z_field`", "`hpgl.scale`"); the user of `dtm` sees "--z-field", "--hpgl-scale".
#pragma once

#include <string>
#include <string_view>

namespace dtm::cli {

/// The flag of a library option field ("z_field" -> "--z-field"); empty if there is none.
[[nodiscard]] std::string_view flag_of(std::string_view field) noexcept;

/// @p text with every `field` the table knows replaced by its flag; other text is unchanged.
[[nodiscard]] std::string cli_text(std::string_view text);

}  // namespace dtm::cli
