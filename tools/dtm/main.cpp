// SPDX-License-Identifier: MIT
// dtm: one binary, thin subcommands. This file is the only place exceptions become exit codes:
//   0 ok, 1 any other failure (dtm::Error, std::exception), 2 bad usage or bad input
//   (dtm::UsageError with dtm::OptionError, dtm::InputError, CLI11 parse errors), 130 cancelled.
// Library messages name options as `field`; cli_text() shows them as the flags users type.
#if __has_include(<malloc.h>)
#include <malloc.h>
#endif

#include <csignal>
#include <exception>
#include <iostream>
#include <vector>

#include "command.hpp"
#include "dtm/core/error.hpp"
#include "option_names.hpp"

void keep_freed_memory() noexcept;  // huge_page_new.cpp

int main(int argc, char** argv) {
#ifdef M_MMAP_THRESHOLD
    // Large arrays (points, meshes, TINs) come and go in phases; a fixed mmap threshold returns
    // each one to the system when it is freed (glibc's adaptive threshold would keep them in the
    // heap and the resident memory would add up across phases).
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
    // Past a file-size limit (ulimit -f) write(2) fails with EFBIG and the writer reports it, as
    // for a full disk, instead of SIGXFSZ killing the process with a core dump.
    std::signal(SIGXFSZ, SIG_IGN);
    using namespace dtm::cli;
    CLI::App app{
        "dtm: survey points and breaklines to a constrained Delaunay TIN, DEMs, contours "
        "and 3-D surfaces"};
    app.set_version_flag("--version", std::string("dtm ") + DTM_VERSION);
    app.require_subcommand(0, 1);  // at most one; "none" is reported below, so that an unknown
                                   // word or option is named in the error instead

    const std::vector<Command> commands{tin_command(),     info_command(),  grid_command(),
                                        contour_command(), build_command(), methods_command(),
                                        voronoi_command(), map_command(),   volume_command(),
                                        profile_command(), check_command(), sections_command()};
    std::function<int()> run;
    std::string_view chosen;
    for (const Command& command : commands) {
        CLI::App* sub = app.add_subcommand(std::string(command.name), std::string(command.summary));
        auto runner = command.setup(*sub);
        sub->callback([&run, &chosen, runner, name = command.name] {
            run = runner;
            chosen = name;
        });
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::cerr << "dtm: " << e.what() << "\nRun 'dtm --help' for more information.\n";
        return 2;
    }
    if (!run) {
        std::cerr << "dtm: a subcommand is required\n" << app.help();
        return 2;
    }
    // The products and analyses reuse freed memory instead of fresh pages (memory_policy.cpp);
    // `tin` and the methods lab keep malloc's defaults, under which their memory is measured.
    for (const std::string_view name :
         {"grid", "contour", "build", "map", "volume", "profile", "check", "sections"}) {
        if (chosen == name) keep_freed_memory();
    }
    try {
        return run ? run() : 0;
    } catch (const dtm::Cancelled&) {
        std::cerr << "dtm: cancelled\n";
        return 130;
    } catch (const dtm::UsageError& e) {
        std::cerr << "dtm: " << cli_text(e.what()) << '\n';
        return 2;
    } catch (const dtm::InputError& e) {
        std::cerr << "dtm: " << cli_text(e.what()) << '\n';
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "dtm: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "dtm: " << cli_text(e.what()) << '\n';
        return 1;
    }
}
