// SPDX-License-Identifier: MIT
/// @file
/// @brief dtm's PLY TIN written by all ranks of a distributed run into one file (R-P1 of
/// docs/distributed.md), byte for byte the file write_tin_ply() writes for the same TIN.
#pragma once

#include <filesystem>

#include "dist/kernel.hpp"
#include "dtm/dist/duplicates.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::io {

/// Collective. The TIN of @p kernel (a triangulate_share of the vertices @p merged numbers, with
/// any constraint bits of insert_constraints) as a binary PLY at @p path: rank 0 writes the
/// header, every rank its vertices (input order) and its faces at their offsets, in the order
/// the serial TIN has them (slot order, the few hull-ghost slots filled by the last real
/// triangles: tin_build_triangles.cpp), rank 0 the constrained edges sorted as finish_tin sorts
/// them,
/// through Comm::open_shared (MPI-IO under MPI). Atomic: a temporary sibling renamed by rank 0
/// once every rank has written. @throws Error on every rank when any rank fails, or beyond 2^31
/// - 1 vertices or faces (a tiled TIN is not written yet).
/// @return the constrained edges written (the PLY `edge` element)
std::uint64_t write_distributed_ply(dist::Comm& comm,
                                    const dist::MergedShare& merged,
                                    const dist::DistributedMesh& kernel,
                                    const std::filesystem::path& path,
                                    const TinWriteOptions& options);

}  // namespace dtm::io
