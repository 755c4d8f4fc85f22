// SPDX-License-Identifier: MIT
// dtm profile SURFACE... --line LINES -o OUTDIR [--exaggeration E] [--stations D] [--plot F]
// Exact sections of each surface along each line (parse -> products::run_profile -> summary).
// Each SURFACE is one file: a dtm .ply TIN, or points (a vector or text file) triangulated alone;
// build a TIN with `dtm tin` first for a surface made of points and breaklines.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "dtm/products/profile.hpp"
#include "input_args.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct ProfileArgs {
    std::vector<std::string> surfaces;
    std::string lines;
    std::string out_dir;
    io::LoadOptions reader;
    TriangulateOptions tin;
    double exaggeration = 10.0;
    double stations = 0.0;
    std::string plot = "pdf";
    bool quiet = false;
};

/// One surface per file, named by the file's stem.
std::vector<products::SurfaceSource> surface_sources(const std::vector<std::string>& files,
                                                     const io::LoadOptions& reader,
                                                     const TriangulateOptions& tin) {
    std::vector<products::SurfaceSource> out;
    for (const std::string& f : files) {
        products::SurfaceSource s{std::filesystem::path(f).stem().string(), reader, tin};
        s.load.files = {{f, io::InputRole::points}};
        out.push_back(std::move(s));
    }
    return out;
}

int run_profile(const ProfileArgs& args) {
    products::ProfileJob job;
    job.surfaces = surface_sources(args.surfaces, args.reader, args.tin);
    job.lines = args.lines;
    job.line_reader = args.reader;
    job.exaggeration = args.exaggeration;
    job.station_interval = args.stations;
    job.plot_format = args.plot == "none" ? std::string() : args.plot;
    job.threads = args.tin.threads;
    const products::ProfileReport r =
        products::run_profile(job, args.out_dir, terminal_progress("profile", args.quiet));
    std::printf(
        "profile: %zu lines x %zu surfaces, %zu breakpoints, %zu gaps -> %s (reading %.2f s, "
        "sections and products %.2f s)\n",
        r.lines, r.surfaces.size(), r.breakpoints, r.gaps, args.out_dir.c_str(), r.read_seconds,
        r.sections_seconds);
    for (const std::string& n : r.notes) {
        std::fprintf(stderr, "profile: note: %s\n", n.c_str());
    }
    return 0;
}

}  // namespace

Command profile_command() {
    return {"profile",
            "Exact sections of surfaces along lines: CSV, GeoPackage, DXF 3-D polylines and plots",
            [](CLI::App& app) {
                auto args = std::make_shared<ProfileArgs>();
                app.add_option("surfaces", args->surfaces,
                               "Surfaces: dtm .ply TINs, or point files triangulated one each")
                    ->required()
                    ->check(CLI::ExistingFile);
                app.add_option("--line,--lines", args->lines,
                               "The lines (OGR LineStrings, or a text file of lines)")
                    ->required()
                    ->check(CLI::ExistingFile);
                app.add_option("-o,--output", args->out_dir, "Output folder")->required();
                app.add_option("--exaggeration", args->exaggeration,
                               "Vertical exaggeration of the plots (default 10)")
                    ->check(CLI::PositiveNumber);
                app.add_option("--stations", args->stations,
                               "Label stations every D along the line (default: automatic)")
                    ->check(CLI::PositiveNumber);
                app.add_option("--plot", args->plot,
                               "Plot format: pdf (one page per line), svg, "
                               "png (one file per line) or none")
                    ->check(CLI::IsMember({"pdf", "svg", "png", "none"}));
                add_reader_options(app, args->reader.read, args->reader.crs);
                add_tin_options(app, args->tin);
                app.add_flag("-q,--quiet", args->quiet, "No progress bar");
                return [args]() { return run_profile(*args); };
            }};
}

}  // namespace dtm::cli
