// SPDX-License-Identifier: MIT
// --contours-fix-flats: terrain from contour lines without flat triangles (contour_flats.hpp).
#include "contour_flats_args.hpp"

#include <cstdio>
#include <utility>

namespace dtm::cli {

void add_contour_flats_options(CLI::App& app, ContourFlatsArgs& args) {
    auto* on = app.add_flag_callback(
        "--contours-fix-flats", [&args] { args.fix = 1; },
        "Remove the flat triangles of a TIN of contour lines by points on the skeleton of each "
        "flat region, heights between the neighbouring levels; summits and pits inside closed "
        "contours without points estimated and reported (default: on when the lines take their "
        "heights from --z-field)");
    auto* off = app.add_flag_callback(
        "--no-contours-fix-flats", [&args] { args.fix = 0; },
        "Keep the TIN of contour lines as it is (flat triangles included)");
    on->excludes(off);
}

namespace {

/// Indices (in the merged terrain) of the breaklines read from the --flat-areas files, which
/// load_inputs reads last.
std::vector<std::size_t> flat_outlines(const io::LoadedInputs& inputs, const InputArgs& args) {
    const std::size_t files = args.flat_areas.size();
    std::size_t count = 0;
    for (std::size_t i = inputs.summaries.size() - std::min(files, inputs.summaries.size());
         i < inputs.summaries.size(); ++i) {
        count += inputs.summaries[i].breaklines;
    }
    std::vector<std::size_t> out;
    const std::size_t total = inputs.terrain.breaklines.size();
    for (std::size_t k = total - std::min(count, total); k < total; ++k) {
        out.push_back(k);
    }
    return out;
}

void print_summary(const ContourFlatsReport& r, const char* command) {
    const auto percent = [](std::size_t part, std::size_t whole) {
        return whole == 0 ? 0.0 : 100.0 * static_cast<double>(part) / static_cast<double>(whole);
    };
    std::fprintf(stderr,
                 "dtm %s: contour flats: %zu of %zu triangles flat (%.1f %%) -> %zu of %zu "
                 "(%.1f %%); %zu points added in %zu flat regions (%zu real flats kept, %zu "
                 "unresolved); %zu summits/pits estimated\n",
                 command, r.flat_before, r.triangles_before,
                 percent(r.flat_before, r.triangles_before), r.flat_after, r.triangles_after,
                 percent(r.flat_after, r.triangles_after), r.points_added, r.regions, r.true_flats,
                 r.unresolved, r.peaks.size());
    for (const EstimatedPeak& p : r.peaks) {
        std::fprintf(stderr, "dtm %s:   estimated %s %.3f at %.3f, %.3f (inside the %g contour)\n",
                     command, p.summit ? "summit" : "pit", p.at.z, p.at.x, p.at.y, p.contour);
    }
}

}  // namespace

TerrainTin triangulate_terrain(io::LoadedInputs& inputs,
                               const InputArgs& input_args,
                               const TriangulateOptions& options,
                               const ContourFlatsArgs& flats,
                               const Progress& progress,
                               const char* command,
                               bool quiet,
                               bool keep_input) {
    TerrainTin out;
    out.survey_points = inputs.terrain.points.size();
    const bool contour_input =
        !input_args.load.z_field.empty() && !inputs.terrain.breaklines.empty();
    out.contour_input = contour_input;
    const bool fix = flats.fix == 1 || (flats.fix < 0 && contour_input);
    if (!fix) {
        if (keep_input) {
            out.result = triangulate(inputs.terrain, options, progress);
            out.input = std::move(inputs.terrain);
        } else {  // consumed: its memory goes as soon as the vertices are merged
            out.result = triangulate(std::move(inputs.terrain), options, progress);
        }
        inputs.terrain = TerrainInput{};
        return out;
    }
    ContourFlatsOptions flat_options;
    flat_options.triangulate = options;
    flat_options.flat_outlines = flat_outlines(inputs, input_args);
    ContourFlatsResult fixed = triangulate_contours(inputs.terrain, flat_options, progress);
    if (keep_input) {
        out.input = std::move(inputs.terrain);
        out.input.points.insert(out.input.points.end(), fixed.added.begin(), fixed.added.end());
    }
    inputs.terrain = TerrainInput{};
    out.result = std::move(fixed.triangulation);
    out.flats = std::move(fixed.report);
    if (!quiet) {
        print_summary(*out.flats, command);
    }
    return out;
}

}  // namespace dtm::cli
