// SPDX-License-Identifier: MIT
// dtm check SURFACE POINTS -o residuals.csv [--stats stats.json] [--interpolation
// linear|cubic|natural] A surface against control points (parse -> products::run_check ->
// statistics on stdout). SURFACE is a dtm .ply TIN or a point file triangulated on its own.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "command.hpp"
#include "dtm/products/check.hpp"
#include "input_args.hpp"
#include "interpolation_args.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct CheckArgs {
    std::string surface;
    std::string points;
    std::string output;
    std::string stats;
    Interpolation interpolation = Interpolation::linear;
    io::LoadOptions reader;
    TriangulateOptions tin;
    bool quiet = false;
};

int run_check(const CheckArgs& args) {
    products::CheckJob job;
    job.surface = {std::filesystem::path(args.surface).stem().string(), args.reader, args.tin};
    job.surface.load.files = {{args.surface, io::InputRole::points}};
    job.points = args.points;
    job.point_reader = args.reader;
    job.interpolation = args.interpolation;
    job.stats = args.stats;
    const products::CheckReport r =
        products::run_check(job, args.output, terminal_progress("check", args.quiet));
    const CheckStatistics& s = r.stats;
    std::printf("check: %zu points, %zu on the surface, %zu outside (listed in %s)\n", s.points,
                s.inside, s.outside, args.output.c_str());
    std::printf(
        "check: residual (point - surface): mean %.4f, std dev %.4f, RMSE %.4f, "
        "max |r| %.4f at %s, NSSDA 95 %% %.4f, |r| p50 %.4f p90 %.4f p95 %.4f\n",
        s.mean, s.std_dev, s.rmse, s.max_abs, r.max_abs_id.c_str(), s.nssda_95, s.p50, s.p90,
        s.p95);
    return 0;
}

}  // namespace

Command check_command() {
    return {"check", "A surface against control points: residuals, mean, RMSE, max, percentiles",
            [](CLI::App& app) {
                auto args = std::make_shared<CheckArgs>();
                app.add_option("surface", args->surface, "The surface: a dtm .ply TIN or points")
                    ->required()
                    ->check(CLI::ExistingFile);
                app.add_option("points", args->points, "Control points (id,x,y,z text or OGR)")
                    ->required()
                    ->check(CLI::ExistingFile);
                app.add_option("-o,--output", args->output, "Residuals CSV")->required();
                app.add_option("--stats", args->stats, "Also write the statistics as JSON here");
                add_interpolation_option(app, "--interpolation", args->interpolation);
                add_reader_options(app, args->reader.read, args->reader.crs);
                add_tin_options(app, args->tin);
                app.add_flag("-q,--quiet", args->quiet, "No progress bar");
                return [args]() { return run_check(*args); };
            }};
}

}  // namespace dtm::cli
