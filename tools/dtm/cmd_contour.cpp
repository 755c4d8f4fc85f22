// SPDX-License-Identifier: MIT
// dtm contour INPUTS... -o OUT --interval I [--base B] [--levels L1,L2,...] [--index-every K]
//             [--smooth N] [--interpolation linear|cubic|natural] [--subdivisions M]
//             [--spot-heights] [--no-labels] [--label-scale S] [--label-height MM]
// Contour lines traced exactly on the TIN, with their labels in DXF and GeoPackage files
// (parse -> options -> library -> report). A .vrt output, and any run under mpirun, is the
// distributed layout: one GeoPackage per rank (a range of levels) and an OGR VRT over them.
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "command.hpp"
#include "contour_flats_args.hpp"
#include "distributed.hpp"
#include "dtm/algo/contour.hpp"
#include "dtm/core/error.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/io/contour_writer.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/products/contours.hpp"
#include "dtm/products/distributed_contours.hpp"
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
    products::ContourFileOptions file;
    bool no_labels = false;
    bool quiet = false;
};

/// Contours as one GeoPackage per rank and an OGR VRT, on the ranks of an MPI job or on this
/// process alone: what the distributed run covers, or a clear refusal.
int run_contour_pieces(ContourArgs args, dist::Comm& comm) {
    check_distributed_input("contour", args.input, args.tin);
    const auto refuse = [](const std::string& what) {
        throw UsageError("contour: distributed contours (.vrt output, or mpirun) do not take " +
                         what + " yet");
    };
    if (io::lower_extension(args.output) != "vrt") {
        throw UsageError(
            "contour: distributed contours are one GeoPackage per rank and an OGR VRT over "
            "them: give -o NAME.vrt, not " +
            args.output);
    }
    if (args.contour.surface != Interpolation::linear) {
        refuse("`interpolation` other than linear");
    }
    if (!args.no_labels || args.file.spot_heights) {
        refuse("labels or spot heights (give --no-labels)");
    }
    io::check_output(products::contour_piece_path(args.output, 0, comm.size()),
                     io::OutputKind::contours, "output");
    args.contour.threads = args.tin.threads;
    const InputArgs& in = args.input;
    products::DistributedContourOptions options;
    options.source = distributed_source(in, args.tin);
    options.contour = args.contour;
    options.output = args.output;
    const products::DistributedContourResult r = products::distributed_contours(
        comm, options, prints() ? terminal_progress("contour", args.quiet) : Progress{});
    if (prints()) {
        std::cout << "contour: " << r.lines << " lines of " << r.levels << " levels -> "
                  << args.output << " (" << r.pieces.size() << " GeoPackage piece"
                  << (r.pieces.size() == 1 ? "" : "s") << " beside it)\n";
    }
    return 0;
}

int run_contour(ContourArgs args) {
    if (args.contour.fixed_levels.empty() && !(args.contour.interval > 0.0)) {
        throw UsageError("contour: give --interval or --levels");
    }
    if (dist::Comm* comm = distributed_comm()) return run_contour_pieces(std::move(args), *comm);
    if (io::lower_extension(args.output) == "vrt") {
        int status = 0;
        dist::run_in_process(1, [&](dist::Comm& comm) { status = run_contour_pieces(args, comm); });
        return status;
    }
    io::check_output(args.output, io::OutputKind::contours, "output");
    args.file.labels = !args.no_labels;
    if (args.file.spot_heights && !io::contour_file_holds_annotation(args.output)) {
        throw UsageError("contour: --spot-heights need a .dxf or .gpkg output, not " + args.output);
    }
    const Progress progress = terminal_progress("contour", args.quiet);
    io::LoadedInputs inputs = io::load_inputs(to_load_options(args.input), progress.sub(0.0, 0.2));
    const products::Surface surface = products::surface(
        inputs, surface_options(args.input, args.tin, args.flats), progress.sub(0.2, 0.6));
    if (surface.contour_flats && !args.quiet) {
        print_contour_flats(*surface.contour_flats, "contour");
    }
    if (surface.dem && !args.quiet) print_dem_report(*surface.dem, "contour");
    const Tin& tin = surface.result.tin;
    args.contour.threads = args.tin.threads;
    args.contour.gradients.threads = args.tin.threads;
    args.contour.gradients.crease_at_breaklines = !surface.contour_input;
    args.file.crs_wkt = inputs.crs_wkt;
    const products::ContourFileReport r = products::write_contour_file(
        tin, nullptr, args.contour, args.output, args.file, progress.sub(0.6, 1.0));
    std::cout << "contour: " << r.lines << " lines -> " << args.output << '\n';
    if (r.annotated) {
        std::cout << "contour: " << r.labels << " labels at 1:" << r.label_scale << " (text "
                  << r.text_height << " high, " << r.label_failures << " positions without room)";
        if (args.file.spot_heights) {
            std::cout << ", " << r.spots << " spot heights (" << r.spot_labels_failed
                      << " without room for the label)";
        }
        std::cout << '\n';
    }
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
                add_dem_options(app, args->input.dem);
                app.add_option("-o,--output", args->output,
                               "Contour file: .gpkg (default format), .shp, .dxf, .geojson; .vrt: "
                               "an OGR VRT over one GeoPackage per rank, NAME-R-of-P.gpkg, as "
                               "mpirun writes")
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
                app.add_flag("--spot-heights", args->file.spot_heights,
                             "DXF/GeoPackage: spot heights (summits, pits, saddles, then evenly "
                             "spread) as points with their height labels");
                app.add_flag("--no-labels", args->no_labels,
                             "DXF/GeoPackage: no index contour numbers (they are written by "
                             "default: along the line, reading uphill, never overlapping)");
                app.add_option("--label-scale", args->file.label_scale,
                               "Drawing scale 1:S of the label texts (default: the largest usual "
                               "scale at which the site fits an A3 sheet)")
                    ->check(CLI::PositiveNumber);
                app.add_option("--label-height", args->file.annotation.text_mm,
                               "Text height on paper in mm (default 2.5)")
                    ->check(CLI::PositiveNumber);
                app.add_flag("-q,--quiet", args->quiet, "No progress on stderr");
                return [args]() { return run_contour(*args); };
            }};
}

}  // namespace dtm::cli
