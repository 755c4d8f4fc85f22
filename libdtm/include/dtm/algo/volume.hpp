// SPDX-License-Identifier: MIT
/// @file
/// @brief Exact volumes between two piecewise-linear surfaces (two TINs, or a TIN and a level
/// plane): cut, fill, their areas in plan and on each surface, and the areas where only one
/// surface exists.
///
/// Conventions (those of Civil 3D's volume surfaces and of the Czech OBJEM programs): the top
/// surface is the one compared (design, later survey, stockpile), the base is the reference
/// (existing ground, earlier survey, the pile's floor). Fill is where the top lies above the base
/// (material added), cut where it lies below (material removed); net = fill - cut.
#pragma once

#include <cstddef>

#include "dtm/algo/overlay.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct VolumeOptions {
    unsigned threads = 0;  ///< worker threads (0: all cores); never changes the result
};

struct VolumeResult {
    double fill = 0.0;  ///< volume where top > base (CRS units cubed)
    double cut = 0.0;   ///< volume where top < base (positive number)
    [[nodiscard]] double net() const noexcept { return fill - cut; }

    double fill_area = 0.0;          ///< plan area where top > base
    double cut_area = 0.0;           ///< plan area where top < base
    double unchanged_area = 0.0;     ///< plan area where top == base (identical surfaces)
    double overlap_area = 0.0;       ///< plan area where both exist (fill + cut + unchanged)
    double fill_area_top_3d = 0.0;   ///< 3-D area of the top surface over the fill area
    double fill_area_base_3d = 0.0;  ///< 3-D area of the base surface under the fill area
    double cut_area_top_3d = 0.0;
    double cut_area_base_3d = 0.0;

    double top_area = 0.0;        ///< plan area of the top TIN
    double base_area = 0.0;       ///< plan area of the base TIN (0 for a plane: unbounded)
    double top_only_area = 0.0;   ///< top exists, base does not (volume not counted there)
    double base_only_area = 0.0;  ///< base exists, top does not (0 for a plane)
    bool base_is_plane = false;

    double max_fill = 0.0;  ///< largest top - base at a piece corner (0 if there is no fill)
    Point2 max_fill_at{};
    double max_cut = 0.0;  ///< largest base - top at a piece corner (0 if there is no cut)
    Point2 max_cut_at{};
    std::size_t pieces = 0;  ///< overlay pieces integrated
};

/// Volume between @p top and @p base. Exact up to the rounding of the computed crossing points
/// and of the sums (compensated): every piece of the overlay is a convex polygon over which
/// top - base is linear; it is split at the zero line and integrated in closed form.
/// @throws Cancelled
[[nodiscard]] VolumeResult volume(const Tin& top,
                                  const Tin& base,
                                  const VolumeOptions& options = {},
                                  const Progress& progress = {});
/// Volume between @p top and the level plane z = @p base_z.
[[nodiscard]] VolumeResult volume(const Tin& top,
                                  double base_z,
                                  const VolumeOptions& options = {},
                                  const Progress& progress = {});
/// The part of a surface's plan area @p whole outside the overlap: the difference of compensated
/// sums of the same pieces, exact up to a few ulps, so a difference within 1e-12 of @p whole is
/// 0 (a surface that lies wholly inside the other has no "only" area).
[[nodiscard]] double only_area(double whole, double overlap);
/// Volume over the pieces of a prepared overlay (both overloads above end here).
[[nodiscard]] VolumeResult volume(const TinOverlay& overlay,
                                  const Tin& top,
                                  const Tin* base,
                                  const Progress& progress = {});

}  // namespace dtm
