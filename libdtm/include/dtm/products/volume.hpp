// SPDX-License-Identifier: MIT
/// @file
/// @brief `dtm volume` and the volume products of `dtm build --base`: exact cut and fill between
/// a top surface and a base (another surface, a level plane, or a stockpile's spanned foot),
/// optionally within a polygon, with a signed-off text protocol, a JSON report, the difference
/// surface (TIN and GeoTIFF), cut/fill polygons and zero lines (GeoPackage and DXF).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dtm/algo/volume.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/products/surface_input.hpp"

namespace dtm::products {

enum class VolumeBaseKind { surface, plane, stockpile };

struct VolumeJob {
    SurfaceSource top;
    VolumeBaseKind base_kind = VolumeBaseKind::surface;
    SurfaceSource base;             ///< base_kind == surface
    double plane_z = 0.0;           ///< base_kind == plane
    std::filesystem::path within;   ///< optional polygon file: volumes inside it only
    io::LoadOptions within_reader;  ///< reader options for the polygon (layer, where, crs)
    double swell = 1.0;  ///< bank-to-loose factor (>= 1 usually): reported for cut and pile
    double cell = 0.0;   ///< cell of difference.tif (0: from the difference surface's spacing)
    unsigned threads = 0;
    bool products = true;  ///< false: only volume.json and volume.txt
};

/// Everything volume.json says.
struct VolumeReport {
    VolumeResult volume;
    std::string crs_wkt;
    std::string top;     ///< description of the top surface
    std::string base;    ///< description of the base
    std::string within;  ///< the polygon file, if any
    std::size_t top_triangles = 0;
    std::size_t base_triangles = 0;
    double swell = 1.0;
    std::size_t fill_regions = 0;
    std::size_t cut_regions = 0;
    std::size_t zero_lines = 0;
    double zero_line_length = 0.0;
    double cell = 0.0;
    std::vector<std::string> notes;  ///< reprojections, warnings
    std::vector<std::string> files;  ///< written into the output folder
    double seconds = 0.0;
};

/// Runs the job and writes its products into @p out_dir (staged in a temporary sibling and moved
/// in at the end: a failed run leaves nothing half-written).
/// @throws InputError for bad inputs (different CRSs that cannot be reconciled, an empty overlap,
/// a polygon that does not close), UsageError, Cancelled.
VolumeReport run_volume(const VolumeJob& job,
                        const std::filesystem::path& out_dir,
                        const Progress& progress = {});

/// The products of an already computed pair of surfaces into @p folder (which exists):
/// volume.json, volume.txt and, when @p job.products, difference.ply, difference.tif,
/// cut_fill.gpkg, zero_lines.dxf. @p base is null for a plane. Fills report.files.
/// @p base_area, when given, is the base's area within the compared region (the base is not
/// clipped to a `--within` polygon, only the top is): it replaces the base's whole area in the
/// "base only" figure.
void write_volume_products(const Tin& top,
                           const Tin* base,
                           const VolumeJob& job,
                           const std::filesystem::path& folder,
                           VolumeReport& report,
                           const Progress& progress = {},
                           std::optional<double> base_area = std::nullopt);

/// The text of volume.json / volume.txt.
[[nodiscard]] std::string volume_json(const VolumeReport& report);
[[nodiscard]] std::string volume_protocol(const VolumeReport& report);

}  // namespace dtm::products
