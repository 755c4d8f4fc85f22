// SPDX-License-Identifier: MIT
// `dtm tin`: read points and breaklines, build the constrained Delaunay TIN, write it by extension.
// Thin: parse -> options -> io::load_inputs -> products::surface -> io::write_tin -> report.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "command.hpp"
#include "contour_flats_args.hpp"
#include "distributed.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/json_writer.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/io/tin_file.hpp"
#include "dtm/products/distributed_tin.hpp"
#include "dtm/products/surface.hpp"
#include "dtm/products/tin_report.hpp"
#include "input_args.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct TinArgs {
    InputArgs input;
    TriangulateOptions triangulate;
    products::ContourFlats flats = products::ContourFlats::automatic;
    std::string output;
    std::string report;
    bool ascii = false;
    bool check = false;
    bool stats = false;
    bool quiet = false;
};

double since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// `dtm tin` on the ranks of an MPI job: what the distributed run covers, or a clear refusal.
int run_tin_distributed(const TinArgs& a, dist::Comm& comm) {
    const InputArgs& in = a.input;
    check_distributed_input("tin", in, a.triangulate);
    const auto refuse = [](const std::string& what) {
        throw UsageError("tin: a distributed run (mpirun) does not take " + what + " yet");
    };
    const bool tiled = io::lower_extension(a.output) == "json";
    if ((io::lower_extension(a.output) != "ply" && !tiled) || a.ascii)
        refuse("an output other than a binary .ply or a tiled TIN's .json");
    if (a.check || !a.report.empty()) refuse("`check` or `report`");
    io::check_output(a.output, tiled ? io::OutputKind::any_file : io::OutputKind::tin, "output");
    const auto start = std::chrono::steady_clock::now();
    const bool shows = prints() && !a.quiet && !a.stats;
    const products::DistributedTinResult r =
        products::distributed_tin(comm, {distributed_source(in, a.triangulate), a.output},
                                  shows ? terminal_progress(false) : Progress{});
    if (r.written != a.output && prints()) {
        std::cerr << "dtm tin: warning: " << r.vertices << " vertices and " << r.triangles
                  << " triangles are more than one PLY indexes; wrote the tiled TIN "
                  << r.written.string() << " (" << r.tiles.size() << " tiles) instead of "
                  << a.output << "\n";
    }
    if (a.stats && prints()) {
        std::cout << products::distributed_tin_stats_json(r, since(start)) << std::flush;
    }
    return 0;
}

int run_tin(const TinArgs& a) {
    if (dist::Comm* comm = distributed_comm()) return run_tin_distributed(a, *comm);
    io::check_output(a.output, io::OutputKind::tin, "output");
    if (!a.report.empty()) io::check_output(a.report, io::OutputKind::any_file, "report");
    if (a.check && (a.input.dem.clip_radius > 0.0 || a.input.dem.max_error > 0.0)) {
        throw UsageError(
            "tin: --check compares the TIN with every input point; it does not take "
            "--dem-clip-radius or --dem-max-error");
    }
    const auto start = std::chrono::steady_clock::now();
    const Progress progress = terminal_progress(a.quiet || a.stats);
    io::LoadedInputs loaded = io::load_inputs(to_load_options(a.input), progress.sub(0, 0.2));
    const double read_s = since(start);

    // --check compares the TIN with the input, so it keeps a copy; otherwise the triangulation
    // consumes the input.
    TerrainInput kept = a.check && !loaded.tin ? loaded.terrain : TerrainInput{};
    const products::Surface surface = products::surface(
        loaded, surface_options(a.input, a.triangulate, a.flats), progress.sub(0.2, 0.9));
    if (surface.contour_flats && !a.quiet && !a.stats) {
        print_contour_flats(*surface.contour_flats, "tin");
    }
    if (surface.dem && !a.quiet && !a.stats) print_dem_report(*surface.dem, "tin");
    const TriangulateResult& result = surface.result;
    if (a.check) {  // topology, every breakline, Delaunay (or local optimality under --optimize)
        kept.points.insert(kept.points.end(), surface.added_points.begin(),
                           surface.added_points.end());
        const CheckReport checked =
            verify_tin(result.tin, kept, result.input_to_vertex, a.triangulate.optimize);
        if (!checked.ok()) throw Error("the TIN failed its checks:\n" + checked.text());
    }

    const auto write_start = std::chrono::steady_clock::now();
    io::TinWriteOptions write_options;
    write_options.crs_wkt = loaded.crs_wkt;
    write_options.ascii = a.ascii;
    io::write_tin(result.tin, a.output, write_options);
    if (!a.report.empty()) products::write_tin_report(a.report, result);
    progress.report(1.0, "done");
    const double write_s = since(write_start);

    if (result.stats.conflicts > 0 && !a.stats) {
        std::cerr << "dtm: warning: " << result.stats.conflicts
                  << " breakline crossings with heights differing by more than "
                  << a.triangulate.z_tolerance << " (first at "
                  << io::json_number(result.conflicts[0].at.x) << ", "
                  << io::json_number(result.conflicts[0].at.y) << "; --report lists them all)\n";
    }
    if (a.stats)
        std::cout << products::tin_stats_json(surface, loaded.skipped_lines,
                                              {read_s, write_s, since(start)})
                  << std::flush;
    return 0;
}

}  // namespace

Command tin_command() {
    return {"tin",
            "Build the constrained Delaunay TIN and write it (.ply, .2dm, .vtp, .gpkg, .shp)",
            [](CLI::App& app) -> std::function<int()> {
                auto args = std::make_shared<TinArgs>();
                add_input_options(app, args->input);
                add_tin_options(app, args->triangulate);
                add_contour_flats_options(app, args->flats);
                add_dem_options(app, args->input.dem);
                app.add_option("-o,--output", args->output, "Output TIN (format by extension)")
                    ->required();
                app.add_flag("--ascii", args->ascii, "PLY as text instead of binary");
                app.add_flag("--check", args->check,
                             "Verify topology, the exact constrained Delaunay property and every "
                             "breakline before writing (exit 1 if broken)");
                app.add_flag("--stats", args->stats, "Print one JSON object of counts and timings");
                app.add_option("--report", args->report,
                               "Write a JSON list of every merged duplicate and height conflict");
                app.add_flag("-q,--quiet", args->quiet, "No progress bar");
                return [args] { return run_tin(*args); };
            }};
}

}  // namespace dtm::cli
