// SPDX-License-Identifier: MIT
// The volume job: read the surfaces (into one CRS), derive the base (level plane, a stockpile's
// spanned foot), clip to the polygon, overlay, integrate, write the products.
//
// Products (docs/products.md "Volumes"): volume.json and volume.txt always; with products also
//   difference.ply  the difference surface top - base as a TIN (exact: linear on every piece)
//   difference.tif  the same sampled at cell centres (GeoTIFF, NoData outside the overlap)
//   cut_fill.gpkg   layer cut_fill: one polygon per connected cut or fill region (kind, area,
//                   volume, max_depth); layer zero_lines: LineStringZ on the surfaces
//   zero_lines.dxf  the zero lines as 3-D POLYLINEs on layer ZERO_LINE
#include "dtm/products/volume.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "dtm/algo/cut_fill.hpp"
#include "dtm/algo/difference_surface.hpp"
#include "dtm/algo/rasterize.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/algo/volume_surfaces.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/formats/dxf.hpp"
#include "dtm/io/formats/vector_file.hpp"
#include "dtm/io/grid_writer.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/io/tin_file.hpp"
#include "dtm/products/rules.hpp"
#include "products/detail/staged_folder.hpp"

namespace dtm::products {
namespace fs = std::filesystem;
namespace {

/// The difference GeoTIFF's cell: the mean vertex spacing over @p area, rounded down by nice_floor,
/// enlarged while the grid would pass 25 million cells.
double difference_cell(const Tin& tin, double area) {
    const double spacing =
        std::sqrt(area / static_cast<double>(std::max<std::size_t>(tin.vertices.size(), 1)));
    double cell = nice_floor(std::max(spacing, 1e-3));
    const Box2 b = tin_bounds(tin);
    while ((b.xmax - b.xmin) / cell * (b.ymax - b.ymin) / cell > 25e6) cell = nice_next(cell);
    return cell;
}

double line_length(const ZeroLine& line) {
    double sum = 0.0;
    for (std::size_t i = 1; i < line.points.size(); ++i) {
        sum += std::hypot(line.points[i].x - line.points[i - 1].x,
                          line.points[i].y - line.points[i - 1].y);
    }
    return sum;
}

void write_map(const CutFillMap& map,
               const std::string& crs,
               const fs::path& folder,
               VolumeReport& report) {
    io::VectorFile gpkg(folder / "cut_fill.gpkg", crs);
    using T = io::VectorField::Type;
    const std::size_t regions = gpkg.add_layer(
        "cut_fill", io::VectorGeometry::polygon,
        {{"kind", T::text}, {"area", T::real}, {"volume", T::real}, {"max_depth", T::real}});
    const std::size_t lines = gpkg.add_layer("zero_lines", io::VectorGeometry::line_3d,
                                             {{"length", T::real}, {"closed", T::integer}});
    for (const CutFillRegion& r : map.regions) {
        gpkg.add_polygon(regions, r.rings,
                         {std::string(r.fill ? "fill" : "cut"), r.area, r.volume, r.max_depth});
        (r.fill ? report.fill_regions : report.cut_regions) += 1;
    }
    const io::DxfLayer zero_layer{"ZERO_LINE", 1};
    io::DxfWriter dxf(folder / "zero_lines.dxf", std::span(&zero_layer, 1));
    for (const ZeroLine& z : map.zero_lines) {
        const double length = line_length(z);
        gpkg.add_line(lines, z.points, {length, static_cast<long long>(z.closed ? 1 : 0)});
        dxf.polyline(zero_layer.name,
                     z.closed ? std::span(z.points).first(z.points.size() - 1)
                              : std::span<const Point3>(z.points),
                     z.closed);
        report.zero_line_length += length;
    }
    report.zero_lines = map.zero_lines.size();
    gpkg.commit();
    dxf.finish();
    report.files.insert(report.files.end(), {"cut_fill.gpkg", "zero_lines.dxf"});
}

}  // namespace

void write_volume_products(const Tin& top,
                           const Tin* base,
                           const VolumeJob& job,
                           const fs::path& folder,
                           VolumeReport& report,
                           const Progress& progress,
                           std::optional<double> base_area) {
    const OverlayOptions options{.threads = job.threads};
    const TinOverlay overlay =
        base != nullptr ? TinOverlay(top, *base, options) : TinOverlay(top, job.plane_z, options);
    report.volume = volume(overlay, top, base, progress.sub(0.0, 0.3));
    if (base != nullptr && base_area.has_value()) {
        report.volume.base_area = *base_area;
        report.volume.base_only_area = only_area(*base_area, report.volume.overlap_area);
    }
    report.top_triangles = top.triangles.size();
    report.base_triangles = base != nullptr ? base->triangles.size() : 0;
    report.swell = job.swell;
    if (report.volume.overlap_area <= 0.0) {
        throw InputError("volume: the top surface (" + report.top + ") and the base (" +
                         report.base + ") do not overlap: nothing to compute");
    }
    if (report.volume.top_only_area > 0.0) {
        report.notes.push_back("the base is absent under " +
                               std::to_string(report.volume.top_only_area) +
                               " m2 of the top surface: no volume is counted there");
    }
    if (report.volume.base_only_area > 0.0) {
        report.notes.push_back("the top surface is absent over " +
                               std::to_string(report.volume.base_only_area) +
                               " m2 of the base: no volume is counted there");
    }
    if (job.products) {
        const DifferenceSurface diff = difference_surface(overlay, progress.sub(0.3, 0.6));
        io::write_tin(diff.tin, folder / "difference.ply", {.crs_wkt = report.crs_wkt});
        report.files.emplace_back("difference.ply");
        report.cell =
            job.cell > 0.0 ? job.cell : difference_cell(diff.tin, report.volume.overlap_area);
        const GridSpec spec = snapped_grid_spec(tin_bounds(diff.tin), report.cell);
        io::GridWriter grid(folder / "difference.tif", spec, {.crs_wkt = report.crs_wkt});
        rasterize(diff.tin, spec, {.threads = job.threads}, grid, progress.sub(0.6, 0.8));
        grid.commit();
        report.files.emplace_back("difference.tif");
        progress.report(0.8, "tracing cut and fill");
        write_map(cut_fill_map(diff, progress.sub(0.8, 0.95)), report.crs_wkt, folder, report);
    }
    detail::write_text_file(folder / "volume.json", volume_json(report));
    detail::write_text_file(folder / "volume.txt", volume_protocol(report));
    report.files.insert(report.files.end(), {"volume.json", "volume.txt"});
    progress.report(1.0, "volume products written");
}

VolumeReport run_volume(const VolumeJob& job, const fs::path& out_dir, const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (!(job.swell > 0.0)) {
        throw UsageError("volume: the swell factor must be positive");
    }
    io::check_output(out_dir, io::OutputKind::folder, "out_dir");  // before any input is read
    io::AtomicDirectory staging(out_dir);
    VolumeReport report;
    LoadedSurface top;
    LoadedSurface base;
    if (job.base_kind == VolumeBaseKind::surface) {  // both read at once
        std::vector<std::string> notes;              // the reprojection note is worded below
        std::vector<LoadedSurface> both =
            load_surfaces({job.top, job.base}, notes, progress.sub(0.0, 0.3));
        top = std::move(both[0]);
        base = std::move(both[1]);
    } else {
        top = load_surface(job.top, {}, progress.sub(0.0, 0.15));
    }
    report.crs_wkt = top.crs_wkt;
    report.top = top.description();
    if (job.base_kind == VolumeBaseKind::surface) {
        report.base = base.description();
        if (!base.transformed_from.empty()) {
            report.notes.push_back("the base was reprojected from " + base.transformed_from +
                                   " into the top surface's " + io::crs_label(top.crs_wkt));
        }
        if (report.crs_wkt.empty()) {
            report.crs_wkt = base.crs_wkt;
        }
        if (top.crs_wkt.empty() != base.crs_wkt.empty()) {
            report.notes.push_back("only one surface carries a CRS (" +
                                   io::crs_label(report.crs_wkt) +
                                   "): the other is taken to be in it too");
        }
    } else if (job.base_kind == VolumeBaseKind::plane) {
        report.base = "level plane z = " + std::to_string(job.plane_z);
    }
    std::optional<double> base_area_within;
    if (!job.within.empty()) {
        const TerrainInput area = load_area(job.within, job.within_reader, report.crs_wkt);
        report.within = job.within.generic_string();
        top.tin = clip_tin(top.tin, area, progress.sub(0.3, 0.4));
        if (top.tin.triangles.empty()) {
            throw InputError(job.within, 0, 0,
                             "the polygon does not overlap the top surface (" + report.top + ")");
        }
        if (job.base_kind == VolumeBaseKind::surface) {
            // Only the top is clipped: two clipped surfaces would share a boundary of rounded
            // crossings along the polygon, whose near-collinear chains the overlay resolves
            // exactly but the difference surface cannot fan from rounded points. The base's
            // own clip gives its area within the polygon (the "base only" figure).
            const Tin base_within = clip_tin(base.tin, area, progress.sub(0.4, 0.5));
            if (base_within.triangles.empty()) {
                throw InputError(job.within, 0, 0,
                                 "the polygon does not overlap the base (" + report.base + ")");
            }
            base_area_within = tin_area(base_within);
        }
    }
    if (job.base_kind == VolumeBaseKind::stockpile) {
        base.tin = spanned_base(top.tin);
        report.base = "stockpile floor spanned by the pile's outer boundary" +
                      std::string(job.within.empty() ? "" : " (clipped to the polygon)");
    }
    const Tin* base_tin = job.base_kind == VolumeBaseKind::plane ? nullptr : &base.tin;
    write_volume_products(top.tin, base_tin, job, staging.staging(), report,
                          progress.sub(0.5, 0.99), base_area_within);
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    detail::commit_files(staging, report.files);
    progress.report(1.0, "done");
    return report;
}

}  // namespace dtm::products
