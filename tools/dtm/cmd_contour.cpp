// SPDX-License-Identifier: MIT
// Placeholder until `dtm contour` is implemented (see the issues); it fails clearly instead of pretending.
#include "command.hpp"
#include "dtm/core/error.hpp"

namespace dtm::cli {
Command contour_command()
{
    return {"contour", "(not implemented yet)", [](CLI::App&) {
                return []() -> int { throw dtm::Error("dtm contour is not implemented yet"); };
            }};
}
}  // namespace dtm::cli
