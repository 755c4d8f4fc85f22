// SPDX-License-Identifier: MIT
/// @file
/// @brief Surfaces that volume jobs derive from a TIN: the TIN clipped to a polygon (volumes
/// "within" a site or a stockpile outline), and the base a stockpile stands on, spanned by the
/// pile's outer boundary.
#pragma once

#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// The part of @p tin inside @p area (its boundaries, minus its holes; closed rings in the TIN's
/// CRS), as a TIN of its own: the overlay of @p tin with a triangulation of @p area, so the
/// clipped surface has the same heights everywhere and new vertices where the polygon's edges
/// cross the TIN's (heights interpolated along the TIN's edges).
/// @throws InputError when @p area has no boundary or cannot be triangulated; Cancelled
[[nodiscard]] Tin clip_tin(const Tin& tin, const TerrainInput& area, const Progress& progress = {});

/// The floor of a stockpile: the constrained Delaunay triangulation of the outer border rings of
/// @p pile (vertices with the pile's heights), i.e. the surface spanned by the pile's foot. Holes
/// of the pile are spanned over (the pile is absent there, the base is not).
/// @throws InputError when @p pile has no triangle
[[nodiscard]] Tin spanned_base(const Tin& pile, const Progress& progress = {});

}  // namespace dtm
