// SPDX-License-Identifier: MIT
/// @file
/// @brief Drawing a section (long profile or cross-section) into a rectangle of a Canvas: height
/// against chainage at a vertical exaggeration, one colour per surface, gaps where a surface is
/// absent, station labels. A map sheet can place it anywhere on its page.
#pragma once

#include <string>
#include <vector>

#include "dtm/algo/profile.hpp"
#include "dtm/io/draw/canvas.hpp"

namespace dtm::products {

struct ProfilePlot {
    std::string title;
    std::vector<std::string> names;  ///< one per profile (the legend)
    std::vector<Profile> profiles;   ///< one per surface, same line
    double exaggeration = 10.0;      ///< vertical scale / horizontal scale
    double station_interval = 0.0;   ///< labelled stations every this (0: about 8 along the line)
    double chainage_offset = 0.0;    ///< added to chainages in labels (cross-sections: -W/2)
    std::string x_label = "chainage [m]";
};

/// The colour of surface @p i in plots (a fixed, colour-blind-safe cycle).
[[nodiscard]] io::draw::Color surface_color(std::size_t i);

/// Draws @p plot into the rectangle at @p top_left, @p width x @p height mm. The scales keep the
/// exaggeration: the drawing shrinks to fit the longer of the two extents.
/// @throws UsageError when no profile has a point.
void draw_profile(io::draw::Canvas& canvas,
                  const ProfilePlot& plot,
                  Point2 top_left,
                  double width,
                  double height);

/// "0+120.00" for 120 m (kilometre + metres, the station notation of road design).
[[nodiscard]] std::string station_label(double chainage);

}  // namespace dtm::products
