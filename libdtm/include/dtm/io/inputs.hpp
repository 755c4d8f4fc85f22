// SPDX-License-Identifier: MIT
/// @file
/// @brief Loading every input a subcommand names (points, breaklines, boundaries, holes, TINs) into
/// one TerrainInput in one planar CRS, with a summary of what each reader found.
/// The readers themselves sit behind the registry in src/io/reader.cpp.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/formats/hpgl_options.hpp"

namespace dtm::io {

/// Which role an input file plays.
enum class InputRole { points, breaklines, soft_breaklines, boundary, holes };

struct InputFile {
    std::filesystem::path path;
    InputRole role = InputRole::points;
};

/// Reader options shared by every subcommand (filled by tools/dtm/input_args.cpp).
struct LoadOptions {
    std::vector<InputFile> files;
    std::string crs;         ///< --crs: CRS of inputs that carry none (EPSG:xxxx, WKT, PROJ)
    std::string target_crs;  ///< --target-crs: reproject everything into this CRS
    bool skip_bad_lines = false;  ///< --skip-bad-lines: count bad text lines instead of failing
    /// --columns: names of the text columns in order ("id,y,x,z,code"; "-" skips a column).
    /// Empty: map by header names, or guess (x,y,z) when there is no header.
    std::string columns;
    std::string layer;    ///< --layer: OGR layer name; empty = every layer
    std::string where;    ///< --where: OGR attribute filter (SQL WHERE clause)
    std::string z_field;  ///< --z-field: OGR attribute holding the height (points, contours)
    HpglOptions hpgl;  ///< options of the HPGL plan reader
};

/// What one input file held (the fields of `dtm info`).
struct InputSummary {
    std::filesystem::path path;
    std::string format;
    std::string crs;  ///< name or EPSG code as found, empty if none
    std::size_t points = 0;
    std::size_t breaklines = 0;
    std::size_t breakline_vertices = 0;
    std::size_t boundaries = 0;
    std::size_t holes = 0;
    std::array<double, 4> bbox{};     ///< xmin, ymin, xmax, ymax
    std::array<double, 2> z_range{};  ///< zmin, zmax
    std::size_t duplicates = 0;
    std::size_t skipped_lines = 0;
    std::vector<std::string> warnings;
};

/// Identifiers and codes of survey points, parallel to TerrainInput::points (empty strings
/// where a reader had none; both vectors empty when no input carried any).
struct PointLabels {
    std::vector<std::string> ids;
    std::vector<std::string> codes;
};

struct LoadedInputs {
    TerrainInput terrain;
    PointLabels labels;          ///< point ids and codes (text point lists)
    std::string crs_wkt;         ///< CRS of terrain (after any projection); empty if unknown
    std::optional<Tin> tin;      ///< set when the (single) input is a dtm PLY TIN
    std::vector<InputSummary> summaries;
    std::size_t skipped_lines = 0;
};

/// @throws InputError (file, line, column, what was expected); Cancelled.
[[nodiscard]] LoadedInputs load_inputs(const LoadOptions& options, const Progress& progress = {});

}  // namespace dtm::io
