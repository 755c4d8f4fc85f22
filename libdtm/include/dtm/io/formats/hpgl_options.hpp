// SPDX-License-Identifier: MIT
/// @file
/// @brief Options of the HP-GL plan reader: what each pen's lines are, which labels are spot
/// heights, and how plotter units become ground coordinates.
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
    std::map<int, PenRole> pens;  ///< role of each pen's lines; pens not listed: ignore
    /// Pens whose integer labels are heights too (decimal labels such as 312.45 or 312,45 are
    /// heights on every pen).
    std::vector<int> height_pens;
    /// Search radius in paper millimetres from a height label to its marker, and from a line
    /// vertex to a spot height.
    double marker_radius_mm = 3.0;
    double scale = 0.0;                     ///< plan scale denominator (500 for 1:500); 0 = not set
    double origin_e = 0.0, origin_n = 0.0;  ///< ground E, N of plotter 0,0 (with scale)
    /// Counter-clockwise angle in degrees of the plan's x axis from grid east (with scale).
    double rotation_deg = 0.0;
    /// CSV of control points px,py,E,N (px, py in plotter units): 2 give a similarity, 3 or more
    /// a least-squares affine transform; an alternative to scale.
    std::string control_file;
};

/// Name of a role in messages: points, breakline, soft-breakline, boundary, hole, ignore.
[[nodiscard]] std::string_view pen_role_name(PenRole role) noexcept;

}  // namespace dtm::io
