// SPDX-License-Identifier: MIT
//
// The steps of the serial flow up to the TIN (load_inputs -> triangulate), each over ranks:
//   read (io/formats/csv/csv_distributed) -> CRS as load_inputs gives it to a text file (the
//   default CRS; S-JTSK positive coordinates to Krovak East-North, point by point) -> exact
//   duplicates (dist/duplicates) -> the tree over ranks (dist/partition) -> the kernel over
//   ranks (dist/kernel) -> the serial degeneracy checks.
#include "products/detail/distributed_surface.hpp"

#include <cstdint>
#include <optional>
#include <span>

#include "dist/constraints.hpp"
#include "dist/domain.hpp"
#include "dtm/core/error.hpp"
#include "dtm/dist/partition.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/reader.hpp"
#include "io/formats/csv/csv_distributed.hpp"
#include "io/formats/ogr_distributed.hpp"
#include "products/detail/distributed_lines.hpp"
#include "products/detail/distributed_ring_heights.hpp"

namespace dtm::products::detail {
namespace {

/// triangulate()'s refusals of degenerate input, with its messages, decided on every rank.
/// @return the triangles of the TIN over all ranks.
std::uint64_t check_not_degenerate(dist::Comm& comm,
                                   std::uint64_t vertices,
                                   const dist::DistributedMesh& k) {
    if (vertices < 3) {
        throw InputError("triangulation needs at least 3 distinct points; the input has " +
                         std::to_string(vertices));
    }
    const auto triangles = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(k.mesh.real_triangles()), dist::Reduce::sum));
    if (triangles == 0) {
        throw InputError("all " + std::to_string(vertices) +
                         " distinct points are collinear: there is no surface to triangulate");
    }
    return triangles;
}

}  // namespace

void report_progress(const Progress& progress, double fraction, const char* what) {
    try {
        progress.report(fraction, what);
    } catch (const Cancelled&) {
    }
}

std::uint64_t bytes_sent(dist::Comm& comm) {
    std::int64_t bytes = 0;
    for (const auto& [phase, t] : comm.traffic()) bytes += static_cast<std::int64_t>(t.bytes);
    return static_cast<std::uint64_t>(comm.allreduce(bytes, dist::Reduce::sum));
}

Box2 box_over_ranks(dist::Comm& comm, const Box2& mine) {
    std::vector<double> values;
    if (!mine.empty()) values = {mine.xmin, mine.ymin, mine.xmax, mine.ymax};
    const auto all = dist::concatenated<double>(
        comm.allgatherv(dist::to_bytes(std::span<const double>(values))));
    Box2 whole;
    for (std::size_t i = 0; i + 3 < all.size(); i += 4) {
        whole.add(all[i], all[i + 1]);
        whole.add(all[i + 2], all[i + 3]);
    }
    return whole;
}

namespace {

/// This rank's run of the input's points, in the CRS the serial load_inputs gives them; that
/// CRS (`target_crs`, else the file's or the default) in @p crs_wkt.
io::DistributedPoints read_points(dist::Comm& comm,
                                  const DistributedSource& source,
                                  std::string& crs_wkt,
                                  std::optional<io::UtmZone>& utm) {
    // Text point lists by byte ranges, OGR sources by feature ranges; the file's CRS first.
    crs_wkt.clear();
    const std::string_view reader = io::find_reader(source.input.path).name;
    io::DistributedPoints read =
        reader == "ogr" || reader == "csv-wkt"
            ? io::read_ogr_points_distributed(comm, source.input, source.read, crs_wkt)
            : io::read_text_points_distributed(comm, source.input, source.read);
    if (crs_wkt.empty()) crs_wkt = read.crs_wkt;
    if (crs_wkt.empty() && !source.default_crs.empty()) {
        try {
            crs_wkt = io::crs_to_wkt(source.default_crs);
        } catch (const UsageError& e) {
            throw OptionError("default_crs", "`default_crs`: " + std::string(e.what()));
        }
    }
    if (!crs_wkt.empty() && io::crs_is_sjtsk(crs_wkt)) {
        for (dist::InputPoint& p : read.points) io::sjtsk_to_east_north(p.p.x, p.p.y);
    }
    if (!source.target_crs.empty()) {  // the serial load's step 3, position by position
        const std::string target = io::target_crs_wkt(source.target_crs);
        if (!crs_wkt.empty() && !io::crs_equivalent(crs_wkt, target)) {
            on_ranks(comm, true, [&] {
                const io::PositionTransform transform(crs_wkt, target, source.input.path.string());
                for (dist::InputPoint& p : read.points) transform(p.p.x, p.p.y);
            });
        }
        crs_wkt = target;
    } else if (!crs_wkt.empty() && io::crs_is_geographic(crs_wkt)) {
        // The serial load's UTM zone: that of the centre of the points' box (exact over ranks),
        // each position projected by GeographicLib (from WGS 84, transformed to it first).
        Box2 mine;
        for (const dist::InputPoint& p : read.points) mine.add(p.p);
        const Box2 box = box_over_ranks(comm, mine);
        utm = io::utm_zone_for((box.xmin + box.xmax) / 2.0, (box.ymin + box.ymax) / 2.0);
        on_ranks(comm, true, [&] {
            const std::string name = source.input.path.string();
            std::optional<io::PositionTransform> to_wgs84;
            if (!io::crs_is_wgs84_like(crs_wkt)) {
                to_wgs84.emplace(crs_wkt, io::crs_to_wkt("EPSG:4326"), name);
            }
            for (dist::InputPoint& p : read.points) {
                if (to_wgs84) (*to_wgs84)(p.p.x, p.p.y);
                io::project_position_to_utm(p.p.x, p.p.y, *utm, name);
            }
        });
        crs_wkt = io::crs_to_wkt("EPSG:" + std::to_string(utm->epsg()));
    }
    return read;
}

}  // namespace

DistributedSurface distributed_surface(dist::Comm& comm,
                                       const DistributedSource& source,
                                       const Progress& progress) {
    DistributedSurface out;
    std::optional<io::UtmZone> utm;  // geographic points without target_crs: their UTM zone
    report_progress(progress, 0.0, "reading");
    io::DistributedPoints read = read_points(comm, source, out.crs_wkt, utm);
    out.points = read.total;
    out.skipped_lines = read.skipped_lines;
    // Breakline vertices follow the points in the merge (the last rank holds the last inputs).
    TerrainInput line_files;
    on_ranks(comm, true, [&] { line_files = read_distributed_lines(source, out.crs_wkt, utm); });
    distributed_line_heights(comm, read.points, line_files);
    Progress rest = progress;
    if (rings_lack_heights(line_files)) {  // serial step 2: a first surface without the rings
        std::vector<dist::InputPoint>().swap(read.points);  // read again after it
        ring_heights_from_surface(comm, source, out.points, line_files, progress.sub(0.0, 0.5));
        read = read_points(comm, source, out.crs_wkt, utm);
        rest = progress.sub(0.5, 1.0);
    }
    DistributedLines loaded;
    on_ranks(comm, true, [&] { loaded = combine_lines(line_files); });
    line_files = {};
    ::dtm::detail::CombinedInput& lines = loaded.combined;
    const std::uint64_t first_line_input = read.points.size();
    if (comm.rank() == comm.size() - 1) {
        for (std::size_t i = 0; i < lines.points.size(); ++i) {
            read.points.push_back({lines.points[i], lines.z_known[i]});
        }
    }
    report_progress(rest, 0.25, "triangulating");
    out.merged = dist::merge_exact_duplicates(comm, read.points, source.duplicates);
    std::vector<dist::InputPoint>().swap(read.points);
    const PlacedLines placed =
        place_lines(comm, out.merged, lines, first_line_input, source.z_tolerance);
    std::vector<std::uint64_t>().swap(out.merged.vertex_of_input);  // the lines were its last use
    out.segments = placed.segments.size();
    out.crossings = placed.crossings;
    std::int64_t unknown = 0;  // soft breakline vertices without heights: a first surface
    for (const dist::Vertex& v : out.merged.vertices) unknown += v.z_known ? 0 : 1;
    if (comm.allreduce(unknown, dist::Reduce::sum) > 0) {
        soft_heights_from_surface(comm, out.merged, placed.segments, rest.sub(0.25, 0.5));
        rest = rest.sub(0.5, 1.0);
    }
    out.line_vertices = lines.points.size();  // every rank holds the lines
    out.points += out.line_vertices;
    lines = {};
    std::vector<dist::Point> points;
    points.reserve(out.merged.vertices.size());
    for (const dist::Vertex& v : out.merged.vertices) points.push_back({v.p.x, v.p.y, v.id});
    out.merged.keep_heights();  // the kernel's positions hold x and y from here on
    dist::Share share = dist::partition_points(comm, std::move(points), {}, rest.sub(0.25, 0.5));
    out.kernel = dist::triangulate_share(comm, std::move(share), {}, rest.sub(0.5, 0.9));
    out.triangles = check_not_degenerate(comm, out.merged.total_vertices, out.kernel);
    if (!placed.segments.empty()) {
        dist::insert_constraints(comm, out.kernel, placed.segments, rest.sub(0.9, 1.0));
    }
    out.removed_triangles =
        dist::apply_distributed_domain(comm, out.kernel, loaded.has_boundary, rest).removed;
    out.removed_triangles += dist::remove_hole_seeds(comm, out.kernel, loaded.hole_seeds, rest);
    if (source.max_edge > 0.0) {
        out.removed_triangles +=
            dist::trim_distributed_long_edges(comm, out.kernel, source.max_edge, rest);
    }
    if (out.removed_triangles == out.triangles) {
        throw InputError("no triangle is left inside the boundary and outside the holes");
    }
    out.triangles -= out.removed_triangles;
    return out;
}

DistributedCounts counts_of(const dist::Comm& comm, const DistributedSurface& surface) {
    DistributedCounts counts;
    counts.ranks = comm.size();
    counts.points = surface.points;
    counts.skipped_lines = surface.skipped_lines;
    counts.vertices = surface.merged.total_vertices;
    counts.crossings = surface.crossings;
    counts.removed_triangles = surface.removed_triangles;
    counts.triangles = surface.triangles;
    return counts;
}

void on_ranks(dist::Comm& comm, bool here, const std::function<void()>& step) {
    enum Kind : std::int64_t { none, error, usage, input, cancelled };
    std::string message;
    std::int64_t kind = none;
    if (here) {
        try {
            step();
        } catch (const Cancelled& e) {
            kind = cancelled;
            message = e.what();
        } catch (const InputError& e) {
            kind = input;
            message = e.what();
        } catch (const UsageError& e) {
            kind = usage;
            message = e.what();
        } catch (const Error& e) {
            kind = error;
            message = e.what();
        }
    }
    if (comm.allreduce(kind != none ? 1 : 0, dist::Reduce::max) == 0) return;
    // The lowest failing rank's message and kind (its exit code) on every rank.
    const std::int64_t first =
        comm.allreduce(kind != none ? comm.rank() : INT64_MAX, dist::Reduce::min);
    const std::int64_t first_kind =
        comm.allreduce(comm.rank() == first ? kind : none, dist::Reduce::max);
    try {
        dist::throw_first_error(comm, message);
    } catch (const Error& e) {
        if (first_kind == cancelled) throw Cancelled();
        if (first_kind == input) throw InputError(e.what());
        if (first_kind == usage) throw UsageError(e.what());
        throw;
    }
}

}  // namespace dtm::products::detail
