// SPDX-License-Identifier: MIT
//
// The distributed `dtm tin` for survey point lists (distributed_tin.hpp): the steps of the serial
// flow (load_inputs -> triangulate -> write_tin), each over ranks:
//   read (io/formats/csv/csv_distributed) -> CRS as load_inputs gives it to a text file (the
//   default CRS; S-JTSK positive coordinates to Krovak East-North, point by point) -> exact
//   duplicates (dist/duplicates) -> the tree over ranks (dist/partition) -> the kernel over
//   ranks (dist/kernel) -> the serial degeneracy checks -> one PLY (io/formats/ply/
//   ply_dist_writer).
#include "dtm/products/distributed_tin.hpp"

#include "dist/kernel.hpp"
#include "dtm/core/error.hpp"
#include "dtm/dist/duplicates.hpp"
#include "dtm/dist/partition.hpp"
#include "dtm/io/formats/crs.hpp"
#include "io/formats/csv/csv_distributed.hpp"
#include "io/formats/ply/ply_dist_writer.hpp"

namespace dtm::products {
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

/// Progress on the ranks that show it; a stop request is agreed on by the steps' reductions.
void report(const Progress& progress, double fraction, const char* what) {
    try {
        progress.report(fraction, what);
    } catch (const Cancelled&) {
    }
}

}  // namespace

DistributedTinResult distributed_tin(dist::Comm& comm,
                                     const DistributedTinOptions& options,
                                     const Progress& progress) {
    DistributedTinResult result;
    result.ranks = comm.size();
    report(progress, 0.0, "reading");
    io::DistributedPoints read =
        io::read_text_points_distributed(comm, options.input, options.read);
    std::string crs_wkt;
    if (!options.default_crs.empty()) {
        try {
            crs_wkt = io::crs_to_wkt(options.default_crs);
        } catch (const UsageError& e) {
            throw OptionError("default_crs", "`default_crs`: " + std::string(e.what()));
        }
        if (io::crs_is_geographic(crs_wkt)) {
            throw UsageError(
                "a distributed run takes projected coordinates only (no UTM projection of "
                "geographic points yet)");
        }
        if (io::crs_is_sjtsk(crs_wkt)) {
            for (dist::InputPoint& p : read.points) io::sjtsk_to_east_north(p.p.x, p.p.y);
        }
    }
    result.points = read.total;
    result.skipped_lines = read.skipped_lines;

    report(progress, 0.2, "triangulating");
    const dist::MergedShare merged =
        dist::merge_exact_duplicates(comm, read.points, options.duplicates);
    std::vector<dist::InputPoint>().swap(read.points);
    std::vector<dist::Point> points;
    points.reserve(merged.vertices.size());
    for (const dist::Vertex& v : merged.vertices) points.push_back({v.p.x, v.p.y, v.id});
    const dist::Share share =
        dist::partition_points(comm, std::move(points), {}, progress.sub(0.2, 0.4));
    const dist::DistributedMesh kernel =
        dist::triangulate_share(comm, share, {}, progress.sub(0.4, 0.8));
    result.triangles = check_not_degenerate(comm, merged.total_vertices, kernel);
    result.vertices = merged.total_vertices;

    report(progress, 0.8, "writing");
    io::TinWriteOptions write;
    write.crs_wkt = crs_wkt;
    io::write_distributed_ply(comm, merged, kernel, options.output, write);
    std::int64_t bytes = 0;
    for (const auto& [phase, t] : comm.traffic()) bytes += static_cast<std::int64_t>(t.bytes);
    result.bytes_sent = static_cast<std::uint64_t>(comm.allreduce(bytes, dist::Reduce::sum));
    result.band_triangles = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(kernel.stats.band_triangles), dist::Reduce::sum));
    result.widenings = static_cast<std::uint32_t>(
        comm.allreduce(static_cast<std::int64_t>(kernel.stats.widenings), dist::Reduce::max));
    report(progress, 1.0, "done");
    return result;
}

}  // namespace dtm::products
