// SPDX-License-Identifier: MIT
// [dc] The production kernel as a method: the reference every other Delaunay method is checked
// against. Guibas and Stolfi (1985), "Primitives for the manipulation of general subdivisions and
// the computation of Voronoi diagrams"; thesis 000 §3.7 (divide and conquer). The kernel itself
// and its parallel tiles: docs/algorithms/cdt.md, docs/algorithms/tiling.md. Its predicate calls
// are not counted (it calls geom:: directly for speed), so its counters stay zero.
#include "dc.hpp"

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"

namespace dtm::methods {

MethodResult run_dc(const MethodInput& input,
                    const MethodOptions& options,
                    const Progress& progress) {
    if (!options.params.empty()) {
        throw UsageError("method dc takes no parameter (got '" + options.params.begin()->first +
                         "')");
    }
    TerrainInput terrain;
    terrain.points.assign(input.points.begin(), input.points.end());
    for (const auto& [a, b] : input.segments) {
        if (a >= input.points.size() || b >= input.points.size()) {
            throw InputError("method dc: a segment names a point that does not exist");
        }
        terrain.breaklines.push_back(Polyline{{input.points[a], input.points[b]}, false, {}});
    }
    TriangulateOptions tri;
    tri.threads = options.threads;
    MethodResult result;
    result.tin = triangulate(std::move(terrain), tri, progress).tin;
    return result;
}

}  // namespace dtm::methods
