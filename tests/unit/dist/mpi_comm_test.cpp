// SPDX-License-Identifier: MIT
// What the launcher's environment says of the job (dist/mpi_comm.hpp), with or without MPI built.
#include "dtm/dist/mpi_comm.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

namespace dtm::dist {
namespace {

TEST(LaunchedRanks, LocalRanksComeFromTheLaunchersEnvironment) {
    unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
    unsetenv("MPI_LOCALNRANKS");
    EXPECT_EQ(launched_local_ranks(), 0);
    setenv("MPI_LOCALNRANKS", "3", 1);
    EXPECT_EQ(launched_local_ranks(), 3);
    setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "4", 1);  // Open MPI's name is read first
    EXPECT_EQ(launched_local_ranks(), 4);
    unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
    unsetenv("MPI_LOCALNRANKS");
}

}  // namespace
}  // namespace dtm::dist
