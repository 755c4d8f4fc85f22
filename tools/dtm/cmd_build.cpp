// SPDX-License-Identifier: MIT
// dtm build INPUTS... -o OUTDIR: the main job, products::build() (libdtm/src/products/build.cpp)
// behind its options. This file declares the options and prints the summary; what is written
// and how the cell and interval are chosen is the library's (docs/products.md). With --base BASE
// the volume products of the TIN against BASE go into volume/ and dtm.qgs shows a cut/fill map.
#include <cstdio>
#include <memory>
#include <string>

#include "command.hpp"
#include "contour_flats_args.hpp"
#include "distributed.hpp"
#include "dtm/core/error.hpp"
#include "dtm/products/build.hpp"
#include "dtm/products/distributed_build.hpp"
#include "input_args.hpp"
#include "interpolation_args.hpp"
#include "option_names.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct BuildArgs {
    InputArgs input;
    InputArgs base;  ///< --base BASE...: compare the TIN with this surface
    std::string out_dir;
    products::BuildOptions build;
    bool quiet = false;
};

/// One short paragraph on stdout: what was built and where the report is.
void print_summary(const products::BuildReport& r, const std::string& out_dir) {
    const PointFate& points = r.accounting.survey_points;
    std::printf(
        "dtm build: %zu points read (%zu used, %zu merged duplicates, %zu outside the "
        "boundary or in holes), %zu bad lines skipped\n",
        points.total, points.used, points.merged, points.removed, r.skipped_lines);
    std::printf(
        "dtm build: TIN %zu vertices, %zu triangles, %zu constrained edges, %zu breakline "
        "conflicts; DEM %zu x %zu cells of %g; %zu contour lines every %g\n",
        r.surface.vertex_count, r.surface.triangle_count, r.surface.constraint_count,
        r.conflicts.size(), r.dem.cols, r.dem.rows, r.dem.cell, r.contour_lines,
        r.contour_interval);
    if (r.map_scale > 0.0) {
        std::printf("dtm build: map.pdf at 1:%g, %zu contour labels (%zu positions without room)\n",
                    r.map_scale, r.map_labels, r.map_label_failures);
    }
    if (r.has_volume) {
        std::printf("dtm build: against the base: fill %.3f, cut %.3f, net %.3f (volume/)\n",
                    r.volume.fill, r.volume.cut, r.volume.net());
    }
    std::printf("dtm build: products and report.json in %s\n", out_dir.c_str());
}

void warn_without_crs(const products::BuildReport& report) {
    if (report.crs_wkt.empty()) {
        std::fprintf(stderr,
                     "dtm build: warning: the inputs carry no CRS (give --crs): the products and "
                     "the QGIS project have none\n");
    }
}

/// The main job on the ranks of an MPI job: what it covers (docs/distributed.md), or a refusal.
int run_build_distributed(BuildArgs& args, dist::Comm& comm) {
    check_distributed_input("build", args.input, args.build.triangulate);
    const auto refuse = [](const std::string& what) {
        throw UsageError("build: a distributed run (mpirun) does not take " + what + " yet");
    };
    if (!args.base.inputs.empty()) refuse("`base` (volumes)");
    if (args.build.map_scale > 0.0) refuse("`map_scale` (it makes no map.pdf)");
    if (args.build.interpolation != Interpolation::linear) {
        refuse("`interpolation` other than linear");
    }
    if (!args.input.read.z_field.empty()) refuse("contour lines (`z_field`)");
    products::DistributedBuildOptions options{
        .source = distributed_source(args.input, args.build.triangulate),
        .out_dir = args.out_dir,
        .cell = args.build.cell,
        .interval = args.build.interval,
        .index_every = args.build.index_every,
        .wording = cli_text};
    const products::BuildReport report = products::distributed_build(
        comm, options, prints() ? terminal_progress("build", args.quiet) : Progress{});
    if (!prints()) return 0;
    if (!args.quiet) {
        const products::DistributedRun& run = *report.distributed;
        std::printf(
            "dtm build: %d ranks; %llu points and %llu line vertices read, %llu merged "
            "duplicates, %zu bad lines skipped\n",
            run.ranks, static_cast<unsigned long long>(run.survey_points),
            static_cast<unsigned long long>(run.line_vertices),
            static_cast<unsigned long long>(run.merged), report.skipped_lines);
        std::printf(
            "dtm build: TIN %zu vertices, %zu triangles, %zu constrained edges; DEM %zu x %zu "
            "cells of %g (dem.vrt); %zu contour lines every %g (contours.vrt)\n",
            report.surface.vertex_count, report.surface.triangle_count,
            report.surface.constraint_count, report.dem.cols, report.dem.rows, report.dem.cell,
            report.contour_lines, report.contour_interval);
        std::printf("dtm build: products and report.json in %s\n", args.out_dir.c_str());
    }
    warn_without_crs(report);
    return 0;
}

int run_build(BuildArgs& args) {
    if (dist::Comm* comm = distributed_comm()) return run_build_distributed(args, *comm);
    const Progress progress = terminal_progress("build", args.quiet);
    args.build.wording = cli_text;
    args.build.flat_areas.assign(args.input.flat_areas.begin(), args.input.flat_areas.end());
    args.build.dem = args.input.dem;
    if (!args.base.inputs.empty()) {
        InputArgs base = args.base;
        base.read = args.input.read;  // the reader options are the command's
        base.crs = args.input.crs;
        args.build.base = to_load_options(base);
    }
    const products::BuildReport report =
        products::build(to_load_options(args.input), args.out_dir, args.build, progress);
    if (report.contour_flats && !args.quiet) print_contour_flats(*report.contour_flats, "build");
    if (report.dem_cells && !args.quiet) print_dem_report(*report.dem_cells, "build");
    if (!args.quiet) print_summary(report, args.out_dir);
    warn_without_crs(report);
    return 0;
}

}  // namespace

Command build_command() {
    return {"build",
            "The main job: TIN, DEM, hillshade, contours, contour map sheet (PDF), VTK surface, "
            "2DM mesh, QGIS project with its print layout, and report into one folder (with "
            "--base: volumes and a cut/fill map too)",
            [](CLI::App& app) {
                auto args = std::make_shared<BuildArgs>();
                add_input_options(app, args->input);
                add_surface_options(app, "base", args->base);
                app.add_option("-o,--output", args->out_dir, "Output folder (created if needed)")
                    ->required();
                app.add_option("--cell", args->build.cell,
                               "DEM cell size in CRS units (default: half the mean point "
                               "spacing, rounded down to 1, 2, 2.5, 5 x 10^k)")
                    ->check(CLI::PositiveNumber);
                app.add_option("--interval", args->build.interval,
                               "Contour interval (default: z range / 20, rounded down to 1, 2, "
                               "2.5, 5 x 10^k)")
                    ->check(CLI::PositiveNumber);
                app.add_option("--index-every", args->build.index_every,
                               "Every N-th contour level is an index contour (default 5)");
                app.add_option("--map-scale", args->build.map_scale,
                               "Scale 1:N of map.pdf, an A3 sheet (default: the largest usual "
                               "scale at which the site fits)")
                    ->check(CLI::PositiveNumber);
                add_tin_options(app, args->build.triangulate);
                add_contour_flats_options(app, args->build.contour_flats);
                add_dem_options(app, args->input.dem);
                add_interpolation_option(app, "--interpolation", args->build.interpolation);
                app.add_flag("-q,--quiet", args->quiet, "No progress bar");
                return [args]() { return run_build(*args); };
            }};
}

}  // namespace dtm::cli
