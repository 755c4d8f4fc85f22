// SPDX-License-Identifier: MIT
/// @file
/// @brief The surface every product is derived from: the input TIN as it is, or the
/// constrained Delaunay triangulation of the loaded terrain (with the flat triangles of a
/// contour map removed, algo/contour_flats.hpp). The one place that decides which, for
/// `dtm build` and every subcommand that reads terrain (tin, grid, contour).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

#include "dtm/algo/contour_flats.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/io/inputs.hpp"

namespace dtm::products {

/// Whether the flat triangles of a TIN of contour lines are removed (triangulate_contours).
enum class ContourFlats {
    automatic,  ///< when the lines are contours (SurfaceOptions::lines_are_contours)
    fix,
    keep,
};

struct SurfaceOptions {
    SurfaceOptions() = default;
    /// Only the triangulation options given: what a caller without contour input needs.
    SurfaceOptions(const TriangulateOptions& options) : triangulate(options) {}  // NOLINT: implicit

    TriangulateOptions triangulate;
    ContourFlats contour_flats = ContourFlats::automatic;
    /// The hard breaklines are contour lines, one height each (their heights came from
    /// ReadOptions::z_field): a smooth surface should not crease along them, and
    /// ContourFlats::automatic removes their flat triangles.
    bool lines_are_contours = false;
    /// Inputs (as in LoadOptions::files, loaded after every other breakline file) whose hard
    /// breaklines outline real flats such as lakes, kept flat when the contour flats are removed.
    std::vector<std::filesystem::path> flat_areas;
};

struct Surface {
    /// The TIN with what the triangulation did (stats, merges, conflicts, input_to_vertex); for a
    /// TIN input: that TIN, points_in = its vertices, input_to_vertex the identity.
    TriangulateResult result;
    std::size_t survey_points = 0;  ///< survey points given to the triangulator (accounting)
    bool from_tin = false;          ///< the input was a TIN, used as it is
    /// The lines are contours (see SurfaceOptions::lines_are_contours, and breaklines exist):
    /// give GradientOptions::crease_at_breaklines = !contour_input to the smooth surfaces.
    bool contour_input = false;
    /// Set when the contour flats were removed: flat triangles before and after, the points
    /// added (after the survey points in input order) and the estimated summits and pits.
    std::optional<ContourFlatsReport> contour_flats;
    std::vector<Point3> added_points;  ///< the points the flat removal added
};

/// The surface of @p inputs: inputs.tin if a reader returned one (it is moved out; optimised
/// under options.triangulate.optimize when that is not delaunay, as triangulate() does), else the
/// triangulation of inputs.terrain with @p options (the terrain is consumed: its memory goes as
/// soon as the vertices are merged). When boundary or hole vertices took the height of the
/// surface, the summaries of the inputs with rings say so.
/// @throws InputError (from triangulate); Cancelled.
[[nodiscard]] Surface surface(io::LoadedInputs& inputs,
                              const SurfaceOptions& options,
                              const Progress& progress = {});

}  // namespace dtm::products
