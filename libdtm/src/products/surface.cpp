// SPDX-License-Identifier: MIT
// The surface of the loaded inputs: a TIN read as it is, or the triangulation of the terrain,
// with the flat triangles of a contour map removed when asked (or by default for contours).
#include "dtm/products/surface.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <string>
#include <utility>

#include "dtm/core/error.hpp"

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

bool reduces_dem(const DemReduceOptions& o) { return o.clip_radius != 0.0 || o.max_error != 0.0; }

/// Takes the raster cells out of inputs.terrain.points (and their empty labels), clips and thins
/// them (reduce_dem) and puts the kept ones back after the survey points. The TIN of the last
/// thinning pass, when there was one, goes to @p s.
void reduce_dem_cells(io::LoadedInputs& inputs,
                      const SurfaceOptions& options,
                      Surface& s,
                      bool keep_triangulation,
                      const Progress& progress) {
    if (inputs.dem_cells.empty()) {
        throw OptionError(options.dem.max_error != 0.0 ? "dem.max_error" : "dem.clip_radius",
                          std::string("`") +
                              (options.dem.max_error != 0.0 ? "dem.max_error" : "dem.clip_radius") +
                              "`: no input is a raster DEM");
    }
    std::vector<Point3>& all = inputs.terrain.points;
    std::vector<char> is_cell(all.size(), 0);
    for (const io::DemCells& d : inputs.dem_cells) {
        std::fill(is_cell.begin() + static_cast<std::ptrdiff_t>(d.first),
                  is_cell.begin() + static_cast<std::ptrdiff_t>(d.last), 1);
    }
    std::vector<Point3> cells;
    std::vector<Point3> survey_points;
    io::PointLabels labels;
    const bool labelled = !inputs.labels.ids.empty();
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (is_cell[i] != 0) {
            cells.push_back(all[i]);
            continue;
        }
        survey_points.push_back(all[i]);
        if (labelled) {
            labels.ids.push_back(std::move(inputs.labels.ids[i]));
            labels.codes.push_back(std::move(inputs.labels.codes[i]));
        }
    }
    all = std::move(survey_points);
    DemReduceResult r =
        reduce_dem(std::move(inputs.terrain), cells, options.dem, options.triangulate, progress);
    inputs.terrain = std::move(r.terrain);
    if (labelled) {
        labels.ids.resize(inputs.terrain.points.size());
        labels.codes.resize(inputs.terrain.points.size());
        inputs.labels = std::move(labels);
    }
    if (r.triangulated && keep_triangulation) s.result = std::move(r.triangulation);
    const DemReduceReport& d = r.report;
    char text[320];
    std::snprintf(text, sizeof text,
                  "DEM cells: %zu given, %zu dropped within %g of the survey, %zu kept%s", d.cells,
                  d.clipped, options.dem.clip_radius, d.kept,
                  options.dem.max_error > 0.0 ? "" : " (all the others)");
    std::string note = text;
    if (options.dem.max_error > 0.0) {
        std::snprintf(text, sizeof text,
                      "; TIN within %g of every cell: max error %.6g, RMS %.6g over %zu cells, %zu "
                      "vertices after %zu passes",
                      options.dem.max_error, d.max_error, d.rms_error, d.measured, d.vertices,
                      d.passes);
        note += text;
        if (d.outside > 0) note += "; " + std::to_string(d.outside) + " cells off the surface";
        if (d.over_error > 0) {
            note += "; " + std::to_string(d.over_error) +
                    " cells above the bound where a survey point gave the vertex its height";
        }
    }
    for (const io::DemCells& c : inputs.dem_cells) {
        if (c.summary < inputs.summaries.size())
            inputs.summaries[c.summary].warnings.push_back(note);
    }
    inputs.dem_cells.clear();
    s.dem = d;
}

}  // namespace

Surface surface(io::LoadedInputs& inputs, const SurfaceOptions& options, const Progress& progress) {
    Surface s;
    if (inputs.tin) {
        if (reduces_dem(options.dem)) {
            throw OptionError(options.dem.max_error != 0.0 ? "dem.max_error" : "dem.clip_radius",
                              "`dem.clip_radius` and `dem.max_error` take raster DEM input, but a "
                              "TIN input is used as it is (add `retriangulate`)");
        }
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
    s.contour_input = options.lines_are_contours && !inputs.terrain.breaklines.empty();
    const bool fix = options.contour_flats == ContourFlats::fix ||
                     (options.contour_flats == ContourFlats::automatic && s.contour_input);
    Progress rest = progress;
    if (reduces_dem(options.dem)) {
        reduce_dem_cells(inputs, options, s, !fix, progress.sub(0.0, 0.9));
        rest = progress.sub(0.9, 1.0);
    }
    s.survey_points = inputs.terrain.points.size();
    if (s.dem && s.dem->passes > 0 && !fix) {
        // the last thinning pass is the triangulation of the kept input
    } else if (fix) {
        ContourFlatsOptions flats;
        flats.triangulate = options.triangulate;
        flats.flat_outlines = flat_outlines(inputs, options);
        ContourFlatsResult fixed = triangulate_contours(inputs.terrain, flats, rest);
        s.result = std::move(fixed.triangulation);
        s.contour_flats = std::move(fixed.report);
        s.added_points = std::move(fixed.added);
    } else {
        s.result = triangulate(std::move(inputs.terrain), options.triangulate, rest);
    }
    inputs.terrain = TerrainInput{};
    note_line_heights(inputs, s.result);
    return s;
}

}  // namespace dtm::products
