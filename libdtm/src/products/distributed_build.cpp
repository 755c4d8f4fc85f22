// SPDX-License-Identifier: MIT
//
// The distributed main job (distributed_build.hpp): the distributed surface once, then every
// product from it, all into one staged folder.
//   1. rank 0 checks the target and stages the folder (io::AtomicDirectory); its path goes to
//      every rank (the ranks share the file system);
//   2. the distributed surface (products/detail/distributed_surface) and tin.ply (MPI-IO);
//   3. the ranks' real triangles (dist::surface_mesh); the measures of the TIN as the serial
//      build takes them, exactly (detail/distributed_measures), and from them the serial rules'
//      cell and interval;
//   4. rank r's triangles as surface-r-of-P.vtp, rank 0 the surface.pvtp over them;
//   5. the DEM tiles and dem.vrt, its hillshade tiles and hillshade.vrt, the contour pieces and
//      contours.vrt (detail/distributed_pieces);
//   6. rank 0: dtm.qgs over the VRTs, report.json, and the commit, once every rank is done.
#include "dtm/products/distributed_build.hpp"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "dist/mesh_vertices.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/formats/qgis_project.hpp"
#include "dtm/io/formats/vtk_surface.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/products/rules.hpp"
#include "products/build_steps.hpp"
#include "products/detail/distributed_measures.hpp"
#include "products/detail/distributed_pieces.hpp"
#include "products/detail/distributed_surface.hpp"
#include "products/detail/surface_routing.hpp"

namespace dtm::products {
namespace {

namespace fs = std::filesystem;

/// Rank 0's staged output folder, known to every rank by its path.
class SharedStaging {
public:
    SharedStaging(dist::Comm& comm, const fs::path& out_dir) : comm_(comm) {
        const fs::path target = out_dir.filename().empty() ? out_dir.parent_path() : out_dir;
        detail::on_ranks(comm, comm.rank() == 0, [&] {
            io::check_output(target, io::OutputKind::folder, "out_dir");
            folder_.emplace(target);
        });
        const std::string mine = folder_ ? folder_->staging().string() : std::string();
        dist::Bytes bytes(reinterpret_cast<const std::byte*>(mine.data()),
                          reinterpret_cast<const std::byte*>(mine.data() + mine.size()));
        comm.bcast(bytes, 0);
        staging_ = std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    }
    /// Where the file @p name goes, not recorded.
    [[nodiscard]] fs::path at(const std::string& name) const { return staging_ / name; }
    /// Where the file @p name goes; recorded for the commit (rank 0).
    fs::path add(const std::string& name) {
        if (folder_) (void)folder_->add(name);
        return staging_ / name;
    }
    [[nodiscard]] std::vector<std::string> files() const {
        return folder_ ? folder_->files() : std::vector<std::string>{};
    }
    /// Collective: rank 0 moves the folder into place once every rank has reached here.
    void commit() {
        detail::on_ranks(comm_, comm_.rank() == 0, [&] { folder_->commit(); });
    }

private:
    dist::Comm& comm_;
    std::optional<io::AtomicDirectory> folder_;
    fs::path staging_;
};

/// Times the stages for the report (on rank 0's clock).
class Laps {
public:
    void lap(const char* stage) {
        const auto now = std::chrono::steady_clock::now();
        timings.push_back({stage, std::chrono::duration<double>(now - last_).count()});
        last_ = now;
    }
    std::vector<StageTime> timings;

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

/// surface-r-of-P.vtp on every rank with triangles, surface.pvtp over them (rank 0).
std::vector<fs::path> write_vtk_pieces(dist::Comm& comm,
                                       SharedStaging& out,
                                       const dist::SurfaceMesh& mine,
                                       const std::string& crs_wkt) {
    const int rank = comm.rank(), ranks = comm.size();
    std::vector<std::uint64_t> mine_count{mine.faces.size()};
    const auto counts = dist::concatenated<std::uint64_t>(
        comm.allgatherv(dist::to_bytes(std::span<const std::uint64_t>(mine_count))));
    std::vector<fs::path> pieces;
    for (int r = 0; r < ranks; ++r) {
        const fs::path piece = detail::piece_path("surface", r, ranks, "vtp");
        if (counts[static_cast<std::size_t>(r)] > 0) pieces.push_back(out.add(piece.string()));
    }
    detail::on_ranks(comm, !mine.faces.empty(), [&] {
        io::TinWriteOptions write;
        write.crs_wkt = crs_wkt;
        io::write_vtp(dist::surface_tin(mine),
                      out.add(detail::piece_path("surface", rank, ranks, "vtp")), write);
    });
    detail::on_ranks(comm, rank == 0, [&] { io::write_pvtp(out.add("surface.pvtp"), pieces); });
    return pieces;
}

void write_project(SharedStaging& out, const BuildReport& report) {
    io::QgisProject project = detail::build_project(report.crs_wkt, report.surface, report);
    project.title = "dtm build (distributed)";
    project.dem = "dem.vrt";
    project.hillshade = "hillshade.vrt";
    project.contours = "contours.vrt";
    io::write_qgis_project(project, out.add("dtm.qgs"));
}

}  // namespace

BuildReport distributed_build(dist::Comm& comm,
                              const DistributedBuildOptions& options,
                              const Progress& progress) {
    const auto worded = [&](std::string_view text) {
        return options.wording ? options.wording(text) : std::string(text);
    };
    Laps clock;
    SharedStaging out(comm, options.out_dir);
    detail::DistributedSurface surface =
        detail::distributed_surface(comm, options.source, progress.sub(0.0, 0.5));
    const DistributedCounts counts = detail::counts_of(comm, surface);
    if (counts.triangles == 0) {
        throw InputError(
            "build: the triangulation has no triangle (is everything outside the boundary?)");
    }
    clock.lap("read_triangulate");

    detail::report_progress(progress, 0.5, "writing the TIN");
    BuildReport report;
    report.crs_wkt = surface.crs_wkt;
    // One PLY, or beyond what a PLY indexes the tiled TIN tin.json and its tiles.
    const detail::TinFileWritten tin_file =
        detail::write_tin_file(comm, surface, out.at("tin.ply"), options.ply_limit);
    (void)out.add(tin_file.written.filename().string());
    for (const std::string& tile : tin_file.tiles) (void)out.add(tile);
    const std::uint64_t constrained = tin_file.constrained_edges;
    DistributedRun run;
    run.ranks = comm.size();
    run.survey_points = surface.points - surface.line_vertices;
    run.line_vertices = surface.line_vertices;
    run.merged = surface.points + surface.crossings - surface.merged.total_vertices;
    run.crossing_vertices = surface.crossings;
    run.band_triangles = static_cast<std::uint64_t>(comm.allreduce(
        static_cast<std::int64_t>(surface.kernel.stats.band_triangles), dist::Reduce::sum));
    run.widenings = static_cast<std::uint32_t>(comm.allreduce(
        static_cast<std::int64_t>(surface.kernel.stats.widenings), dist::Reduce::max));
    comm.set_phase("surface vertices");
    dist::SurfaceMesh mine = dist::surface_mesh(comm, surface.merged, std::move(surface.kernel));
    surface = {};  // the kernel's mesh is no longer needed
    report.surface = detail::distributed_surface_stats(comm, mine, counts.vertices,
                                                       counts.triangles, constrained);
    run.unused_vertices = counts.vertices - detail::used_vertex_count(comm, mine);
    report.skipped_lines = counts.skipped_lines;
    report.triangulation.intersections = counts.crossings;
    report.triangulation.removed_triangles = counts.removed_triangles;
    clock.lap("write_tin");

    detail::report_progress(progress, 0.6, "VTK pieces");
    (void)write_vtk_pieces(comm, out, mine, report.crs_wkt);
    clock.lap("vtk");

    const bool cell_given = options.cell > 0.0;
    const double cell = cell_given ? options.cell : default_cell(report.surface);
    report.cell_rule = cell_given ? worded("given (`cell`)") : default_cell_rule;
    report.dem = snapped_grid_spec(report.surface.extent, cell);
    const io::GridWriteOptions grid_write{.crs_wkt = report.crs_wkt};
    const fs::path dem_vrt = out.add("dem.vrt");
    const bool shows = comm.rank() == 0;
    detail::DemTiles tiles = detail::write_dem_tiles(comm, report.dem, mine, dem_vrt, grid_write,
                                                     shows ? progress.sub(0.65, 0.8) : Progress{});
    for (const fs::path& tile : tiles.tiles) (void)out.add(tile.filename().string());
    clock.lap("dem");
    comm.set_phase("hillshade");
    for (const fs::path& tile :
         detail::write_derivative_tiles(comm, report.dem, dem_vrt, out.add("hillshade.vrt"),
                                        io::DemDerivative::hillshade, report.crs_wkt)) {
        (void)out.add(tile.filename().string());
    }
    clock.lap("hillshade");

    const bool interval_given = options.interval > 0.0;
    ContourOptions contour;
    contour.interval = interval_given ? options.interval : default_interval(report.surface);
    contour.index_every = options.index_every;
    report.contour_interval = contour.interval;
    report.index_every = options.index_every;
    report.interval_rule = interval_given ? worded("given (`interval`)") : default_interval_rule;
    const std::vector<ContourLevel> levels =
        contour_levels(report.surface.z_min, report.surface.z_max, contour);
    report.contour_levels = levels.size();
    const fs::path contour_vrt = out.add("contours.vrt");
    detail::ContourPieces pieces =
        detail::write_contour_pieces(comm, std::move(mine), levels, contour, contour_vrt,
                                     {.crs_wkt = report.crs_wkt, .layer = "contours"},
                                     shows ? progress.sub(0.8, 0.95) : Progress{});
    for (const fs::path& piece : pieces.pieces) (void)out.add(piece.filename().string());
    report.contour_lines = pieces.lines;
    clock.lap("contours");

    run.bytes_sent = detail::bytes_sent(comm);
    run.phase_bytes = detail::phase_bytes(comm);
    report.distributed = std::move(run);
    detail::on_ranks(comm, comm.rank() == 0, [&] {
        write_project(out, report);
        clock.lap("project");
        report.timings = clock.timings;
        report.outputs = out.files();
        report.outputs.emplace_back("report.json");
        write_report(report, out.add("report.json"));
    });
    progress.report(0.99, "moving the products into place");
    out.commit();
    detail::report_progress(progress, 1.0, "done");
    return report;
}

}  // namespace dtm::products
