// SPDX-License-Identifier: MIT
/// @file
/// @brief The surface every product is derived from: the input TIN as it is, or the
/// constrained Delaunay triangulation of the loaded terrain. The one place that decides which,
/// for `dtm build` and every subcommand that reads terrain (tin, grid, contour).
#pragma once

#include <cstddef>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/io/inputs.hpp"

namespace dtm::products {

struct Surface {
    /// The TIN with what the triangulation did (stats, merges, conflicts, input_to_vertex); for a
    /// TIN input: that TIN, points_in = its vertices, input_to_vertex the identity.
    TriangulateResult result;
    std::size_t survey_points = 0;  ///< survey points given to the triangulator (accounting)
    bool from_tin = false;          ///< the input was a TIN, used as it is
};

/// The surface of @p inputs: inputs.tin if a reader returned one (it is moved out), else the
/// triangulation of inputs.terrain with @p options (the terrain is consumed: its memory goes as
/// soon as the vertices are merged). When boundary or hole vertices took the height of the
/// surface, the summaries of the inputs with rings say so.
/// @throws InputError (from triangulate); Cancelled.
[[nodiscard]] Surface surface(io::LoadedInputs& inputs, const TriangulateOptions& options,
                              const Progress& progress = {});

}  // namespace dtm::products
