// SPDX-License-Identifier: MIT
/// @file
/// @brief --contours-fix-flats / --no-contours-fix-flats, shared by the subcommands that
/// triangulate (tin, grid, contour, build), and the products::SurfaceOptions they make.
#pragma once

#include <CLI/CLI.hpp>

#include "dtm/products/surface.hpp"
#include "input_args.hpp"

namespace dtm::cli {

/// Declares --contours-fix-flats / --no-contours-fix-flats on @p app.
void add_contour_flats_options(CLI::App& app, products::ContourFlats& mode);

/// The surface options of a subcommand: the lines are contours when their heights come from
/// --z-field; the --flat-areas files outline real flats.
[[nodiscard]] products::SurfaceOptions surface_options(const InputArgs& input,
                                                       const TriangulateOptions& triangulate,
                                                       products::ContourFlats mode);

/// The contour-flats summary on stderr (flat triangles before and after, estimated summits).
void print_contour_flats(const ContourFlatsReport& report, const char* command);

}  // namespace dtm::cli
