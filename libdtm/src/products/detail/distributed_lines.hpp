// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: hard breaklines in a distributed run, as the serial flow takes them (the
/// vertices after the points in the merge, the segments split at their crossings), replicated
/// on every rank.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algo/detail/input_merge.hpp"
#include "dist/constraints.hpp"
#include "dtm/dist/duplicates.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/products/distributed_tin.hpp"

namespace dtm::products::detail {

struct DistributedLines {
    ::dtm::detail::CombinedInput combined;
    bool has_boundary = false;
    std::vector<Point2> hole_seeds;  ///< points of the hole files
};

/// Every rank: the breakline, soft breakline, boundary and hole files read by the serial readers
/// into @p crs_wkt (the points' CRS; empty: as they come), or into the UTM zone @p utm the
/// points' geographic positions chose. @throws InputError (the readers' messages); UsageError
/// for points in those files (not taken by a distributed run yet)
[[nodiscard]] TerrainInput read_distributed_lines(const DistributedSource& source,
                                                  const std::string& crs_wkt,
                                                  std::optional<io::UtmZone> utm);

/// Collective: the heights of 2-D line vertices from the survey points at the same position,
/// the first in input order over all ranks (@p mine: this rank's run of the input, in order),
/// as resolve_line_heights() step 1 (boundary and hole vertices on none are left to
/// ring_heights_from_surface). @throws InputError on every rank, as the serial run, for a
/// breakline vertex on no survey point
void distributed_line_heights(dist::Comm& comm,
                              std::span<const dist::InputPoint> mine,
                              TerrainInput& lines);

/// Every rank: the lines' vertices and segments numbered from 0 in the serial order.
[[nodiscard]] DistributedLines combine_lines(const TerrainInput& lines);

struct PlacedLines {
    std::vector<dist::GlobalSegment> segments;  ///< vertex numbers, split at crossings
    std::uint64_t crossings = 0;                ///< vertices added at crossings
};

/// Collective, after merge_exact_duplicates of the points followed by lines.points on the last
/// rank (its local inputs from @p first_line_input): the segments in vertex numbers, split as
/// split_segments splits them; the crossing vertices are appended to the last rank's vertices
/// (numbered after all others) and merged.total_vertices grows on every rank.
/// @throws Error on every rank when the split's rounds run out
[[nodiscard]] PlacedLines place_lines(dist::Comm& comm,
                                      dist::MergedShare& merged,
                                      const ::dtm::detail::CombinedInput& lines,
                                      std::uint64_t first_line_input,
                                      double z_tolerance);

}  // namespace dtm::products::detail
