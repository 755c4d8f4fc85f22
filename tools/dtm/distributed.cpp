// SPDX-License-Identifier: MIT
#include "distributed.hpp"

namespace dtm::cli {
namespace {
dist::Comm* job = nullptr;
}  // namespace

dist::Comm* distributed_comm() noexcept { return job; }
void set_distributed_comm(dist::Comm* comm) noexcept { job = comm; }
bool prints() noexcept { return job == nullptr || job->rank() == 0; }

}  // namespace dtm::cli
