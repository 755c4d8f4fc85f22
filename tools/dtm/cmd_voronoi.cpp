// SPDX-License-Identifier: MIT
// dtm voronoi INPUTS... -o cells.gpkg [--boundary F] [--hole F]
// Thiessen polygons of the survey points, clipped to the boundary or the convex hull
// (parse -> options -> library -> report).
#include <iostream>
#include <memory>
#include <string>

#include "command.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/products/voronoi.hpp"
#include "input_args.hpp"
#include "terminal_progress.hpp"

namespace dtm::cli {
namespace {

struct VoronoiArgs {
    InputArgs input;
    std::string output;
    products::VoronoiCellsOptions options;
    bool quiet = false;
};

int run_voronoi(const VoronoiArgs& args) {
    io::check_output(args.output, io::OutputKind::any_file, "output");
    const Progress progress = terminal_progress("voronoi", args.quiet);
    const io::LoadedInputs inputs =
        io::load_inputs(to_load_options(args.input), progress.sub(0.0, 0.2));
    const products::VoronoiCellsReport r =
        products::write_voronoi_cells(inputs, args.output, args.options, progress.sub(0.2, 1.0));
    std::cout << "voronoi: " << r.cells << " cells of " << r.points << " points";
    if (r.duplicates > 0) std::cout << " (" << r.duplicates << " duplicates share a cell)";
    if (r.empty_cells > 0) std::cout << ", " << r.empty_cells << " outside the region";
    std::cout << ", clipped to the " << (r.boundary ? "boundary" : "convex hull") << " -> "
              << args.output << '\n';
    return 0;
}

}  // namespace

Command voronoi_command() {
    return {"voronoi",
            "Thiessen (Voronoi) polygons of the points, clipped to a boundary or the hull",
            [](CLI::App& app) {
                auto args = std::make_shared<VoronoiArgs>();
                add_input_options(app, args->input);
                app.add_option("-o,--output", args->output,
                               "Cells: .gpkg (default format), .shp, .geojson")
                    ->required();
                app.add_option("--threads", args->options.threads, "Worker threads (default: all)");
                app.add_flag("-q,--quiet", args->quiet, "No progress on stderr");
                return [args]() { return run_voronoi(*args); };
            }};
}

}  // namespace dtm::cli
