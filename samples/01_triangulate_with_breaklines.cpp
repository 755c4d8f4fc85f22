// SPDX-License-Identifier: MIT
// Sample 1: the core library alone (dtm_core: no GDAL, no files). Survey points of a small
// slope with a ditch along its foot given as a 3-D breakline -> constrained Delaunay TIN ->
// the breakline is in the TIN, checked exactly, and the surface height anywhere on it.
//
//   sample_01_triangulate_with_breaklines
#include <cmath>
#include <cstdio>
#include <exception>

#include "dtm/algo/surface_sampler.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"

int main() {
    try {
        dtm::TerrainInput input;
        for (int j = 0; j <= 20; ++j) {  // 21 x 21 spot heights, 5 m apart, rising to the north
            for (int i = 0; i <= 20; ++i) {
                const double x = 5.0 * i + 0.7 * std::sin(j);  // not a perfect grid
                const double y = 5.0 * j;
                input.points.push_back({x, y, 300.0 + 0.08 * y});
            }
        }
        dtm::Polyline ditch;  // a ditch bottom across the slope, 40 cm below it
        for (int k = 0; k <= 10; ++k) {
            const double x = 10.0 * k;
            const double y = 31.0 + 4.0 * std::sin(x / 15.0);
            ditch.points.push_back({x, y, 300.0 + 0.08 * y - 0.4});
        }
        input.breaklines.push_back(ditch);

        const dtm::TriangulateResult result = dtm::triangulate(input);
        const dtm::Tin& tin = result.tin;
        const dtm::CheckReport check = dtm::verify_constraints(tin, input, result.input_to_vertex);
        std::printf("%zu vertices, %zu triangles, %zu constrained edges; breakline %s\n",
                    tin.vertices.size(), tin.triangles.size(), tin.constraints.size(),
                    check.ok() ? "present edge by edge" : check.text().c_str());

        const dtm::SurfaceSampler surface(tin);
        dtm::SurfaceSampler::Cursor cursor;
        for (const double x : {15.0, 50.0, 85.0}) {
            const double y = 31.0 + 4.0 * std::sin(x / 15.0);
            std::printf("  z on the ditch at x = %4.1f: %.3f m (slope above it: %.3f m)\n", x,
                        surface.height({x, y}, cursor), surface.height({x, y + 4.0}, cursor));
        }
        return check.ok() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sample_01: %s\n", e.what());
        return 1;
    }
}
