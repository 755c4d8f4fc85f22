// SPDX-License-Identifier: MIT
//
// The distributed `dtm tin` for survey point lists (distributed_tin.hpp): the distributed
// surface (products/detail/distributed_surface) written as one PLY (io/formats/ply/
// ply_dist_writer).
#include "dtm/products/distributed_tin.hpp"

#include "io/formats/ply/ply_dist_writer.hpp"
#include "products/detail/distributed_surface.hpp"

namespace dtm::products {

DistributedTinResult distributed_tin(dist::Comm& comm,
                                     const DistributedTinOptions& options,
                                     const Progress& progress) {
    DistributedTinResult result;
    const detail::DistributedSurface surface =
        detail::distributed_surface(comm, options.source, progress.sub(0.0, 0.8));
    static_cast<DistributedCounts&>(result) = detail::counts_of(comm, surface);

    detail::report_progress(progress, 0.8, "writing");
    io::TinWriteOptions write;
    write.crs_wkt = surface.crs_wkt;
    result.constrained_edges =
        io::write_distributed_ply(comm, surface.merged, surface.kernel, options.output, write);
    result.bytes_sent = detail::bytes_sent(comm);
    result.band_triangles = static_cast<std::uint64_t>(comm.allreduce(
        static_cast<std::int64_t>(surface.kernel.stats.band_triangles), dist::Reduce::sum));
    result.widenings = static_cast<std::uint32_t>(comm.allreduce(
        static_cast<std::int64_t>(surface.kernel.stats.widenings), dist::Reduce::max));
    detail::report_progress(progress, 1.0, "done");
    return result;
}

}  // namespace dtm::products
