// SPDX-License-Identifier: MIT
/// @file
/// @brief The product steps of products::build(): each writes its files into the staging folder
/// and fills its section of the report. The list (order, progress, which options turn a step
/// on) is in build.cpp.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/algo/interpolation.hpp"
#include "dtm/algo/surface_stats.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/formats/qgis_project.hpp"
#include "dtm/products/build.hpp"

namespace dtm::products::detail {

/// What every step may read, and where it writes.
struct BuildContext {
    const BuildOptions& options;
    const Tin& tin;
    const TinInterpolant& interpolant;  ///< options.interpolation on tin, for the DEM and contours
    const std::string& crs_wkt;         ///< CRS of the TIN; empty if unknown
    const SurfaceStats& surface;
    io::AtomicDirectory& out;
    BuildReport& report;
    const std::vector<io::InputSummary>* inputs = nullptr;  ///< what was read (names of sources)
    std::optional<io::QgisLayout> map_layout;  ///< map.pdf's sheet, for the QGIS print layout

    /// @p text as options.wording words it.
    [[nodiscard]] std::string worded(std::string_view text) const {
        return options.wording ? options.wording(text) : std::string(text);
    }
};

struct BuildStep {
    std::string_view stage;               ///< its name in the report's timings
    double progress_end;                  ///< the overall fraction done when it has finished
    bool (*wanted)(const BuildOptions&);  ///< nullptr: always run
    void (*run)(BuildContext& context, const Progress& progress);
};

/// tin.ply, tin.2dm, surface.vtp (tin_step.cpp).
void write_tin_files(BuildContext& context, const Progress& progress);
/// dem.tif and hillshade.tif; report.dem, report.cell_rule (dem_step.cpp).
void write_dem(BuildContext& context, const Progress& progress);
/// contours.gpkg; report.contour_* (contour_step.cpp).
void write_contours(BuildContext& context, const Progress& progress);
/// map.pdf, the contour map sheet; report.map_*, map_layout (map_step.cpp).
void write_map_sheet(BuildContext& context, const Progress& progress);
/// With BuildOptions::base: volume/ (volume.json, volume.txt, difference.ply, difference.tif,
/// cut_fill.gpkg, zero_lines.dxf); report.volume (volume_step.cpp).
bool wants_volume(const BuildOptions& options);
void write_volume(BuildContext& context, const Progress& progress);
/// dtm.qgs with a layer for each product written before it (project_step.cpp).
void write_project(BuildContext& context, const Progress& progress);
/// The project of a build without its layers: CRS, extent, colour range, the contour layer's
/// name and fields, the index interval from report.contour_interval and index_every (also the
/// distributed build's, products/distributed_build.cpp).
[[nodiscard]] io::QgisProject build_project(const std::string& crs_wkt,
                                            const SurfaceStats& surface,
                                            const BuildReport& report);

}  // namespace dtm::products::detail
