// SPDX-License-Identifier: MIT
/// @file
/// @brief [pseudo] Pseudo-triangulation by incremental insertion with the generalized flip
/// (thesis 001: Hobza 2010 after Trcka 2007), and the checks and angle statistics of its faces.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "dtm/methods/method.hpp"

namespace dtm::methods {

[[nodiscard]] MethodResult run_pseudo(const MethodInput& input,
                                      const MethodOptions& options,
                                      const Progress& progress);

/// Problems of @p faces as a pseudo-triangulation of @p points (empty: valid): every face a
/// counter-clockwise simple polygon with exactly three convex corners; every edge in one face
/// (hull) or two (opposite directions); the boundary edges forming the convex hull; the faces'
/// area the hull's; every point a vertex; no two edges crossing. At most @p limit are listed.
[[nodiscard]] std::vector<std::string> check_pseudo_triangulation(std::span<const Point3> points,
                                                                  const PolygonFaces& faces,
                                                                  std::size_t limit = 10);

/// The angle tool (thesis 001 §4.2, Tools > angle measurement): per face the smallest and the
/// largest corner angle in degrees; their means; histograms in 5-degree bins (0-180).
struct PseudoAngleStats {
    std::vector<double> min_angle;  ///< per face
    std::vector<double> max_angle;
    double mean_min = 0.0;
    double mean_max = 0.0;
    std::vector<std::size_t> min_histogram;  ///< 36 bins of 5 degrees
    std::vector<std::size_t> max_histogram;
};
[[nodiscard]] PseudoAngleStats pseudo_angle_stats(std::span<const Point3> points,
                                                  const PolygonFaces& faces);

}  // namespace dtm::methods
