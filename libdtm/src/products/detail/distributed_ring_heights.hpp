// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: heights from a first surface in a distributed run: of 2-D boundary and hole
/// vertices that lie on no survey point (resolve_line_heights step 2) and of soft breakline
/// vertices (triangulate's first pass), the first surface built on all ranks.
#pragma once

#include <span>
#include <vector>

#include "dist/constraints.hpp"
#include "dist/mesh_vertices.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/dist/comm.hpp"
#include "dtm/dist/duplicates.hpp"
#include "dtm/products/distributed_tin.hpp"

namespace dtm::products::detail {

/// Collective: the heights SurfaceSampler::height_or_nearest gives at @p at (the same list on
/// every rank) on the TIN whose real triangles the ranks hold, @p mine on this rank (vertices
/// in ascending number, corners as in the serial TIN): linear inside, beyond the hull the
/// nearest vertex's z (of equally near ones the lowest number), the same bits as serially.
[[nodiscard]] std::vector<double> heights_on_surface(dist::Comm& comm,
                                                     const dist::SurfaceMesh& mine,
                                                     std::span<const Point2> at);

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

/// Collective, after place_lines: gives the merged vertices without a height (a soft line's
/// alone) the height of the TIN of the others with the segments that are not soft, as
/// triangulate() does serially (no domain), by heights_on_surface. Before keep_heights().
void soft_heights_from_surface(dist::Comm& comm,
                               dist::MergedShare& merged,
                               const std::vector<dist::GlobalSegment>& segments,
                               const Progress& progress);

}  // namespace dtm::products::detail
