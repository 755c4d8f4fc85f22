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
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "distributed.hpp"
#include "dtm/core/error.hpp"
#include "dtm/dist/mpi_comm.hpp"
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
    // One rank of `mpirun -np P dtm ...` (P > 1): the job's communicator for the subcommand;
    // errors are elected, so every rank exits with the same code and rank 0 alone prints.
    std::unique_ptr<dtm::dist::MpiSession> session;
    if (dtm::dist::launched_ranks() > 1) {
        if (!dtm::dist::mpi_built()) {
            std::cerr << "dtm: started by mpirun, but this dtm was built without MPI\n";
            return 2;
        }
        session = std::make_unique<dtm::dist::MpiSession>(argc, argv);
        set_distributed_comm(&session->world());
        share_cores_among_local_ranks();  // e.g. one TBB thread per rank at -np 2 on 2 cores
    }
    const auto say = [](const std::string& text) {
        if (prints()) std::cerr << "dtm: " << text << '\n';
    };
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
        if (e.get_exit_code() == 0) return prints() ? app.exit(e) : 0;  // --help, --version
        say(std::string(e.what()) + "\nRun 'dtm --help' for more information.");
        return 2;
    }
    if (!run) {
        say("a subcommand is required\n" + app.help());
        return 2;
    }
    if (distributed_comm() != nullptr && chosen != "tin" && chosen != "grid" &&
        chosen != "contour" && chosen != "build") {
        say("only `dtm tin`, `dtm grid`, `dtm contour` and `dtm build` run distributed (under "
            "mpirun) yet; "
            "run `dtm " +
            std::string(chosen) + "` on one machine");
        return 2;
    }
    // The products and analyses reuse freed memory instead of fresh pages (huge_page_new.cpp);
    // `tin`, the methods lab and every distributed rank keep malloc's defaults, under which
    // their memory is measured (a rank's phases differ in size: its peak is what R-M1 bounds).
    for (const std::string_view name :
         {"grid", "contour", "build", "map", "volume", "profile", "check", "sections"}) {
        if (chosen == name && distributed_comm() == nullptr) keep_freed_memory();
    }
    try {
        return run ? run() : 0;
    } catch (const dtm::Cancelled&) {
        say("cancelled");
        return 130;
    } catch (const dtm::UsageError& e) {
        say(cli_text(e.what()));
        return 2;
    } catch (const dtm::InputError& e) {
        say(cli_text(e.what()));
        return 2;
    } catch (const std::bad_alloc&) {
        say("out of memory");
        return 1;
    } catch (const std::exception& e) {
        say(cli_text(e.what()));
        return 1;
    }
}
