// SPDX-License-Identifier: MIT
/// @file
/// @brief The survey of the sample site: what a field crew would bring back from the analytic
/// terrain of sample_terrain.hpp (points, breaklines, boundary, building, check points).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sample_terrain.hpp"

namespace dtm::sample {

struct SurveyPoint {
    std::string id;
    double e = 0.0;
    double n = 0.0;
    double z = 0.0;
};

struct Line {
    std::string kind;
    std::vector<SurveyPoint> vertices;  ///< closed rings repeat the first vertex
};

struct Survey {
    std::vector<SurveyPoint> points;     ///< spot heights, including the extras below
    std::size_t outside_points = 0;      ///< spot heights measured beyond the boundary
    std::size_t repeated_points = 0;     ///< spot heights measured twice at the same place
    std::vector<std::string> bad_lines;  ///< corrupt records added to the CSV
    std::vector<Line> breaklines;
    Line boundary;
    Line building;
    std::vector<SurveyPoint> check_points;  ///< true z at random places on the surface
};

struct SurveyOptions {
    double spacing = 3.5;  ///< spacing of the jittered grid of spot heights (m)
    std::size_t check_points = 200;
    std::uint64_t seed = 5514;
};

/// Builds the survey. Deterministic for given options (own PRNG, no std distributions).
[[nodiscard]] Survey make_survey(const SurveyOptions& options = {});

/// The same survey before the road was built: every point, breakline, boundary and building
/// vertex at the same place with the natural ground's height (natural_z, to the millimetre).
/// Triangulated with the same lines it gives the same triangles as the built survey, so the road's
/// cut and fill between the two TINs has an independent closed form triangle by triangle.
[[nodiscard]] Survey natural_survey(const Survey& built);

}  // namespace dtm::sample
