// SPDX-License-Identifier: MIT
// --contours-fix-flats: terrain from contour lines without flat triangles (contour_flats.hpp).
#include "contour_flats_args.hpp"

#include <cstdio>

namespace dtm::cli {

void add_contour_flats_options(CLI::App& app, products::ContourFlats& mode) {
    auto* on = app.add_flag_callback(
        "--contours-fix-flats", [&mode] { mode = products::ContourFlats::fix; },
        "Remove the flat triangles of a TIN of contour lines by points on the skeleton of each "
        "flat region, heights between the neighbouring levels; summits and pits inside closed "
        "contours without points estimated and reported (default: on when the lines take their "
        "heights from --z-field)");
    auto* off = app.add_flag_callback(
        "--no-contours-fix-flats", [&mode] { mode = products::ContourFlats::keep; },
        "Keep the TIN of contour lines as it is (flat triangles included)");
    on->excludes(off);
}

products::SurfaceOptions surface_options(const InputArgs& input,
                                         const TriangulateOptions& triangulate,
                                         products::ContourFlats mode) {
    products::SurfaceOptions options;
    options.triangulate = triangulate;
    options.contour_flats = mode;
    options.lines_are_contours = !input.read.z_field.empty();
    options.flat_areas.assign(input.flat_areas.begin(), input.flat_areas.end());
    return options;
}

void print_contour_flats(const ContourFlatsReport& r, const char* command) {
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

}  // namespace dtm::cli
