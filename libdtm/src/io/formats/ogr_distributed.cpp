// SPDX-License-Identifier: MIT
//
// The distributed OGR points reader (ogr_distributed.hpp): every rank opens the source, counts
// its features and reads its share through read_ogr's own loop (detail::read_ogr_range), which
// skips to the share's first feature with OGRLayer::SetNextByIndex (the shapefile and GeoPackage
// drivers seek; others step). The first error in file order wins: the smallest failing feature
// number, then the lowest rank (an error before any feature, such as a missing layer, is
// feature 0 and the same on every rank).
#include "io/formats/ogr_distributed.hpp"

#include <optional>

#include "dtm/core/error.hpp"
#include "io/detail/file_crs.hpp"
#include "io/formats/ogr_range.hpp"

namespace dtm::io {

DistributedPoints read_ogr_points_distributed(dist::Comm& comm,
                                              const InputFile& file,
                                              const ReadOptions& options,
                                              std::string& crs_wkt) {
    comm.set_phase("read");
    ReadResult result;
    std::optional<InputError> failure;
    detail::FeatureRange range;
    try {
        const std::uint64_t total = detail::ogr_feature_count(file, options);
        const auto r = static_cast<std::uint64_t>(comm.rank());
        const auto p = static_cast<std::uint64_t>(comm.size());
        range.first = r * total / p;
        range.last = (r + 1) * total / p;
        if (range.first < range.last) {
            result = detail::read_ogr_range(file, options, {}, range);
        } else {  // no feature here: the file's CRS only
            range.first = range.last = detail::FeatureRange::none - 1;
            result = detail::read_ogr_range(file, options, {}, range);
            range.failed_at = detail::FeatureRange::none;
        }
        detail::identify_file_crs(file, result);
    } catch (const InputError& e) {
        failure = e;
    }
    // A failing feature's order is its number + 1; an error before any feature is 0.
    const std::int64_t order = !failure ? INT64_MAX
                               : range.failed_at == detail::FeatureRange::none
                                   ? 0
                                   : static_cast<std::int64_t>(range.failed_at) + 1;
    elect_input_error(comm, file, failure ? &*failure : nullptr, order);
    const TerrainInput& t = result.terrain;
    const bool lines = !t.breaklines.empty() || !t.soft_breaklines.empty() ||
                       !t.boundaries.empty() || !t.holes.empty();
    if (comm.allreduce(lines ? 1 : 0, dist::Reduce::max) != 0) {
        throw UsageError(file.path.string() +
                         ": a distributed run (mpirun) does not take line or polygon features in "
                         "the points input yet (give them as a breaklines input)");
    }
    crs_wkt = result.crs_wkt;
    DistributedPoints out;
    out.points.reserve(t.points.size());
    for (const Point3& q : t.points) out.points.push_back({q, true});
    out.first_input =
        static_cast<std::uint64_t>(comm.exscan_sum(static_cast<std::int64_t>(out.points.size())));
    out.total = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(out.points.size()), dist::Reduce::sum));
    return out;
}

}  // namespace dtm::io
