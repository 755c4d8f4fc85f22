// SPDX-License-Identifier: MIT
/// @file
/// @brief The surface interpolation option shared by grid, contour and build.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "dtm/algo/interpolation.hpp"

namespace dtm::cli {

/// Declares @p flag (--interpolation) taking linear, cubic or natural.
void add_interpolation_option(CLI::App& app, const std::string& flag, Interpolation& method);

}  // namespace dtm::cli
