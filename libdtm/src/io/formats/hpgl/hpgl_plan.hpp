// SPDX-License-Identifier: MIT
/// @file
/// @brief Turns a Plot into terrain, still in plotter units: spot heights (numeric labels
/// snapped to the nearest point marker) and lines by pen role with heights taken from the spot
/// heights on their vertices.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/io/formats/hpgl_options.hpp"
#include "io/formats/hpgl/hpgl_plot.hpp"

namespace dtm::io::hpgl {

struct SpotHeight {
    Point2 at;  ///< the marker's position, or the label's when no marker was in reach
    double z = 0.0;
    std::size_t label = 0;  ///< index into Plot::labels
    bool on_marker = false;
};

struct RoleLine {
    PenRole role = PenRole::ignore;  ///< breakline, soft_breakline, boundary or hole
    int pen = 0;
    std::vector<Point3> points;  ///< x, y in plotter units; closed rings do not repeat the start
    bool closed = false;
    std::size_t offset = 0;
    std::size_t height_vertices = 0;  ///< vertices that took a spot height
};

struct TerrainPlan {
    std::vector<SpotHeight> spots;
    std::vector<RoleLine> lines;
    std::size_t crosses = 0;  ///< crosses found (their strokes are not lines)
    std::size_t markers = 0;  ///< every marker considered
    std::size_t height_labels = 0;
    std::size_t labels_without_marker = 0;
    std::size_t ignored_lines = 0;  ///< lines on pens without a role (or role ignore)
    std::vector<std::string> warnings;
};

/// The height a label states: "312.45", "312,45", "-3.5" (and "312" when @p allow_integer);
/// nullopt for any other text. Surrounding blanks and line ends are ignored.
[[nodiscard]] std::optional<double> parse_height_label(std::string_view text, bool allow_integer);

/// Finds crosses, matches height labels to markers and gives lines their heights.
/// Lines that are consumed as crosses are removed from @p plot.
[[nodiscard]] TerrainPlan build_terrain_plan(Plot& plot, const HpglOptions& options);

}  // namespace dtm::io::hpgl
