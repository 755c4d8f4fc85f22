// SPDX-License-Identifier: MIT
// Build step "project": a QGIS project showing every product written before it, in the TIN's CRS.
#include <algorithm>

#include "build_steps.hpp"
#include "dtm/io/formats/qgis_project.hpp"

namespace dtm::products::detail {

io::QgisProject build_project(const std::string& crs_wkt,
                              const SurfaceStats& surface,
                              const BuildReport& report) {
    io::QgisProject project;
    project.title = "dtm build";
    project.crs_wkt = crs_wkt;
    project.extent = surface.extent;
    project.z_min = surface.z_min;
    project.z_max = surface.z_max;
    project.contour_layer = "contours";
    project.elevation_field = "elevation";
    project.index_field = "index";
    project.index_interval =
        report.contour_interval * static_cast<double>(std::max<std::size_t>(report.index_every, 1));
    return project;
}

void write_project(BuildContext& context, const Progress&) {
    const io::AtomicDirectory& out = context.out;
    const auto layer = [&out](const char* name) {
        return out.contains(name) ? std::filesystem::path(name) : std::filesystem::path();
    };
    io::QgisProject project = build_project(context.crs_wkt, context.surface, context.report);
    project.dem = layer("dem.tif");
    project.hillshade = layer("hillshade.tif");
    project.contours = layer("contours.gpkg");
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
