// SPDX-License-Identifier: MIT
// Placeholder until `dtm info` is implemented (see the issues); it fails clearly instead of pretending.
#include "command.hpp"
#include "dtm/core/error.hpp"

namespace dtm::cli {
Command info_command()
{
    return {"info", "(not implemented yet)", [](CLI::App&) {
                return []() -> int { throw dtm::Error("dtm info is not implemented yet"); };
            }};
}
}  // namespace dtm::cli
