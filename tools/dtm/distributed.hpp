// SPDX-License-Identifier: MIT
/// @file
/// @brief The MPI job this process is a rank of, when started by `mpirun -np P dtm ...` (P > 1).
#pragma once

#include "dtm/algo/triangulate.hpp"
#include "dtm/dist/comm.hpp"
#include "dtm/products/distributed_tin.hpp"
#include "input_args.hpp"

namespace dtm::cli {

/// The job's communicator, or null when dtm runs on its own.
[[nodiscard]] dist::Comm* distributed_comm() noexcept;
void set_distributed_comm(dist::Comm* comm) noexcept;
/// True where messages and progress are printed: rank 0, or the only process.
[[nodiscard]] bool prints() noexcept;

/// One rank's share of its machine: @p cores (what this process may run on) divided among the
/// @p local_ranks of the job on that machine, at least one; @p cores when local_ranks is 0.
[[nodiscard]] unsigned threads_per_rank(unsigned cores, unsigned local_ranks) noexcept;
/// Bounds this rank's TBB threads to threads_per_rank (local ranks from
/// dist::launched_local_ranks) for the whole run, so that ranks sharing
/// a machine do not oversubscribe it (`--threads` may lower it further, not raise it).
void share_cores_among_local_ranks();

/// What a distributed run covers of the inputs and TIN options (one text point list or OGR point
/// source; breakline, soft breakline, boundary and hole files; the constrained Delaunay TIN with
/// its domain and `max_edge`, without `snap`, optimisation, flat areas, CRS change or DEM
/// thinning). @throws UsageError "COMMAND: a distributed run (mpirun) does not take ... yet"
void check_distributed_input(const char* command,
                             const InputArgs& in,
                             const TriangulateOptions& triangulate);

/// The distributed products' source: the point list, the breakline files and the TIN options
/// they read (after check_distributed_input).
[[nodiscard]] products::DistributedSource distributed_source(const InputArgs& in,
                                                             const TriangulateOptions& triangulate);

}  // namespace dtm::cli
