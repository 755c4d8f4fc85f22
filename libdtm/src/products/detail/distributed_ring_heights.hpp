// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: heights of 2-D boundary and hole vertices that lie on no survey point, in a
/// distributed run, from a first surface of the points and hard breaklines (resolve_line_heights
/// step 2, built on all ranks).
#pragma once

#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/dist/comm.hpp"
#include "dtm/products/distributed_tin.hpp"

namespace dtm::products::detail {

/// Whether some boundary or hole vertex of @p lines has no height yet.
[[nodiscard]] bool rings_lack_heights(const TerrainInput& lines);

/// Collective: gives every boundary and hole vertex of @p lines without a height the height of
/// the TIN of @p source's points and its breaklines alone (built as the serial step builds it:
/// the `first` duplicate rule, no domain), linear on its triangles, the nearest vertex's beyond
/// its hull (the lowest vertex number of equally near ones), as SurfaceSampler gives it.
/// @p points: the input's point count. @throws InputError as the serial step.
void ring_heights_from_surface(dist::Comm& comm,
                               const DistributedSource& source,
                               std::uint64_t points,
                               TerrainInput& lines,
                               const Progress& progress);

}  // namespace dtm::products::detail
