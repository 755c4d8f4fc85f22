// SPDX-License-Identifier: MIT
/// @file
/// @brief Triangulation options shared by tin, grid, contour and build.
#pragma once

#include <CLI/CLI.hpp>

#include "dtm/algo/triangulate.hpp"

namespace dtm::cli {

/// Declares --snap, --duplicates, --max-edge, --z-tolerance, --threads, --optimize, --tiles on
/// @p app.
void add_tin_options(CLI::App& app, TriangulateOptions& options);

}  // namespace dtm::cli
