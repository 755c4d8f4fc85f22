// SPDX-License-Identifier: MIT
// Placeholder until `dtm grid` is implemented (see the issues); it fails clearly instead of pretending.
#include "command.hpp"
#include "dtm/core/error.hpp"

namespace dtm::cli {
Command grid_command()
{
    return {"grid", "(not implemented yet)", [](CLI::App&) {
                return []() -> int { throw dtm::Error("dtm grid is not implemented yet"); };
            }};
}
}  // namespace dtm::cli
