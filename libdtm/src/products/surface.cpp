// SPDX-License-Identifier: MIT
// The surface of the loaded inputs: a TIN read as it is, or the triangulation of the terrain.
#include "dtm/products/surface.hpp"

#include <numeric>
#include <string>
#include <utility>

namespace dtm::products {

Surface surface(io::LoadedInputs& inputs, const TriangulateOptions& options,
                const Progress& progress)
{
    Surface s;
    if (inputs.tin) {
        s.from_tin = true;
        s.result.tin = std::move(*inputs.tin);
        inputs.tin.reset();
        const std::size_t n = s.result.tin.vertices.size();
        s.result.stats.points_in = n;
        s.survey_points = n;
        s.result.input_to_vertex.resize(n);
        std::iota(s.result.input_to_vertex.begin(), s.result.input_to_vertex.end(), VertexIndex{0});
        return s;
    }
    s.survey_points = inputs.terrain.points.size();
    s.result = triangulate(std::move(inputs.terrain), options, progress);
    inputs.terrain = TerrainInput{};
    const std::size_t from_surface = s.result.line_heights.from_surface;
    if (from_surface > 0) {
        const std::string note = std::to_string(from_surface) +
                                 " boundary/hole vertices without height took the height of the "
                                 "surface";
        for (io::InputSummary& summary : inputs.summaries) {
            if (summary.boundaries > 0 || summary.holes > 0) summary.warnings.push_back(note);
        }
    }
    return s;
}

}  // namespace dtm::products
