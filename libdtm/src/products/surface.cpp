// SPDX-License-Identifier: MIT
// The surface of the loaded inputs: a TIN read as it is, or the triangulation of the terrain,
// with the flat triangles of a contour map removed when asked (or by default for contours).
#include "dtm/products/surface.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

namespace dtm::products {
namespace {

/// Indices (into terrain.breaklines) of the hard breaklines read from options.flat_areas, which
/// are loaded after every other breakline file: the last ones.
std::vector<std::size_t> flat_outlines(const io::LoadedInputs& inputs,
                                       const SurfaceOptions& options) {
    std::size_t count = 0;
    for (const io::InputSummary& summary : inputs.summaries) {
        if (std::find(options.flat_areas.begin(), options.flat_areas.end(), summary.path) !=
            options.flat_areas.end()) {
            count += summary.breaklines;
        }
    }
    const std::size_t total = inputs.terrain.breaklines.size();
    std::vector<std::size_t> out(std::min(count, total));
    std::iota(out.begin(), out.end(), total - out.size());
    return out;
}

void note_line_heights(io::LoadedInputs& inputs, const TriangulateResult& result) {
    const std::size_t from_surface = result.line_heights.from_surface;
    if (from_surface == 0) return;
    const std::string note = std::to_string(from_surface) +
                             " boundary/hole vertices without height took the height of the "
                             "surface";
    for (io::InputSummary& summary : inputs.summaries) {
        if (summary.boundaries > 0 || summary.holes > 0) summary.warnings.push_back(note);
    }
}

}  // namespace

Surface surface(io::LoadedInputs& inputs, const SurfaceOptions& options, const Progress& progress) {
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
        const TriangulateOptions& t = options.triangulate;
        if (t.optimize != Criterion::delaunay) {
            s.result.stats.optimize = optimize_tin(
                s.result.tin, {.criterion = t.optimize, .threads = t.threads}, progress);
        }
        return s;
    }
    s.survey_points = inputs.terrain.points.size();
    s.contour_input = options.lines_are_contours && !inputs.terrain.breaklines.empty();
    const bool fix = options.contour_flats == ContourFlats::fix ||
                     (options.contour_flats == ContourFlats::automatic && s.contour_input);
    if (fix) {
        ContourFlatsOptions flats;
        flats.triangulate = options.triangulate;
        flats.flat_outlines = flat_outlines(inputs, options);
        ContourFlatsResult fixed = triangulate_contours(inputs.terrain, flats, progress);
        s.result = std::move(fixed.triangulation);
        s.contour_flats = std::move(fixed.report);
        s.added_points = std::move(fixed.added);
    } else {
        s.result = triangulate(std::move(inputs.terrain), options.triangulate, progress);
    }
    inputs.terrain = TerrainInput{};
    note_line_heights(inputs, s.result);
    return s;
}

}  // namespace dtm::products
