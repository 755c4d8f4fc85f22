// SPDX-License-Identifier: MIT
// A contour file with labels: trace into the writer while keeping the lines, then place the
// labels on them (annotate_contours) and add them to the same file before it is committed.
#include "dtm/products/contours.hpp"

#include "dtm/algo/rasterize.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/contour_writer.hpp"
#include "dtm/products/map.hpp"

namespace dtm::products {

ContourFileReport write_contour_file(const Tin& tin,
                                     const TinInterpolant* interpolant,
                                     const ContourOptions& options,
                                     const std::filesystem::path& path,
                                     const ContourFileOptions& file,
                                     const Progress& progress) {
    if (file.spot_heights && !io::contour_file_holds_annotation(path)) {
        throw OptionError("spot_heights",
                          "`spot_heights` need a .dxf or .gpkg contour file, not " + path.string());
    }
    io::ContourWriter writer(path, {.crs_wkt = file.crs_wkt, .layer = file.layer});
    ContourFileReport report;
    const bool annotate = writer.holds_annotation() && (file.labels || file.spot_heights);
    const auto trace = [&](ContourSink& sink, const Progress& p) {
        if (interpolant != nullptr) {
            contour(tin, *interpolant, options, sink, p);
        } else {
            contour(tin, options, sink, p);
        }
    };
    if (!annotate) {
        trace(writer, progress);
        writer.commit();
        report.lines = writer.feature_count();
        return report;
    }
    ContourKeeper keeper(writer);
    trace(keeper, progress.sub(0.0, 0.6));
    report.label_scale =
        file.label_scale > 0.0 ? file.label_scale : default_map_scale(tin_bounds(tin));
    ContourAnnotationOptions a = file.annotation;
    a.units_per_mm = report.label_scale / 1000.0;
    a.spot_heights = file.spot_heights;
    ContourAnnotation annotation =
        annotate_contours(tin, keeper.lines(), a, progress.sub(0.6, 0.95));
    if (!file.labels) {
        annotation.labels.clear();
        annotation.failures.clear();
    }
    writer.add_annotation(annotation);
    writer.commit();
    report.lines = writer.feature_count();
    report.annotated = true;
    report.text_height = annotation.text_height;
    report.labels = annotation.labels.size();
    report.label_failures = annotation.failures.size();
    report.spots = annotation.spots.size();
    report.spot_labels_failed = annotation.spot_labels_failed;
    progress.report(1.0, "contours written");
    return report;
}

}  // namespace dtm::products
