// SPDX-License-Identifier: MIT
/// @file
/// @brief Options of the HPGL plan reader (pen roles, spot heights, georeferencing), and the
/// parsers of their command-line spellings (shared by the CLI and the tests).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace dtm::io {

/// What lines drawn with a pen become.
/// points: every vertex drawn with the pen is a point marker (a spot height's label snaps to it).
enum class PenRole { points, breakline, soft_breakline, boundary, hole, ignore };

struct HpglOptions {
    std::map<int, PenRole> pens;  ///< --hpgl-pens 2=breakline,3=boundary,...; unnamed pens: ignore
    /// --hpgl-height-pens 5,6: pens whose integer labels are heights too (decimal labels such as
    /// 312.45 or 312,45 are heights on every pen).
    std::vector<int> height_pens;
    double marker_radius_mm = 3.0;          ///< --hpgl-marker-radius (millimetres on paper)
    double scale = 0.0;                     ///< --hpgl-scale (500 for 1:500); 0 = not set
    double origin_e = 0.0, origin_n = 0.0;  ///< --hpgl-origin E,N: ground of plotter 0,0
    double rotation_deg = 0.0;  ///< --hpgl-rotation: counter-clockwise angle of the plan's x axis from east
    std::string control_file;   ///< --hpgl-control FILE (CSV px,py,E,N; px,py in plotter units)
};

/// Parses "2=breakline,3=boundary,4=hole,1=ignore". Role names: points, breakline,
/// soft-breakline (or soft_breakline, soft), boundary, hole, ignore.
/// @throws UsageError naming the offending item.
[[nodiscard]] std::map<int, PenRole> parse_pen_roles(std::string_view text);
/// Parses a pen list "5,6". @throws UsageError.
[[nodiscard]] std::vector<int> parse_pen_list(std::string_view text);
/// Name of a role as parse_pen_roles spells it.
[[nodiscard]] std::string_view pen_role_name(PenRole role) noexcept;

}  // namespace dtm::io
