// SPDX-License-Identifier: MIT
//
// The distributed `dtm tin` for survey point lists (distributed_tin.hpp): the distributed
// surface (products/detail/distributed_surface) written as one PLY (io/formats/ply/
// ply_dist_writer), or as a tiled TIN (io/formats/tin_tiles/tiles_dist_writer) when asked for
// or when one PLY cannot index it.
#include "dtm/products/distributed_tin.hpp"

#include "dtm/io/extension.hpp"
#include "io/formats/ply/ply_dist_writer.hpp"
#include "io/formats/tin_tiles/tiles_dist_writer.hpp"
#include "products/detail/distributed_surface.hpp"

namespace dtm::products {

detail::TinFileWritten detail::write_tin_file(dist::Comm& comm,
                                              const DistributedSurface& surface,
                                              const std::filesystem::path& output,
                                              std::uint64_t ply_limit) {
    io::TinWriteOptions write;
    write.crs_wkt = surface.crs_wkt;
    TinFileWritten out;
    out.written = output;
    const bool too_big = surface.merged.total_vertices > ply_limit || surface.triangles > ply_limit;
    if (io::lower_extension(output) != "json" && !too_big) {
        out.constrained_edges =
            io::write_distributed_ply(comm, surface.merged, surface.kernel, output, write);
        return out;
    }
    out.written.replace_extension(".json");
    io::TilesWritten tiles =
        io::write_distributed_tiles(comm, surface.merged, surface.kernel, out.written, write);
    out.tiles = std::move(tiles.tiles);
    out.constrained_edges = tiles.constrained_edges;
    return out;
}

DistributedTinResult distributed_tin(dist::Comm& comm,
                                     const DistributedTinOptions& options,
                                     const Progress& progress) {
    DistributedTinResult result;
    const detail::DistributedSurface surface =
        detail::distributed_surface(comm, options.source, progress.sub(0.0, 0.8));
    static_cast<DistributedCounts&>(result) = detail::counts_of(comm, surface);

    detail::report_progress(progress, 0.8, "writing");
    detail::TinFileWritten written =
        detail::write_tin_file(comm, surface, options.output, options.ply_limit);
    result.written = std::move(written.written);
    result.tiles = std::move(written.tiles);
    result.constrained_edges = written.constrained_edges;
    result.bytes_sent = detail::bytes_sent(comm);
    result.band_triangles = static_cast<std::uint64_t>(comm.allreduce(
        static_cast<std::int64_t>(surface.kernel.stats.band_triangles), dist::Reduce::sum));
    result.widenings = static_cast<std::uint32_t>(comm.allreduce(
        static_cast<std::int64_t>(surface.kernel.stats.widenings), dist::Reduce::max));
    detail::report_progress(progress, 1.0, "done");
    return result;
}

}  // namespace dtm::products
