// SPDX-License-Identifier: MIT
/// @file
/// @brief The --hpgl-* options of every subcommand that reads terrain.
#pragma once

#include <CLI/CLI.hpp>

#include "dtm/io/formats/hpgl_options.hpp"

namespace dtm::cli {

/// Declares --hpgl-pens, --hpgl-height-pens, --hpgl-marker-radius, --hpgl-scale, --hpgl-origin,
/// --hpgl-rotation and --hpgl-control on @p app, filling @p options while parsing.
void add_hpgl_options(CLI::App& app, io::HpglOptions& options);

}  // namespace dtm::cli
