// SPDX-License-Identifier: MIT
/// @file
/// @brief The MPI backend of dist::Comm (built with DTM_WITH_MPI, Open MPI's C API).
#pragma once

#include <memory>

#include "dtm/dist/comm.hpp"

namespace dtm::dist {

/// Whether this build has the MPI backend.
[[nodiscard]] bool mpi_built() noexcept;

/// The number of ranks the process was launched with by mpirun/srun (OMPI_COMM_WORLD_SIZE,
/// PMI_SIZE, PMIX_SIZE), 0 when it was not launched by one.
[[nodiscard]] int launched_ranks() noexcept;
/// The job's ranks on this machine as the launcher says (Open MPI's OMPI_COMM_WORLD_LOCAL_SIZE,
/// MPICH's MPI_LOCALNRANKS), 0 when it does not.
[[nodiscard]] int launched_local_ranks() noexcept;

/// MPI for the lifetime of the object (MPI_Init_thread with MPI_THREAD_FUNNELED: TBB threads
/// compute, the main thread communicates) and the world communicator as a Comm.
/// @throws Error when the build has no MPI backend or MPI fails to start.
class MpiSession {
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    [[nodiscard]] Comm& world() noexcept;
    /// Ends every rank of the job with @p code (after an error seen by this rank only).
    [[noreturn]] void abort(int code) noexcept;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace dtm::dist
