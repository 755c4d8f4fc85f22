// SPDX-License-Identifier: MIT
// dtm contour INPUTS... -o OUT --interval I [--base B] [--levels L1,L2,...] [--index-every K]
//             [--smooth N] [--interpolation linear|cubic|natural] [--subdivisions M]
// Contour lines traced exactly on the TIN (parse -> options -> library -> report).
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "command.hpp"
#include "contour_flats_args.hpp"
#include "dtm/algo/contour.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/contour_writer.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/products/surface.hpp"
#include "input_args.hpp"
#include "interpolation_args.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct ContourArgs {
    InputArgs input;
    TriangulateOptions tin;
    products::ContourFlats flats = products::ContourFlats::automatic;
    std::string output;
    ContourOptions contour;
    bool quiet = false;
};

int run_contour(ContourArgs args) {
    if (args.contour.fixed_levels.empty() && !(args.contour.interval > 0.0)) {
        throw UsageError("contour: give --interval or --levels");
    }
    io::check_output(args.output, io::OutputKind::contours, "output");
    const Progress progress = terminal_progress("contour", args.quiet);
    io::LoadedInputs inputs = io::load_inputs(to_load_options(args.input), progress.sub(0.0, 0.2));
    const products::Surface surface = products::surface(
        inputs, surface_options(args.input, args.tin, args.flats), progress.sub(0.2, 0.6));
    if (surface.contour_flats && !args.quiet) {
        print_contour_flats(*surface.contour_flats, "contour");
    }
    const Tin& tin = surface.result.tin;
    args.contour.threads = args.tin.threads;
    args.contour.gradients.threads = args.tin.threads;
    args.contour.gradients.crease_at_breaklines = !surface.contour_input;
    io::ContourWriter writer(args.output, {.crs_wkt = inputs.crs_wkt});
    contour(tin, args.contour, writer, progress.sub(0.6, 1.0));
    writer.commit();
    std::cout << "contour: " << writer.feature_count() << " lines -> " << args.output << '\n';
    return 0;
}

}  // namespace

Command contour_command() {
    return {"contour",
            "Contour lines traced exactly on the TIN (GeoPackage, shapefile, DXF, GeoJSON)",
            [](CLI::App& app) {
                auto args = std::make_shared<ContourArgs>();
                args->contour.interval = 0.0;
                add_input_options(app, args->input);
                add_tin_options(app, args->tin);
                add_contour_flats_options(app, args->flats);
                app.add_option("-o,--output", args->output,
                               "Contour file: .gpkg (default format), .shp, .dxf, .geojson")
                    ->required();
                app.add_option("--interval", args->contour.interval, "Distance between levels")
                    ->check(CLI::PositiveNumber);
                app.add_option("--base", args->contour.base,
                               "Levels are base + k * interval (default 0)");
                app.add_option("--levels", args->contour.fixed_levels,
                               "Explicit levels L1,L2,... (instead of --interval)")
                    ->delimiter(',');
                app.add_option("--index-every", args->contour.index_every,
                               "Every K-th level is an index contour (default 5; 0: none)");
                app.add_option("--smooth", args->contour.smooth,
                               "Corner-cutting passes that keep lines inside their triangles "
                               "and never crossing (default 0)");
                add_interpolation_option(app, "--interpolation", args->contour.surface);
                app.add_option("--subdivisions", args->contour.subdivisions,
                               "cubic/natural: each triangle's three sub-triangles are cut into "
                               "M x M pieces on which the lines are traced (default 4)")
                    ->check(CLI::Range(1, 64));
                app.add_option("--max-levels", args->contour.max_levels,
                               "Refuse more levels than this (default 100000)");
                app.add_flag("-q,--quiet", args->quiet, "No progress on stderr");
                return [args]() { return run_contour(*args); };
            }};
}

}  // namespace dtm::cli
