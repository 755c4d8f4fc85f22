// SPDX-License-Identifier: MIT
// dtm volume TOP... [--base BASE... | --plane Z | --stockpile] [--within POLYGON] [--swell F]
//            -o OUTDIR
// Exact cut and fill between two surfaces (parse -> products::run_volume -> summary).
// TOP takes the usual input options (--breaklines, --boundary, ...); the base surface takes the
// same ones prefixed: --base-breaklines, --base-boundary, --base-holes, --base-soft-breaklines.
#include <cstdio>
#include <memory>
#include <string>

#include "command.hpp"
#include "dtm/core/error.hpp"
#include "dtm/products/volume.hpp"
#include "input_args.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct VolumeArgs {
    InputArgs top;
    InputArgs base;
    std::string out_dir;
    double plane = 0.0;
    bool has_plane = false;
    bool stockpile = false;
    std::string within;
    double swell = 1.0;
    double cell = 0.0;
    bool no_products = false;
    TriangulateOptions tin;
    bool quiet = false;
};

int run_volume(const VolumeArgs& args) {
    const int bases =
        (args.base.inputs.empty() ? 0 : 1) + (args.has_plane ? 1 : 0) + (args.stockpile ? 1 : 0);
    if (bases != 1) {
        throw UsageError("volume: give exactly one base: --base BASE, --plane Z or --stockpile");
    }
    if (args.top.inputs.empty()) {
        throw UsageError("volume: give the top surface (a .ply TIN or points) as INPUTS");
    }
    products::VolumeJob job;
    job.top = {"top", to_load_options(args.top), args.tin};
    InputArgs base = args.base;
    base.read = args.top.read;  // the reader options are the command's
    base.crs = args.top.crs;
    job.base = {"base", to_load_options(base), args.tin};
    job.base_kind = args.stockpile   ? products::VolumeBaseKind::stockpile
                    : args.has_plane ? products::VolumeBaseKind::plane
                                     : products::VolumeBaseKind::surface;
    job.plane_z = args.plane;
    job.within = args.within;
    job.within_reader.read = args.top.read;
    job.within_reader.crs = args.top.crs;
    job.swell = args.swell;
    job.cell = args.cell;
    job.threads = args.tin.threads;
    job.products = !args.no_products;
    const Progress progress = terminal_progress("volume", args.quiet);
    const products::VolumeReport r = products::run_volume(job, args.out_dir, progress);
    const VolumeResult& v = r.volume;
    std::printf(
        "volume: fill %.3f, cut %.3f, net %.3f (fill %.3f / cut %.3f / unchanged %.3f of "
        "%.3f compared area)\n",
        v.fill, v.cut, v.net(), v.fill_area, v.cut_area, v.unchanged_area, v.overlap_area);
    if (v.top_only_area > 0.0 || v.base_only_area > 0.0) {
        std::printf("volume: not compared: %.3f top only, %.3f base only\n", v.top_only_area,
                    v.base_only_area);
    }
    for (const std::string& note : r.notes) {
        std::fprintf(stderr, "volume: note: %s\n", note.c_str());
    }
    std::printf("volume: %zu products in %s (%.2f s)\n", r.files.size(), args.out_dir.c_str(),
                r.seconds);
    return 0;
}

}  // namespace

Command volume_command() {
    return {"volume",
            "Exact cut and fill between two surfaces, a surface and a level, or a stockpile and "
            "its foot: protocol, JSON, difference TIN/GeoTIFF, cut/fill polygons, zero lines",
            [](CLI::App& app) {
                auto args = std::make_shared<VolumeArgs>();
                add_input_options(app, args->top);
                add_surface_options(app, "base", args->base);
                app.add_option("-o,--output", args->out_dir, "Output folder (created if needed)")
                    ->required();
                app.add_option("--plane", args->plane, "Base: the level plane z = Z")
                    ->each([args](const std::string&) { args->has_plane = true; });
                app.add_flag("--stockpile", args->stockpile,
                             "Base: the surface spanned by the pile's outer boundary (or by "
                             "--within)");
                app.add_option("--within", args->within,
                               "Only inside this polygon (OGR polygons or closed lines)")
                    ->check(CLI::ExistingPath);
                app.add_option("--swell", args->swell,
                               "Swell factor: loose volume = bank volume x F (reported for the "
                               "cut; the pile's bank volume is fill / F)")
                    ->check(CLI::PositiveNumber);
                app.add_option("--cell", args->cell,
                               "Cell of difference.tif (default: the difference surface's mean "
                               "spacing, rounded)")
                    ->check(CLI::PositiveNumber);
                app.add_flag("--no-products", args->no_products,
                             "Only volume.json and volume.txt (no maps)");
                add_tin_options(app, args->tin);
                app.add_flag("-q,--quiet", args->quiet, "No progress bar");
                return [args]() { return run_volume(*args); };
            }};
}

}  // namespace dtm::cli
