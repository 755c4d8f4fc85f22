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

/// What a distributed run covers of the inputs and TIN options (one text point list and hard
/// breakline files, the constrained Delaunay TIN without domain or optimisation). @throws
/// UsageError "COMMAND: a distributed run (mpirun) does not take ... yet"
void check_distributed_input(const char* command,
                             const InputArgs& in,
                             const TriangulateOptions& triangulate);

/// The distributed products' source: the point list, the breakline files and the TIN options
/// they read (after check_distributed_input).
[[nodiscard]] products::DistributedSource distributed_source(const InputArgs& in,
                                                             const TriangulateOptions& triangulate);

}  // namespace dtm::cli
