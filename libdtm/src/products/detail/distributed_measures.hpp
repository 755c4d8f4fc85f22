// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: the measures of a distributed TIN that the serial build takes of its Tin
/// (surface_stats, the vertices no triangle names, the traffic per phase), from the ranks'
/// meshes, exactly: the same numbers on every rank count.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dist/mesh_vertices.hpp"
#include "dtm/algo/surface_stats.hpp"
#include "dtm/dist/comm.hpp"

namespace dtm::products::detail {

/// Collective: surface_stats() of the TIN whose real triangles the ranks hold in @p mine
/// (every triangle on one rank): the extent and z range as exact minima and maxima, the areas
/// as exact sums of the serial terms (relative to the serial TIN's first triangle's first
/// corner). The counts are given (they are known from the run).
[[nodiscard]] SurfaceStats distributed_surface_stats(dist::Comm& comm,
                                                     const dist::SurfaceMesh& mine,
                                                     std::uint64_t vertex_count,
                                                     std::uint64_t triangle_count,
                                                     std::uint64_t constraint_count);

/// Collective: how many distinct vertices the triangles of all ranks name.
[[nodiscard]] std::uint64_t used_vertex_count(dist::Comm& comm, const dist::SurfaceMesh& mine);

/// Collective: the bytes all ranks sent, per phase (in name order).
[[nodiscard]] std::vector<std::pair<std::string, std::uint64_t>> phase_bytes(dist::Comm& comm);

}  // namespace dtm::products::detail
