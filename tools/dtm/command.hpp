// SPDX-License-Identifier: MIT
/// @file
/// @brief The subcommand table of the `dtm` binary: each subcommand lives in its own cmd_*.cpp and
/// is thin (parse -> options -> library call -> report).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string_view>

namespace dtm::cli {

/// One subcommand. `setup` declares its options on the CLI11 subcommand and returns the function
/// that runs it once parsing succeeded; the function returns the process exit code.
struct Command {
    std::string_view name;
    std::string_view summary;
    std::function<std::function<int()>(CLI::App& sub)> setup;
};

Command tin_command();
Command info_command();
Command grid_command();
Command contour_command();
Command build_command();
Command methods_command();
Command voronoi_command();
Command map_command();
Command volume_command();
Command profile_command();
Command check_command();
Command sections_command();

}  // namespace dtm::cli
