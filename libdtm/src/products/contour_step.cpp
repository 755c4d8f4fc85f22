// SPDX-License-Identifier: MIT
// Build step "contours": contour lines traced exactly on the TIN (or on its cubic or
// natural-neighbour surface, BuildOptions::interpolation) into a GeoPackage, with the index
// contour numbers and spot heights placed at the map's scale (layers contour_labels,
// spot_heights: products/contours.hpp).
#include "build_steps.hpp"
#include "dtm/algo/contour.hpp"
#include "dtm/products/contours.hpp"
#include "dtm/products/rules.hpp"

namespace dtm::products::detail {

void write_contours(BuildContext& context, const Progress& progress) {
    const bool given = context.options.interval > 0.0;
    ContourOptions options;
    options.interval = given ? context.options.interval : default_interval(context.surface);
    options.index_every = context.options.index_every;
    options.threads = context.options.triangulate.threads;
    BuildReport& report = context.report;
    report.contour_interval = options.interval;
    report.index_every = options.index_every;
    report.interval_rule = given ? context.worded("given (`interval`)") : default_interval_rule;
    report.contour_levels =
        contour_levels(context.surface.z_min, context.surface.z_max, options).size();
    ContourFileOptions file;
    file.crs_wkt = context.crs_wkt;
    file.spot_heights = true;
    file.label_scale = context.options.map_scale;
    const ContourFileReport written =
        write_contour_file(context.tin, &context.interpolant, options,
                           context.out.add("contours.gpkg"), file, progress);
    report.contour_lines = written.lines;
    report.contour_label_scale = written.label_scale;
    report.contour_label_height = written.text_height;
    report.contour_labels = written.labels;
    report.contour_label_failures = written.label_failures;
    report.contour_spot_heights = written.spots;
}

}  // namespace dtm::products::detail
