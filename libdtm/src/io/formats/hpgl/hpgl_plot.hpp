// SPDX-License-Identifier: MIT
/// @file
/// @brief What an HP-GL plot draws, in plotter units (40 per millimetre, the logical plotter
/// frame after IP/SC scaling): pen-down polylines, labels and point markers. Produced by the
/// plotter state machine (hpgl_plot.cpp), consumed by the spot-height matcher.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"

namespace dtm::io::hpgl {

inline constexpr double units_per_mm = 40.0;

struct PlotLine {
    int pen = 0;
    std::vector<Point2> points;  ///< consecutive duplicates removed
    std::size_t offset = 0;      ///< byte offset of the instruction that started it
};

struct PlotLabel {
    int pen = 0;
    Point2 at;  ///< pen position when LB was given
    std::string text;
    std::size_t offset = 0;
};

enum class MarkerKind { symbol, circle, cross, dot, pen_vertex };

struct PlotMarker {
    Point2 at;
    MarkerKind kind = MarkerKind::symbol;
    int pen = 0;
    std::size_t offset = 0;
};

struct Plot {
    std::vector<PlotLine> lines;  ///< single-vertex lines are pen-down dots
    std::vector<PlotLabel> labels;
    std::vector<PlotMarker> markers;  ///< SM symbols and small CI circles (crosses come later)
    std::size_t instructions = 0;
    std::size_t unknown_instructions = 0;
    std::string unknown_names;  ///< first few unknown mnemonics, space separated
    std::vector<std::string> warnings;
    std::size_t problems = 0;  ///< corrupt places skipped (lenient mode only)
};

struct PlotOptions {
    double circle_marker_radius = 3.0 * units_per_mm;  ///< larger CI circles are not markers
    bool strict = true;  ///< throw InputError at the first corrupt byte
};

/// Runs the whole byte stream through the tokenizer and the plotter state machine.
/// @throws InputError("<file>: byte N: ...") when strict and the data is corrupt; Cancelled.
[[nodiscard]] Plot plot_hpgl(std::string_view bytes,
                             const std::filesystem::path& file,
                             const PlotOptions& options,
                             const Progress& progress = {});

}  // namespace dtm::io::hpgl
