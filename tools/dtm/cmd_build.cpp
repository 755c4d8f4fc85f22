// SPDX-License-Identifier: MIT
// Placeholder until `dtm build` is implemented (see the issues); it fails clearly instead of pretending.
#include "command.hpp"
#include "dtm/core/error.hpp"

namespace dtm::cli {
Command build_command()
{
    return {"build", "(not implemented yet)", [](CLI::App&) {
                return []() -> int { throw dtm::Error("dtm build is not implemented yet"); };
            }};
}
}  // namespace dtm::cli
