// SPDX-License-Identifier: MIT
// `dtm tin`: read points and breaklines, build the constrained Delaunay TIN, write it by extension.
// Thin: parse -> options -> io::load_inputs -> products::surface -> io::write_tin -> report.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "command.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/tin_file.hpp"
#include "dtm/products/surface.hpp"
#include "input_args.hpp"
#include "json_text.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct TinArgs {
    InputArgs input;
    TriangulateOptions triangulate;
    std::string output;
    std::string report;
    bool ascii = false;
    bool check = false;
    bool stats = false;
    bool quiet = false;
};

double since(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void write_report(const std::string& path, const TriangulateResult& r)
{
    io::AtomicOutput out(path);
    {
        std::ofstream f(out.temp_path());
        f << "{\n  \"duplicates_merged\": " << r.merges.size() << ",\n  \"merges\": [";
        for (std::size_t i = 0; i < r.merges.size(); ++i) {
            const DuplicateMerge& m = r.merges[i];
            f << (i ? ",\n    " : "\n    ") << "{\"kept_input\": " << m.kept_input
              << ", \"merged_input\": " << m.merged_input << ", \"kept\": [" << json_number(m.kept.x)
              << ", " << json_number(m.kept.y) << ", " << json_number(m.kept.z) << "], \"merged\": ["
              << json_number(m.merged.x) << ", " << json_number(m.merged.y) << ", " << json_number(m.merged.z)
              << "]}";
        }
        f << "\n  ],\n  \"conflicts\": [";
        for (std::size_t i = 0; i < r.conflicts.size(); ++i) {
            const ConstraintConflict& c = r.conflicts[i];
            f << (i ? ",\n    " : "\n    ") << "{\"x\": " << json_number(c.at.x) << ", \"y\": "
              << json_number(c.at.y) << ", \"z_first\": " << json_number(c.z_first)
              << ", \"z_second\": " << json_number(c.z_second) << "}";
        }
        f << "\n  ]\n}\n";
        if (!f) throw Error("cannot write the report " + path);
    }
    out.commit();
}

void check_tin(const TriangulateResult& result, const TerrainInput& input)
{
    const Tin& tin = result.tin;
    std::string problems;
    for (const CheckReport& r : {verify_topology(tin), verify_constrained_delaunay(tin),
                                 verify_constraints(tin, input, result.input_to_vertex)}) {
        problems += r.text();
    }
    if (!problems.empty()) throw Error("the TIN failed its checks:\n" + problems);
}

int run_tin(const TinArgs& a)
{
    const auto start = std::chrono::steady_clock::now();
    const Progress progress = terminal_progress(a.quiet || a.stats);
    io::LoadedInputs loaded = io::load_inputs(to_load_options(a.input), progress.sub(0, 0.2));
    const double read_s = since(start);

    // --check compares the TIN with the input, so it keeps a copy; otherwise the triangulation
    // consumes the input.
    const TerrainInput kept = a.check && !loaded.tin ? loaded.terrain : TerrainInput{};
    const products::Surface surface =
        products::surface(loaded, a.triangulate, progress.sub(0.2, 0.9));
    const TriangulateResult& result = surface.result;
    if (a.check) check_tin(result, kept);

    const auto write_start = std::chrono::steady_clock::now();
    io::TinWriteOptions write_options;
    write_options.crs_wkt = loaded.crs_wkt;
    write_options.ascii = a.ascii;
    io::write_tin(result.tin, a.output, write_options);
    if (!a.report.empty()) write_report(a.report, result);
    progress.report(1.0, "done");
    const double write_s = since(write_start);

    if (result.stats.conflicts > 0 && !a.stats) {
        std::cerr << "dtm: warning: " << result.stats.conflicts
                  << " breakline crossings with heights differing by more than "
                  << a.triangulate.z_tolerance << " (first at " << json_number(result.conflicts[0].at.x)
                  << ", " << json_number(result.conflicts[0].at.y) << "; --report lists them all)\n";
    }
    if (a.stats) {
        const TriangulateStats& s = result.stats;
        std::cout << "{\"points_in\": " << s.points_in
                  << ", \"duplicates_merged\": " << s.duplicates_merged
                  << ", \"skipped_lines\": " << loaded.skipped_lines
                  << ", \"vertices\": " << result.tin.vertices.size()
                  << ", \"triangles\": " << result.tin.triangles.size()
                  << ", \"constrained_edges\": " << result.tin.constraints.size()
                  << ", \"intersections\": " << s.intersections << ", \"conflicts\": " << s.conflicts
                  << ", \"removed_triangles\": " << s.removed_triangles << ", \"seconds\": {\"read\": "
                  << json_number(read_s) << ", \"triangulate\": " << json_number(s.seconds_triangulate)
                  << ", \"constrain\": " << json_number(s.seconds_constrain)
                  << ", \"write\": " << json_number(write_s) << ", \"total\": " << json_number(since(start))
                  << "}}" << std::endl;
    }
    return 0;
}

}  // namespace

Command tin_command()
{
    return {"tin", "Build the constrained Delaunay TIN and write it (.ply, .2dm, .vtp, .gpkg, .shp)",
            [](CLI::App& app) -> std::function<int()> {
                auto args = std::make_shared<TinArgs>();
                add_input_options(app, args->input);
                add_tin_options(app, args->triangulate);
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
