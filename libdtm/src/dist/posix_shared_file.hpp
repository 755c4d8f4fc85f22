// SPDX-License-Identifier: MIT
/// @file
/// @brief SharedFile on POSIX pwrite, for ranks that share a file system on one machine (the
/// in-process backend): rank 0 creates the file, every rank writes its ranges through its own
/// descriptor, close() syncs and agrees on failure.
#pragma once

#include <memory>
#include <string>

#include "dtm/dist/comm.hpp"

namespace dtm::dist {

std::unique_ptr<SharedFile> open_posix_shared(Comm& comm, const std::string& path);

}  // namespace dtm::dist
