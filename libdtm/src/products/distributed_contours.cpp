// SPDX-License-Identifier: MIT
//
// The distributed contours (distributed_contours.hpp). After the distributed surface:
//   1. every rank lists its real triangles and their vertices (dist::surface_mesh), each
//      triangle with its index in the serial TIN;
//   2. the exact height range over the ranks (one allgather of two numbers, no arithmetic) gives
//      the serial levels, the same list on every rank; the levels are cut into P ranges of
//      about equal numbers of crossed triangles (one int64 allreduce of the counts per level);
//   3. a triangle is crossed by the levels k with lo <= k < hi, lo and hi the least and greatest
//      count of levels at or below a corner (the serial bucketing's rule), and goes to the ranks
//      owning one of them (route_faces: vertices once per destination);
//   4. each rank rebuilds a Tin in the serial orders (vertices by number, triangles by serial
//      index, links across the edges it received) and traces its levels with
//      contour_level_range: a line of level k crosses only triangles level k crosses, and the
//      triangle across each edge it crosses is crossed too, so the rank holds the whole line and
//      traces it as the serial run does (the tracer compares triangle indices only, whose order is
//      kept);
//   5. the lines go to the rank's GeoPackage (io::ContourWriter, atomic), then rank 0 writes the
//      OGR VRT (io::write_contour_vrt), pieces in level order: read through it, the layer is
//      the serial one feature for feature.
#include "dtm/products/distributed_contours.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "dist/mesh_vertices.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/contour_writer.hpp"
#include "products/detail/distributed_pieces.hpp"
#include "products/detail/distributed_surface.hpp"
#include "products/detail/surface_routing.hpp"

namespace dtm::products {
namespace {

/// The levels [lo, hi) that cross face @p f: lo and hi are the least and greatest count of levels
/// at or below one of its corners (the serial bucketing's rule).
std::pair<std::size_t, std::size_t> crossed_levels(const std::vector<double>& values,
                                                   const dist::SurfaceFace& f,
                                                   const std::vector<dist::SurfaceVertex>& v) {
    std::size_t lo = values.size(), hi = 0;
    for (const std::uint32_t corner : f.v) {
        const auto at = static_cast<std::size_t>(
            std::upper_bound(values.begin(), values.end(), v[corner].p.z) - values.begin());
        lo = std::min(lo, at);
        hi = std::max(hi, at);
    }
    return {lo, hi};
}

/// The first level of every rank's range and the end (P + 1 numbers): ranges of about equal
/// numbers of crossed triangles over all ranks (integer sums, the same on every rank); a rank
/// may get no level when one level crosses more than its share.
std::vector<std::size_t> level_ranges(dist::Comm& comm,
                                      const std::vector<double>& values,
                                      const dist::SurfaceMesh& surface) {
    std::vector<std::int64_t> crossings(values.size() + 1, 0);  // differences, then counts
    for (const dist::SurfaceFace& f : surface.faces) {
        const auto [lo, hi] = crossed_levels(values, f, surface.vertices);
        if (lo >= hi) continue;
        ++crossings[lo];
        --crossings[hi];
    }
    for (std::size_t k = 1; k < crossings.size(); ++k) crossings[k] += crossings[k - 1];
    comm.allreduce(std::span<std::int64_t>(crossings), dist::Reduce::sum);
    std::int64_t total = 0;
    for (std::size_t k = 0; k < values.size(); ++k) total += crossings[k];
    const auto ranks = static_cast<std::int64_t>(comm.size());
    std::vector<std::size_t> starts{0};
    std::int64_t before = 0;  // crossings of the levels below k
    std::size_t k = 0;
    for (std::int64_t r = 1; r < ranks; ++r) {
        // Rank r starts at the first level whose crossings' midpoint lies at or after r / P of
        // the total: (before + crossings / 2) P >= r total.
        while (k < values.size() && (2 * before + crossings[k]) * ranks < 2 * r * total) {
            before += crossings[k++];
        }
        starts.push_back(k);
    }
    starts.push_back(values.size());
    return starts;
}

/// Every face goes to the ranks owning a level that crosses it.
Tin route_to_level_ranges(dist::Comm& comm,
                          const std::vector<double>& values,
                          const std::vector<std::size_t>& starts,
                          dist::SurfaceMesh surface) {
    const auto owner = [&](std::size_t k) {  // the last rank whose range starts at or before k
        return static_cast<std::size_t>(std::upper_bound(starts.begin(), starts.end(), k) -
                                        starts.begin()) -
               1;
    };
    const auto destinations = [&](const dist::SurfaceFace& f,
                                  const std::vector<dist::SurfaceVertex>& vertices) {
        const auto [lo, hi] = crossed_levels(values, f, vertices);
        if (lo >= hi) return detail::RankRange{};
        return detail::RankRange{owner(lo), owner(hi - 1)};
    };
    comm.set_phase("contour triangles");
    return detail::route_faces(comm, std::move(surface), destinations, detail::Links::shared_edges);
}

}  // namespace

std::filesystem::path contour_piece_path(const std::filesystem::path& vrt, int rank, int ranks) {
    return detail::piece_path(vrt, rank, ranks, "gpkg");
}

namespace detail {

std::pair<double, double> height_range(dist::Comm& comm, const dist::SurfaceMesh& mine) {
    const double inf = std::numeric_limits<double>::infinity();
    double lo = inf, hi = -inf;
    for (const dist::SurfaceVertex& v : mine.vertices) {
        lo = std::min(lo, v.p.z);
        hi = std::max(hi, v.p.z);
    }
    std::vector<double> values;
    if (!mine.vertices.empty()) values = {lo, hi};
    const auto all = dist::concatenated<double>(
        comm.allgatherv(dist::to_bytes(std::span<const double>(values))));
    lo = inf, hi = -inf;
    for (std::size_t i = 0; i + 1 < all.size(); i += 2) {
        lo = std::min(lo, all[i]);
        hi = std::max(hi, all[i + 1]);
    }
    return {lo, hi};
}

ContourPieces write_contour_pieces(dist::Comm& comm,
                                   dist::SurfaceMesh mine,
                                   const std::vector<ContourLevel>& levels,
                                   const ContourOptions& options,
                                   const std::filesystem::path& vrt,
                                   const io::ContourWriteOptions& write,
                                   const Progress& progress) {
    std::vector<double> values;
    for (const ContourLevel& l : levels) values.push_back(l.value);
    const std::vector<std::size_t> starts = level_ranges(comm, values, mine);
    const Tin tin = route_to_level_ranges(comm, values, starts, std::move(mine));

    const int rank = comm.rank(), ranks = comm.size();
    const auto at = [](int r) { return static_cast<std::size_t>(r); };
    const std::size_t first = starts[at(rank)], last = starts[at(rank) + 1];
    // Ranks with levels write a piece; with no level at all, rank 0 writes the empty layer.
    const auto writes = [&](int r) {
        return starts[at(r)] < starts[at(r) + 1] || (levels.empty() && r == 0);
    };
    std::uint64_t lines = 0;
    on_ranks(comm, writes(rank), [&] {
        io::ContourWriter writer(contour_piece_path(vrt, rank, ranks), write);
        contour_level_range(tin, levels, first, last, options, writer, progress);
        writer.commit();
        lines = writer.feature_count();
    });
    ContourPieces result;
    result.lines = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(lines), dist::Reduce::sum));
    for (int r = 0; r < ranks; ++r) {
        if (writes(r)) result.pieces.push_back(contour_piece_path(vrt, r, ranks));
    }
    on_ranks(comm, rank == 0, [&] { io::write_contour_vrt(vrt, result.pieces, write); });
    return result;
}

}  // namespace detail

DistributedContourResult distributed_contours(dist::Comm& comm,
                                              const DistributedContourOptions& options,
                                              const Progress& progress) {
    if (options.contour.surface != Interpolation::linear) {
        throw UsageError("contour: distributed contours follow the linear surface only");
    }
    DistributedContourResult result;
    detail::DistributedSurface surface =
        detail::distributed_surface(comm, options.source, progress.sub(0.0, 0.6));
    static_cast<DistributedCounts&>(result) = detail::counts_of(comm, surface);

    detail::report_progress(progress, 0.6, "tracing");
    comm.set_phase("contour vertices");
    dist::SurfaceMesh mine = dist::surface_mesh(comm, surface.merged, std::move(surface.kernel));
    const io::ContourWriteOptions write{.crs_wkt = std::move(surface.crs_wkt),
                                        .layer = options.layer};
    surface = {};  // the kernel's mesh is no longer needed
    const auto [zmin, zmax] = detail::height_range(comm, mine);
    const std::vector<ContourLevel> levels = contour_levels(zmin, zmax, options.contour);
    result.levels = levels.size();
    detail::ContourPieces pieces = detail::write_contour_pieces(
        comm, std::move(mine), levels, options.contour, options.output, write,
        comm.rank() == 0 ? progress.sub(0.7, 0.95) : Progress{});
    result.lines = pieces.lines;
    result.pieces = std::move(pieces.pieces);
    result.bytes_sent = detail::bytes_sent(comm);
    detail::report_progress(progress, 1.0, "done");
    return result;
}

}  // namespace dtm::products
