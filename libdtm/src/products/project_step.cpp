// SPDX-License-Identifier: MIT
// Build step "project": a QGIS project showing every product written before it, in the TIN's CRS.
#include <algorithm>

#include "build_steps.hpp"
#include "dtm/io/formats/qgis_project.hpp"

namespace dtm::products::detail {

void write_project(BuildContext& context, const Progress&) {
    const io::AtomicDirectory& out = context.out;
    const auto layer = [&out](const char* name) {
        return out.contains(name) ? std::filesystem::path(name) : std::filesystem::path();
    };
    io::QgisProject project;
    project.title = "dtm build";
    project.crs_wkt = context.crs_wkt;
    project.extent = context.surface.extent;
    project.z_min = context.surface.z_min;
    project.z_max = context.surface.z_max;
    project.dem = layer("dem.tif");
    project.hillshade = layer("hillshade.tif");
    project.contours = layer("contours.gpkg");
    project.contour_layer = "contours";
    project.elevation_field = "elevation";
    project.index_field = "index";
    project.index_interval =
        context.report.contour_interval *
        static_cast<double>(std::max<std::size_t>(context.report.index_every, 1));
    if (!project.contours.empty() && context.report.contour_label_height > 0.0) {
        project.contour_label_layer = "contour_labels";
        project.spot_layer = "spot_heights";
        project.label_height = context.report.contour_label_height;
    }
    project.mesh = layer("tin.2dm");
    project.layout = context.map_layout;
    project.cut_fill = layer("volume/cut_fill.gpkg");
    io::write_qgis_project(project, context.out.add("dtm.qgs"));
}

}  // namespace dtm::products::detail
