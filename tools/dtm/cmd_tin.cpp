// SPDX-License-Identifier: MIT
// `dtm tin`: read points and breaklines, build the constrained Delaunay TIN, write it by extension.
// Thin: parse -> options -> io::load_inputs -> dtm::triangulate -> io::write_tin -> report.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "command.hpp"
#include "dtm/algo/criteria.hpp"
#include "dtm/algo/optimize.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/tin_file.hpp"
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

/// The optimisation's figures as a JSON object (criterion, flips, quality before and after).
std::string optimize_json(const OptimizeStats& o)
{
    auto quality = [](const QualitySummary& q) {
        return "{\"worst\": " + json_number(q.worst) + ", \"mean\": " + json_number(q.mean) +
               ", \"sum\": " + json_number(q.sum) + "}";
    };
    return "{\"criterion\": " + json_string(criterion_name(o.criterion)) +
           ", \"flips\": " + std::to_string(o.flips) +
           ", \"improvable_before\": " + std::to_string(o.improvable_before) +
           ", \"improvable_after\": " + std::to_string(o.improvable_after) +
           ", \"converged\": " + (o.converged ? "true" : "false") +
           ", \"quality_before\": " + quality(o.before) + ", \"quality_after\": " + quality(o.after) +
           ", \"seconds\": " + json_number(o.seconds) + "}";
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
        f << "\n  ]";
        if (r.stats.optimize.criterion != Criterion::delaunay) {
            f << ",\n  \"optimize\": " << optimize_json(r.stats.optimize);
        }
        f << "\n}\n";
        if (!f) throw Error("cannot write the report " + path);
    }
    out.commit();
}

void check_tin(const TriangulateResult& result, const TerrainInput& input, Criterion optimize)
{
    const Tin& tin = result.tin;
    std::string problems;
    CheckReport optimal = optimize == Criterion::delaunay ? verify_constrained_delaunay(tin)
                                                          : CheckReport{};
    if (optimize != Criterion::delaunay) {
        for (const auto& [a, b] : improvable_edges(tin, optimize, 5)) {
            optimal.problems.push_back("edge " + std::to_string(a) + "-" + std::to_string(b) +
                                       " is not locally optimal under " +
                                       std::string(criterion_name(optimize)));
        }
    }
    for (const CheckReport& r : {verify_topology(tin), optimal,
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

    TriangulateResult result;
    if (loaded.tin) {
        result.tin = *loaded.tin;
    } else {
        // Without --check the input is not needed afterwards: let the triangulation consume it.
        result = a.check ? triangulate(loaded.terrain, a.triangulate, progress.sub(0.2, 0.9))
                         : triangulate(std::move(loaded.terrain), a.triangulate,
                                       progress.sub(0.2, 0.9));
    }
    if (loaded.tin && a.triangulate.optimize != Criterion::delaunay) {
        result.stats.optimize = optimize_tin(
            result.tin, {.criterion = a.triangulate.optimize, .threads = a.triangulate.threads},
            progress.sub(0.2, 0.9));
    }
    if (a.check) {
        check_tin(result, loaded.tin ? TerrainInput{} : loaded.terrain, a.triangulate.optimize);
    }

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
                  << "}";
        if (s.optimize.criterion != Criterion::delaunay) {
            std::cout << ", \"optimize\": " << optimize_json(s.optimize);
        }
        std::cout << "}" << std::endl;
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
