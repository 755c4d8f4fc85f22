// SPDX-License-Identifier: MIT
// `dtm methods`: the triangulation methods of the source literature, listed and run one by one.
//   dtm methods list [--json]
//   dtm methods run NAME INPUT -o OUT.ply [--stats] [--param KEY=VALUE]... [--seed S]
// Thin: parse -> methods::registry / MethodFn -> io::write_tin -> print.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "dtm/algo/line_heights.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/json_writer.hpp"
#include "dtm/io/tin_file.hpp"
#include "dtm/methods/registry.hpp"
#include "input_args.hpp"
#include "terminal_progress.hpp"

namespace dtm::cli {
namespace {

int run_list(bool json) {
    const auto methods = methods::registry();
    if (!json) {
        for (const methods::MethodInfo& m : methods) {
            std::printf("%-24s %-12s %-30s %s\n", std::string(m.name).c_str(),
                        std::string(methods::family_name(m.family)).c_str(),
                        std::string(m.complexity).c_str(), std::string(m.summary).c_str());
        }
        return 0;
    }
    std::string out = "[";
    for (std::size_t i = 0; i < methods.size(); ++i) {
        const methods::MethodInfo& m = methods[i];
        out += (i ? ",\n " : "\n ");
        out += "{\"name\": " + io::json_string(m.name) +
               ", \"family\": " + io::json_string(methods::family_name(m.family)) +
               ", \"source\": " + io::json_string(m.source) +
               ", \"complexity\": " + io::json_string(m.complexity) +
               ", \"summary\": " + io::json_string(m.summary) +
               ", \"takes_constraints\": " + (m.takes_constraints ? "true" : "false") +
               ", \"quadratic\": " + (m.quadratic ? "true" : "false") +
               ", \"params\": " + io::json_string(m.params) + "}";
    }
    std::printf("%s\n]\n", out.c_str());
    return 0;
}

struct RunArgs {
    std::string name;
    InputArgs input;
    std::string output;
    std::vector<std::string> params;
    std::uint64_t seed = 1;
    unsigned threads = 0;
    bool stats = false;
    bool quiet = false;
};

std::string counters_json(const methods::MethodCounters& c) {
    std::string out = "{\"orient_calls\": " + std::to_string(c.orient_calls) +
                      ", \"incircle_calls\": " + std::to_string(c.incircle_calls) +
                      ", \"flips\": " + std::to_string(c.flips) +
                      ", \"walk_steps\": " + std::to_string(c.walk_steps) +
                      ", \"peak_bytes\": " + std::to_string(c.peak_bytes);
    for (const auto& [key, value] : c.extra) {
        out += ", " + io::json_string(key) + ": " + std::to_string(value);
    }
    return out + "}";
}

int run_method(const RunArgs& a) {
    const methods::MethodInfo* method = methods::find_method(a.name);
    if (method == nullptr) {
        throw UsageError("methods run: unknown method '" + a.name +
                         "' (dtm methods list shows them)");
    }
    methods::MethodOptions options;
    options.seed = a.seed;
    options.threads = a.threads;
    for (const std::string& p : a.params) {
        const auto eq = p.find('=');
        if (eq == std::string::npos || eq == 0) {
            throw UsageError("methods run: --param expects KEY=VALUE, got '" + p + "'");
        }
        options.params[p.substr(0, eq)] = p.substr(eq + 1);
    }
    const Progress progress = terminal_progress("methods", a.quiet || a.stats);
    io::LoadedInputs loaded = io::load_inputs(to_load_options(a.input), progress.sub(0.0, 0.1));
    // 2-D breakline vertices take the height of a survey point at their position, as in
    // triangulate(); then they join the points and each breakline segment becomes a constraint.
    (void)resolve_line_heights(loaded.terrain);
    std::vector<Point3> points = std::move(loaded.terrain.points);
    std::vector<methods::Segment> segments;
    for (const Polyline& line : loaded.terrain.breaklines) {
        for (std::size_t i = 0; i < line.points.size(); ++i) {
            points.push_back(line.points[i]);
            if (i > 0) {
                const auto b = static_cast<VertexIndex>(points.size() - 1);
                segments.emplace_back(b - 1, b);
            }
        }
    }
    if (!segments.empty() && !method->takes_constraints) {
        throw UsageError("methods run: method '" + a.name + "' takes no breaklines");
    }
    const auto start = std::chrono::steady_clock::now();
    const methods::MethodResult result =
        method->run(methods::MethodInput{points, segments}, options, progress.sub(0.1, 0.95));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    io::TinWriteOptions write_options;
    write_options.crs_wkt = loaded.crs_wkt;
    io::write_tin(result.tin, a.output, write_options);
    progress.report(1.0, "done");
    if (a.stats) {
        std::cout << "{\"method\": " << io::json_string(a.name) << ", \"points\": " << points.size()
                  << ", \"vertices\": " << result.tin.vertices.size()
                  << ", \"triangles\": " << result.tin.triangles.size()
                  << ", \"seconds\": " << io::json_number(seconds)
                  << ", \"counters\": " << counters_json(result.counters)
                  << (result.stats_json.empty() ? "" : ", ") << result.stats_json << "}"
                  << std::endl;
    }
    return 0;
}

}  // namespace

Command methods_command() {
    return {"methods",
            "The triangulation methods of the source literature: list them, run one",
            [](CLI::App& app) -> std::function<int()> {
                app.require_subcommand(1);
                auto run = std::make_shared<std::function<int()>>();

                auto json = std::make_shared<bool>(false);
                CLI::App* list = app.add_subcommand("list", "List every method of the registry");
                list->add_flag("--json", *json, "One JSON array with every field of the registry");
                list->callback([run, json] { *run = [json] { return run_list(*json); }; });

                auto args = std::make_shared<RunArgs>();
                CLI::App* one = app.add_subcommand("run", "Run one method on a point input");
                one->add_option("name", args->name, "Method name (dtm methods list)")->required();
                add_input_options(*one, args->input);
                one->add_option("-o,--output", args->output, "Output TIN (format by extension)")
                    ->required();
                one->add_option("--param", args->params,
                                "Method parameter KEY=VALUE (repeatable; see dtm methods list)");
                one->add_option("--seed", args->seed, "Seed of randomised methods (default 1)");
                one->add_option("--threads", args->threads, "Threads of parallel methods");
                one->add_flag("--stats", args->stats,
                              "Print one JSON object with the counters and seconds");
                one->add_flag("-q,--quiet", args->quiet, "No progress bar");
                one->callback([run, args] { *run = [args] { return run_method(*args); }; });

                return [run] { return (*run)(); };
            }};
}

}  // namespace dtm::cli
