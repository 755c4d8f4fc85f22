// SPDX-License-Identifier: MIT
/// @file
/// @brief From plotter units to ground coordinates: scale + origin + rotation, or control points
/// (2: similarity, 3 or more: least-squares affine with residuals).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/io/formats/hpgl_options.hpp"

namespace dtm::io::hpgl {

/// E = e0 + ex * px + ey * py, N = n0 + nx * px + ny * py, with px, py in plotter units.
struct Affine {
    double e0 = 0.0, ex = 1.0, ey = 0.0;
    double n0 = 0.0, nx = 0.0, ny = 1.0;
    [[nodiscard]] Point2 apply(Point2 p) const noexcept {
        return {e0 + ex * p.x + ey * p.y, n0 + nx * p.x + ny * p.y};
    }
};

struct ControlPoint {
    Point2 plotter;  ///< plotter units
    Point2 ground;
};

struct Georeference {
    Affine transform;
    std::vector<std::string> notes;  ///< what was used; residuals; "not georeferenced"
};

/// Reads a control-point CSV: "px,py,E,N" per line (',', ';', tab or blanks between values),
/// '#' comments, an optional header line. px, py are plotter units, or paper millimetres when
/// the header names them px_mm, py_mm. @throws InputError with file, line and column.
[[nodiscard]] std::vector<ControlPoint> read_control_points(const std::filesystem::path& file);

/// Least-squares fit: 2 points give the exact similarity, 3 or more an affine transform.
/// @throws InputError when the points are too few, coincide or are collinear.
[[nodiscard]] Affine fit_control_points(const std::vector<ControlPoint>& points,
                                        const std::filesystem::path& file);

/// The transform options.hpgl asks for. Without georeferencing: plotter millimetres
/// (x = px / 40, y = py / 40), with a note saying so.
/// @throws OptionError when both scale and control_file are given; InputError.
[[nodiscard]] Georeference make_georeference(const HpglOptions& options);

}  // namespace dtm::io::hpgl
