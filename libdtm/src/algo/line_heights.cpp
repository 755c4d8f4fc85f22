// SPDX-License-Identifier: MIT
// Heights of 2-D line vertices. A vertex that coincides with a survey point takes its z (found by
// a hash of the exact x, y); a hard breakline vertex left without is an error, since a breakline
// is a statement about the terrain's height; boundary and hole vertices left without take the
// height of the surface of the points and hard breaklines (their constrained Delaunay TIN,
// sampled by SurfaceSampler: linear inside, nearest vertex beyond the hull); soft breakline
// vertices are left to triangulate(), which interpolates them on the surface of everything else.
#include "dtm/algo/line_heights.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <unordered_map>

#include "dtm/algo/surface_sampler.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"

namespace dtm {
namespace {

struct XyHash {
    std::size_t operator()(const Point2& p) const noexcept {
        const std::size_t a = std::hash<double>{}(p.x);
        return a ^ (std::hash<double>{}(p.y) + 0x9e3779b97f4a7c15ULL + (a << 6) + (a >> 2));
    }
};

bool lacks_height(const std::vector<Polyline>& lines) {
    return std::any_of(lines.begin(), lines.end(), [](const Polyline& l) {
        return std::any_of(l.points.begin(), l.points.end(),
                           [](const Point3& p) { return std::isnan(p.z); });
    });
}

/// Step 1 with the heights of the input's own points.
std::size_t heights_from_points(TerrainInput& t) {
    std::unordered_map<Point2, double, XyHash> z_at;
    z_at.reserve(t.points.size());
    for (const Point3& p : t.points) z_at.emplace(p.xy(), p.z);
    return heights_from_survey_points(t, [&](const Point2& p) -> std::optional<double> {
        const auto it = z_at.find(p);
        if (it == z_at.end()) return std::nullopt;
        return it->second;
    });
}

/// Step 2: boundary and hole vertices from the surface of the points and hard breaklines.
std::size_t rings_from_surface(TerrainInput& t,
                               const LineHeightOptions& options,
                               const Progress& progress) {
    std::size_t missing = 0;
    for (const auto* rings : {&t.boundaries, &t.holes}) {
        for (const Polyline& l : *rings) {
            missing += static_cast<std::size_t>(std::count_if(
                l.points.begin(), l.points.end(), [](const Point3& p) { return std::isnan(p.z); }));
        }
    }
    if (missing == 0) return 0;
    TerrainInput surface;
    surface.points = t.points;
    surface.breaklines = t.breaklines;
    if (surface.points.size() < 3) {
        throw InputError(
            "boundary/hole vertices have no heights and there are fewer than 3 "
            "survey points to take them from");
    }
    TriangulateOptions triangulation;
    triangulation.threads = options.threads;
    triangulation.tiles = options.tiles;
    const Tin tin = triangulate(std::move(surface), triangulation, progress).tin;
    const SurfaceSampler sampler(tin);
    SurfaceSampler::Cursor cursor;
    for (auto* rings : {&t.boundaries, &t.holes}) {
        for (Polyline& l : *rings) {
            for (Point3& p : l.points) {
                if (std::isnan(p.z)) p.z = sampler.height_or_nearest(p.xy(), cursor);
            }
        }
    }
    return missing;
}

}  // namespace

std::size_t heights_from_survey_points(TerrainInput& t, const SurveyHeightAt& height_at) {
    std::size_t filled = 0;
    const auto fill = [&](std::vector<Polyline>& lines, const char* kind, bool required) {
        for (Polyline& l : lines) {
            for (Point3& p : l.points) {
                if (!std::isnan(p.z)) continue;
                if (const std::optional<double> z = height_at(p.xy())) {
                    p.z = *z;
                    ++filled;
                } else if (required) {
                    throw InputError(l.source + ": " + kind + " vertex (" + std::to_string(p.x) +
                                     ", " + std::to_string(p.y) +
                                     ") has no height: expected a z column/geometry z, `z_field`, "
                                     "or a survey point at that position (2-D lines: use "
                                     "`soft_breaklines`)");
                }
            }
        }
    };
    fill(t.breaklines, "breakline", true);
    fill(t.boundaries, "boundary", false);
    fill(t.holes, "hole", false);
    fill(t.soft_breaklines, "soft breakline", false);
    return filled;
}

LineHeightReport resolve_line_heights(TerrainInput& input,
                                      const LineHeightOptions& options,
                                      const Progress& progress) {
    LineHeightReport report;
    if (!lacks_height(input.breaklines) && !lacks_height(input.boundaries) &&
        !lacks_height(input.holes) && !lacks_height(input.soft_breaklines)) {
        return report;
    }
    report.from_points = heights_from_points(input);
    report.from_surface = rings_from_surface(input, options, progress);
    return report;
}

}  // namespace dtm
