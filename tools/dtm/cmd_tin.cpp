// SPDX-License-Identifier: MIT
// `dtm tin`: read points and breaklines, build the constrained Delaunay TIN, write it by extension.
// Thin: parse -> options -> io::load_inputs -> products::surface -> io::write_tin -> report.
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "command.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/json_writer.hpp"
#include "dtm/io/tin_file.hpp"
#include "dtm/products/surface.hpp"
#include "input_args.hpp"
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

/// --report: every merged duplicate and every height conflict.
void write_report(const std::string& path, const TriangulateResult& r)
{
    using Layout = io::JsonWriter::Layout;
    io::JsonWriter json;
    json.begin_object();
    json.value("duplicates_merged", r.merges.size());
    json.begin_array("merges");
    const auto point = [&json](const char* key, const Point3& p) {
        json.begin_array(key, Layout::inline_);
        for (const double c : {p.x, p.y, p.z}) json.value({}, c);
        json.end();
    };
    for (const DuplicateMerge& m : r.merges) {
        json.begin_object({}, Layout::inline_);
        json.value("kept_input", m.kept_input);
        json.value("merged_input", m.merged_input);
        point("kept", m.kept);
        point("merged", m.merged);
        json.end();
    }
    json.end();
    json.begin_array("conflicts");
    for (const ConstraintConflict& c : r.conflicts) {
        json.begin_object({}, Layout::inline_);
        json.value("x", c.at.x);
        json.value("y", c.at.y);
        json.value("z_first", c.z_first);
        json.value("z_second", c.z_second);
        json.end();
    }
    json.end();
    json.end();
    io::AtomicOutput out(path);
    {
        std::ofstream f(out.temp_path(), std::ios::binary);
        f << json.str();
        if (!f) throw Error("cannot write the report " + path);
    }
    out.commit();
}

/// --stats: one line of counts and timings.
std::string stats_json(const TriangulateResult& result, std::size_t skipped_lines,
                       const std::array<double, 3>& seconds)
{
    using Layout = io::JsonWriter::Layout;
    const TriangulateStats& s = result.stats;
    io::JsonWriter json;
    json.begin_object({}, Layout::inline_);
    json.value("points_in", s.points_in);
    json.value("duplicates_merged", s.duplicates_merged);
    json.value("skipped_lines", skipped_lines);
    json.value("vertices", result.tin.vertices.size());
    json.value("triangles", result.tin.triangles.size());
    json.value("constrained_edges", result.tin.constraints.size());
    json.value("intersections", s.intersections);
    json.value("conflicts", s.conflicts);
    json.value("removed_triangles", s.removed_triangles);
    json.begin_object("seconds", Layout::inline_);
    json.value("read", seconds[0]);
    json.value("triangulate", s.seconds_triangulate);
    json.value("constrain", s.seconds_constrain);
    json.value("write", seconds[1]);
    json.value("total", seconds[2]);
    json.end();
    json.end();
    return json.str();
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
                  << a.triangulate.z_tolerance << " (first at "
                  << io::json_number(result.conflicts[0].at.x) << ", "
                  << io::json_number(result.conflicts[0].at.y) << "; --report lists them all)\n";
    }
    if (a.stats) std::cout << stats_json(result, loaded.skipped_lines, {read_s, write_s, since(start)}) << std::flush;
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
