// SPDX-License-Identifier: MIT
/// @file
/// @brief `dtm check`: a surface against control points: residuals.csv (every point, the ones
/// outside the surface listed with status "outside") and the statistics (JSON).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "dtm/algo/check_points.hpp"
#include "dtm/algo/interpolation.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/products/surface_input.hpp"

namespace dtm::products {

struct CheckJob {
    SurfaceSource surface;
    std::filesystem::path points;
    io::LoadOptions point_reader;
    Interpolation interpolation = Interpolation::linear;  ///< the surface between the vertices
    std::filesystem::path stats;                          ///< optional JSON file of the statistics
};

struct CheckReport {
    CheckStatistics stats;
    std::string max_abs_id;                ///< id of the point with the largest |residual|
    std::vector<std::string> outside_ids;  ///< points outside the surface
};

/// The heights of @p tin under @p interpolant (prepared for it): LinearSurface or
/// InterpolatedSurface. Both must outlive the result.
[[nodiscard]] std::unique_ptr<SurfaceHeight> make_surface_height(const Tin& tin,
                                                                 const TinInterpolant& interpolant);

/// Writes @p csv (id,x,y,z,surface_z,residual,status) atomically, and job.stats if set.
CheckReport run_check(const CheckJob& job,
                      const std::filesystem::path& csv,
                      const Progress& progress = {});

/// The statistics as JSON text.
[[nodiscard]] std::string check_json(const CheckReport& report);

}  // namespace dtm::products
