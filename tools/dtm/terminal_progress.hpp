// SPDX-License-Identifier: MIT
/// @file
/// @brief The dtm::Progress the subcommands hand to the library: a bar on stderr.
#pragma once

#include "dtm/core/progress.hpp"

namespace dtm::cli {

/// Progress on stderr:
/// - stderr is a terminal: one line `dtm: <stage> [#####.....]  42%` redrawn in place (at most
///   every 0.1 s), ended with a newline at 100 % or when the last copy of the handle goes away;
/// - stderr is a file or pipe (or TERM=dumb): one line `dtm: [ 42%] <stage>` per new stage;
/// - @p quiet: nothing is printed.
/// In every mode the first Ctrl-C (SIGINT) asks the running algorithm to stop: the next report()
/// or check() throws dtm::Cancelled, outputs are not committed and dtm exits with 130. A second
/// Ctrl-C ends the process at once.
[[nodiscard]] Progress terminal_progress(bool quiet);

/// The same, labelled `dtm <command>:` (for example terminal_progress("grid")).
/// Takes const char* on purpose: a string_view overload would lose to the bool one for literals.
[[nodiscard]] Progress terminal_progress(const char* command, bool quiet = false);

}  // namespace dtm::cli
