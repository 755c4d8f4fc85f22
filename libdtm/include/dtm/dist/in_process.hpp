// SPDX-License-Identifier: MIT
/// @file
/// @brief P virtual ranks in one process (one thread each): the distributed code without MPI.
#pragma once

#include <cstdint>
#include <functional>

#include "dtm/core/error.hpp"
#include "dtm/dist/comm.hpp"

namespace dtm::dist {

/// Thrown in the other ranks when one rank of an in-process run failed.
class Aborted : public Error {
public:
    Aborted() : Error("another rank failed") {}
};

struct InProcessOptions {
    unsigned jitter_microseconds = 0;  ///< see Comm::set_jitter
    std::uint64_t seed = 1;
};

/// Runs @p job on @p ranks virtual ranks, each on its own thread with its own Comm, and waits
/// for all. When ranks throw, rethrows the exception of the lowest rank that failed on its own
/// (not with Aborted). Collectives check that every rank is at the same call.
void run_in_process(int ranks,
                    const std::function<void(Comm&)>& job,
                    const InProcessOptions& options = {});

}  // namespace dtm::dist
