// SPDX-License-Identifier: MIT
/// @file
/// @brief Input options shared by every subcommand that reads terrain (tin, info, grid, contour,
/// build), so all of them take every input kind the same way.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "dtm/algo/dem_reduce.hpp"
#include "dtm/io/inputs.hpp"

namespace dtm::cli {

struct InputArgs {
    std::vector<std::string> inputs;  ///< positional INPUTS...
    std::vector<std::string> breaklines;
    std::vector<std::string> soft_breaklines;
    std::vector<std::string> boundaries;
    std::vector<std::string> holes;
    std::vector<std::string> flat_areas;  ///< real flats (lakes): hard breaklines, loaded last
    io::ReadOptions read;                 ///< what the readers take
    io::CrsOptions crs;
    DemReduceOptions dem;  ///< --dem-clip-radius, --dem-max-error (add_dem_options)
};

/// Declares the positional INPUTS and the reader options on @p app.
void add_input_options(CLI::App& app, InputArgs& args);

/// Declares the reader options alone (--crs, --target-crs, --columns, --layer, --where,
/// --z-field, --skip-bad-lines, --retriangulate, --surface, HP-GL options), for commands whose
/// files are declared otherwise.
void add_reader_options(CLI::App& app, io::ReadOptions& read, io::CrsOptions& crs);

/// Declares a second surface's files: --NAME FILE... (points, lines or a dtm .ply TIN) and
/// --NAME-breaklines, --NAME-soft-breaklines, --NAME-boundary, --NAME-holes. The reader options
/// (--crs, --columns, --layer, ...) are the command's.
void add_surface_options(CLI::App& app, const std::string& name, InputArgs& args);

/// The LoadOptions for io::load_inputs and products::build (the --flat-areas files come last,
/// as breaklines).
[[nodiscard]] io::LoadOptions to_load_options(const InputArgs& args);

}  // namespace dtm::cli
