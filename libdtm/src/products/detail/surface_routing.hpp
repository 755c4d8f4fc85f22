// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: the TIN's real triangles sent to the ranks that make a product from them
/// (row blocks of a DEM, level ranges of contours), rebuilt there as a Tin.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <vector>

#include "dist/mesh_vertices.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/dist/comm.hpp"

namespace dtm::products::detail {

/// Ranks first..last (none when first > last).
struct RankRange {
    std::size_t first = 1, last = 0;
};

/// How the received triangles are linked: only whether an edge is on the TIN's border (a
/// neighbour link of no_triangle there and 0 elsewhere: what rasterize reads), or to the
/// received triangles across their edges (link_neighbours: what contour tracing walks).
enum class Links { border_only, shared_edges };

/// The ranks a face goes to, given the vertices its corners index.
using Destinations =
    std::function<RankRange(const dist::SurfaceFace&, const std::vector<dist::SurfaceVertex>&)>;

/// Collective: sends every face of @p surface to the ranks @p destinations gives it, with the
/// vertices it names indexed per destination (a vertex once per destination unless its faces
/// alternate between destinations; the receiver merges repeats by number), and returns the Tin
/// of what this rank received: vertices once each in ascending number (the serial TIN's order),
/// triangles in the serial TIN's order with its corners.
[[nodiscard]] Tin route_faces(dist::Comm& comm,
                              dist::SurfaceMesh surface,
                              const Destinations& destinations,
                              Links links);

/// The piece of rank @p rank of @p ranks beside @p target: "<stem>-<rank>-of-<ranks>.<extension>".
[[nodiscard]] std::filesystem::path piece_path(const std::filesystem::path& target,
                                               int rank,
                                               int ranks,
                                               const char* extension);

}  // namespace dtm::products::detail
