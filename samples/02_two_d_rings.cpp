// SPDX-License-Identifier: MIT
// Sample 2: the core library alone (dtm_core). A boundary and a building footprint given in
// 2-D only (no heights, as drawn on a plan): triangulate() gives their vertices the height of
// the surface of the survey points, cuts the TIN at the boundary and leaves the building out,
// exactly as `dtm tin --boundary ... --holes ...` does.
//
//   sample_02_two_d_rings
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>

#include "dtm/algo/surface_stats.hpp"
#include "dtm/algo/triangulate.hpp"

namespace {

dtm::Polyline ring(std::initializer_list<dtm::Point2> corners) {
    dtm::Polyline line;
    for (const dtm::Point2& p : corners) {
        line.points.push_back({p.x, p.y, std::numeric_limits<double>::quiet_NaN()});  // 2-D
    }
    line.closed = true;
    return line;
}

}  // namespace

int main() {
    try {
        dtm::TerrainInput input;
        for (int j = 0; j <= 30; ++j) {  // a gentle dome, a point every 4 m
            for (int i = 0; i <= 30; ++i) {
                const double x = 4.0 * i + 0.5 * std::cos(j);
                const double y = 4.0 * j;
                input.points.push_back(
                    {x, y,
                     250.0 +
                         6.0 * std::exp(-((x - 60) * (x - 60) + (y - 60) * (y - 60)) / 2000.0)});
            }
        }
        input.boundaries.push_back(ring({{8, 6}, {112, 10}, {110, 114}, {5, 108}}));
        input.holes.push_back(ring({{50, 50}, {70, 50}, {70, 64}, {50, 64}}));

        const dtm::TriangulateResult result = dtm::triangulate(input);
        const dtm::SurfaceStats stats = dtm::surface_stats(result.tin);
        std::printf("%zu ring vertices took the height of the surface\n",
                    result.line_heights.from_surface);
        std::printf(
            "%zu triangles inside the boundary and outside the building: %.1f m2 "
            "(%zu removed)\n",
            stats.triangle_count, stats.planimetric_area, result.stats.removed_triangles);
        // the area is the boundary polygon's minus the building's, exactly: the rings are edges
        const double expected = 10776.0 - 280.0;
        std::printf("expected %.1f m2: %s\n", expected,
                    std::abs(stats.planimetric_area - expected) < 1e-6 ? "yes" : "NO");
        return std::abs(stats.planimetric_area - expected) < 1e-6 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sample_02: %s\n", e.what());
        return 1;
    }
}
