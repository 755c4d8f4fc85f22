// SPDX-License-Identifier: MIT
/// @file
/// @brief The tiled TIN written by all ranks of a distributed run (dtm/io/formats/tin_tiles.hpp,
/// R-P2 of docs/distributed.md): one PLY tile per rank and one manifest, which put together are
/// the TIN write_distributed_ply() writes as one file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dist/kernel.hpp"
#include "dtm/dist/duplicates.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::io {

struct TilesWritten {
    std::uint64_t constrained_edges = 0;
    std::vector<std::string> tiles;  ///< file names next to the manifest, in rank order
};

/// Collective. Every rank writes its tile next to @p manifest (temporary, then renamed), rank 0
/// then the manifest (temporary, then renamed: the one step that switches from an old tiled TIN
/// to the new one, whose tiles carry a new run token) and finally removes the tiles of the
/// manifest it replaced. @throws Error on every rank when any rank fails (with the lowest failing
/// rank's message); the tiles written are then removed and an old manifest stays as it was.
TilesWritten write_distributed_tiles(dist::Comm& comm,
                                     const dist::MergedShare& merged,
                                     const dist::DistributedMesh& kernel,
                                     const std::filesystem::path& manifest,
                                     const TinWriteOptions& options);

}  // namespace dtm::io
