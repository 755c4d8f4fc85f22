// SPDX-License-Identifier: MIT
/// @file
/// @brief --contours-fix-flats, shared by the subcommands that triangulate (tin, grid, contour,
/// build), and the triangulation of the loaded inputs with or without it.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>

#include "dtm/algo/contour_flats.hpp"
#include "dtm/io/inputs.hpp"
#include "input_args.hpp"

namespace dtm::cli {

struct ContourFlatsArgs {
    int fix = -1;  ///< 1 on, 0 off, -1 auto: on for contour input (--z-field and lines)
};

/// Declares --contours-fix-flats / --no-contours-fix-flats on @p app.
void add_contour_flats_options(CLI::App& app, ContourFlatsArgs& args);

struct TerrainTin {
    TriangulateResult result;
    std::optional<ContourFlatsReport> flats;  ///< set when the flats were removed
    std::size_t survey_points = 0;            ///< survey points given (the added ones excluded)
    /// The lines are contours (heights from --z-field): a smooth surface should not crease
    /// along them.
    bool contour_input = false;
    /// The input as triangulated (with the added points), when keep_input was asked for.
    TerrainInput input;
};

/// Triangulates @p inputs.terrain (consumed): with the contour flats removed when asked, or by
/// default when the lines carry their heights from --z-field. @p quiet silences the summary
/// line on stderr; @p keep_input keeps the input (for checks) in the result.
[[nodiscard]] TerrainTin triangulate_terrain(io::LoadedInputs& inputs,
                                             const InputArgs& input_args,
                                             const TriangulateOptions& options,
                                             const ContourFlatsArgs& flats,
                                             const Progress& progress,
                                             const char* command,
                                             bool quiet,
                                             bool keep_input = false);

}  // namespace dtm::cli
