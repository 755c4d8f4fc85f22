// SPDX-License-Identifier: MIT
/// @file
/// @brief The report of products::build() (report.json): inputs, what became of every input
/// point, TIN counts, CRS, extent, z range, areas, breakline conflicts, each product's figures
/// and the timings per stage. A new product adds its section here and in src/products/report.cpp.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dtm/algo/contour_flats.hpp"
#include "dtm/algo/dem_reduce.hpp"
#include "dtm/algo/surface_stats.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/volume.hpp"
#include "dtm/core/grid.hpp"
#include "dtm/io/inputs.hpp"

namespace dtm::products {

struct StageTime {
    std::string stage;
    double seconds = 0.0;
};

/// What a distributed build (products::distributed_build) reports of its ranks.
struct DistributedRun {
    int ranks = 1;
    std::uint64_t survey_points = 0;  ///< read from the point list
    std::uint64_t line_vertices = 0;  ///< of breaklines, boundaries and holes
    std::uint64_t merged = 0;         ///< merged into another input point (exact duplicates)
    std::uint64_t crossing_vertices = 0;
    std::uint64_t unused_vertices = 0;  ///< no triangle names them (outside, in holes, peeled)
    std::uint64_t band_triangles = 0;   ///< merged across ranks, all merges
    std::uint32_t widenings = 0;        ///< most band widenings of one merge
    std::uint64_t bytes_sent = 0;       ///< by all ranks, every phase
    std::vector<std::pair<std::string, std::uint64_t>> phase_bytes;  ///< all ranks, per phase
};

struct BuildReport {
    // what was read and built
    std::vector<io::InputSummary> inputs;
    std::size_t skipped_lines = 0;  ///< bad input lines skipped (ReadOptions::skip_bad_lines)
    std::string crs_wkt;
    InputAccounting accounting;
    TriangulateStats triangulation;
    std::vector<ConstraintConflict> conflicts;
    SurfaceStats surface;
    /// Set when the flat triangles of contour input were removed.
    std::optional<ContourFlatsReport> contour_flats;
    std::optional<DemReduceReport> dem_cells;  ///< raster DEM cells clipped and thinned
    std::string interpolation = "linear";      ///< the surface of the DEM and the contours
    // the DEM (step "dem": dem.tif, hillshade.tif)
    GridSpec dem;
    std::string cell_rule;  ///< how the cell size was chosen (given, or the automatic rule)
    // the contours (step "contours": contours.gpkg)
    double contour_interval = 0.0;
    std::size_t index_every = 0;
    std::string interval_rule;
    std::size_t contour_levels = 0;
    std::size_t contour_lines = 0;
    /// dtm's placed labels in contours.gpkg (layers contour_labels, spot_heights)
    double contour_label_scale = 0.0;
    double contour_label_height = 0.0;  ///< CRS units
    std::size_t contour_labels = 0;
    std::size_t contour_label_failures = 0;
    std::size_t contour_spot_heights = 0;
    // the map sheet (step "map": map.pdf)
    double map_scale = 0.0;  ///< 1 : map_scale of map.pdf (0: no map)
    std::size_t map_labels = 0;
    std::size_t map_label_failures = 0;
    std::size_t map_spot_heights = 0;
    // the volume against the base (step "volume": volume/), when one was given
    bool has_volume = false;
    VolumeResult volume;
    std::string volume_base;  ///< the base's files
    // the run
    std::optional<DistributedRun> distributed;  ///< set by a distributed build
    std::vector<StageTime> timings;
    std::vector<std::string> outputs;  ///< file names written into the output folder
};

/// Conflicts listed individually in the report (the count is always complete).
inline constexpr std::size_t report_conflict_limit = 1000;

/// The report as a JSON document (UTF-8, 2-space indentation).
[[nodiscard]] std::string report_json(const BuildReport& report);

/// Writes report_json(report) to exactly @p path (the caller provides atomicity).
/// @throws Error if the file cannot be written.
void write_report(const BuildReport& report, const std::filesystem::path& path);

}  // namespace dtm::products
