// SPDX-License-Identifier: MIT
// dtm sections SURFACE... --alignment LINE --interval D --width W -o OUTDIR
// Cross-sections across an alignment; areas and volumes between the first two surfaces
// (parse -> products::run_sections -> summary). Each SURFACE is one file (a .ply TIN or points).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "dtm/products/sections.hpp"
#include "input_args.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct SectionsArgs {
    std::vector<std::string> surfaces;
    std::string alignment;
    std::string out_dir;
    SectionOptions options;
    double exaggeration = 2.0;
    std::string plot = "pdf";
    io::LoadOptions reader;
    TriangulateOptions tin;
    bool quiet = false;
};

int run_sections(const SectionsArgs& args) {
    products::SectionsJob job;
    for (const std::string& f : args.surfaces) {
        products::SurfaceSource s{std::filesystem::path(f).stem().string(), args.reader, args.tin};
        s.load.files = {{f, io::InputRole::points}};
        job.surfaces.push_back(std::move(s));
    }
    job.alignment = args.alignment;
    job.reader = args.reader;
    job.options = args.options;
    job.exaggeration = args.exaggeration;
    job.plot_format = args.plot == "none" ? std::string() : args.plot;
    job.threads = args.tin.threads;
    const products::SectionsReport r =
        products::run_sections(job, args.out_dir, terminal_progress("sections", args.quiet));
    std::printf("sections: %zu sections every %g across %g -> %s\n", r.sections.size(),
                args.options.interval, args.options.width, args.out_dir.c_str());
    if (!r.exact.empty()) {
        std::printf(
            "sections: fill: end-area %.3f, exact %.3f (%+.2f %%); cut: end-area %.3f, "
            "exact %.3f (%+.2f %%)\n",
            r.end_area_fill, r.exact_fill,
            r.exact_fill > 0 ? 100.0 * (r.end_area_fill / r.exact_fill - 1.0) : 0.0, r.end_area_cut,
            r.exact_cut, r.exact_cut > 0 ? 100.0 * (r.end_area_cut / r.exact_cut - 1.0) : 0.0);
    }
    for (const std::string& n : r.notes) {
        std::fprintf(stderr, "sections: note: %s\n", n.c_str());
    }
    return 0;
}

}  // namespace

Command sections_command() {
    return {"sections",
            "Cross-sections across an alignment: cut/fill areas, end-area and exact volumes, "
            "a sheet of section plots",
            [](CLI::App& app) {
                auto args = std::make_shared<SectionsArgs>();
                app.add_option("surfaces", args->surfaces,
                               "Surfaces (first: top/design, second: base/existing): .ply TINs "
                               "or point files")
                    ->required()
                    ->check(CLI::ExistingFile);
                app.add_option("--alignment", args->alignment, "The alignment (a line file)")
                    ->required()
                    ->check(CLI::ExistingFile);
                app.add_option("--interval", args->options.interval, "Station interval")
                    ->required()
                    ->check(CLI::PositiveNumber);
                app.add_option("--width", args->options.width,
                               "Total section width (half to each side)")
                    ->required()
                    ->check(CLI::PositiveNumber);
                app.add_option("-o,--output", args->out_dir, "Output folder")->required();
                app.add_option("--exaggeration", args->exaggeration,
                               "Vertical exaggeration of the plots (default 2)")
                    ->check(CLI::PositiveNumber);
                app.add_option("--plot", args->plot, "pdf (sheets), svg, png or none")
                    ->check(CLI::IsMember({"pdf", "svg", "png", "none"}));
                add_reader_options(app, args->reader.read, args->reader.crs);
                add_tin_options(app, args->tin);
                app.add_flag("-q,--quiet", args->quiet, "No progress bar");
                return [args]() { return run_sections(*args); };
            }};
}

}  // namespace dtm::cli
