// SPDX-License-Identifier: MIT
/// @file
/// @brief The --hpgl-* options of every subcommand that reads terrain.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string_view>
#include <vector>

#include "dtm/io/formats/hpgl_options.hpp"

namespace dtm::cli {

/// Parses --hpgl-pens "2=breakline,3=boundary,4=hole,1=ignore". Role names: points, breakline,
/// soft-breakline (or soft_breakline, soft), boundary, hole, ignore.
/// @throws UsageError naming --hpgl-pens and the offending item.
[[nodiscard]] std::map<int, io::PenRole> parse_pen_roles(std::string_view text);
/// Parses --hpgl-height-pens "5,6". @throws UsageError.
[[nodiscard]] std::vector<int> parse_pen_list(std::string_view text);

/// Declares --hpgl-pens, --hpgl-height-pens, --hpgl-marker-radius, --hpgl-scale, --hpgl-origin,
/// --hpgl-rotation and --hpgl-control on @p app, filling @p options while parsing.
void add_hpgl_options(CLI::App& app, io::HpglOptions& options);

}  // namespace dtm::cli
