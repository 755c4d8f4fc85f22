// SPDX-License-Identifier: MIT
/// @file
/// @brief Options of the HPGL plan reader (pen roles, spot heights, georeferencing).
#pragma once

#include <map>
#include <optional>
#include <string>

namespace dtm::io {

/// What lines drawn with a pen become.
enum class PenRole { points, breakline, soft_breakline, boundary, hole, ignore };

struct HpglOptions {
    std::map<int, PenRole> pens;                 ///< --hpgl-pens 2=breakline,3=boundary,...
    std::optional<std::map<int, bool>> height_pens;  ///< --hpgl-height-pens: pens whose integer labels are heights
    double marker_radius_mm = 3.0;               ///< --hpgl-marker-radius (on paper)
    double scale = 0.0;                          ///< --hpgl-scale (500 for 1:500); 0 = not set
    double origin_e = 0.0, origin_n = 0.0;       ///< --hpgl-origin E,N: ground of plotter 0,0
    double rotation_deg = 0.0;                   ///< --hpgl-rotation
    std::string control_file;                    ///< --hpgl-control FILE (px,py,E,N)
};

}  // namespace dtm::io
