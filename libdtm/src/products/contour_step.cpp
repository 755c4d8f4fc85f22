// SPDX-License-Identifier: MIT
// Build step "contours": contour lines traced exactly on the TIN (or on its cubic or
// natural-neighbour surface, BuildOptions::interpolation) into a GeoPackage.
#include "build_steps.hpp"
#include "dtm/algo/contour.hpp"
#include "dtm/io/contour_writer.hpp"
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
    io::ContourWriteOptions write_options;
    write_options.crs_wkt = context.crs_wkt;
    io::ContourWriter writer(context.out.add("contours.gpkg"), write_options);
    contour(context.tin, context.interpolant, options, writer, progress);
    writer.commit();
    report.contour_lines = writer.feature_count();
}

}  // namespace dtm::products::detail
