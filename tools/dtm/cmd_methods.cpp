// SPDX-License-Identifier: MIT
// `dtm methods`: the triangulation methods of the source literature, listed and run one by one.
//   dtm methods list [--json]
//   dtm methods run NAME INPUT -o OUT.ply [--stats] [--param KEY=VALUE]... [--seed S]
//   dtm methods compare [--methods a,b] [--n 1000,10000] [--dist uniform,gauss] [--repeat R]
//                       [--sets S] [--seed S] [--threads T] [--cap-seconds C] -o DIR
// Thin: parse -> lab::run_method / lab::registry_json / lab::run_compare + lab::write_compare
// -> print.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "command.hpp"
#include "dtm/core/error.hpp"
#include "dtm/lab/compare.hpp"
#include "dtm/lab/run.hpp"
#include "dtm/methods/registry.hpp"
#include "input_args.hpp"
#include "terminal_progress.hpp"

namespace dtm::cli {
namespace {

int run_list(bool json) {
    if (json) {
        std::printf("%s\n", lab::registry_json().c_str());
        return 0;
    }
    for (const methods::MethodInfo& m : methods::registry()) {
        std::printf("%-24s %-12s %-30s %s\n", std::string(m.name).c_str(),
                    std::string(methods::family_name(m.family)).c_str(),
                    std::string(m.complexity).c_str(), std::string(m.summary).c_str());
    }
    return 0;
}

struct RunArgs {
    std::string name;
    InputArgs input;
    std::string output;
    std::vector<std::string> params;
    std::map<std::string, std::string> aliases;  ///< --swap X means --param swap=X
    std::uint64_t seed = 1;
    unsigned threads = 0;
    bool stats = false;
    bool quiet = false;
};

int run_method(const RunArgs& a) {
    methods::MethodOptions options;
    options.seed = a.seed;
    options.threads = a.threads;
    for (const auto& [key, value] : a.aliases) {
        if (!value.empty()) options.params[key] = value;
    }
    for (const std::string& p : a.params) {
        const auto eq = p.find('=');
        if (eq == std::string::npos || eq == 0) {
            throw UsageError("methods run: --param expects KEY=VALUE, got '" + p + "'");
        }
        options.params[p.substr(0, eq)] = p.substr(eq + 1);
    }
    const lab::MethodRun run = lab::run_method(a.name, to_load_options(a.input), options, a.output,
                                               terminal_progress("methods", a.quiet || a.stats));
    if (a.stats) {
        std::cout << lab::method_stats_json(*run.method, run.points, run.result, run.seconds)
                  << std::endl;
    }
    return 0;
}

struct CompareArgs {
    lab::CompareOptions options;
    std::vector<std::string> distributions;
    std::string output;
    bool no_historical = false;
    bool quiet = false;
};

int run_compare(CompareArgs& a) {
    for (const std::string& d : a.distributions) {
        const auto parsed = methods::parse_distribution(d);
        if (!parsed) {
            throw UsageError(
                "methods compare: unknown distribution '" + d +
                "' (uniform, gauss, cluster, arc, grid, circle, collinear, duplicates)");
        }
        a.options.distributions.push_back(*parsed);
    }
    a.options.historical = !a.no_historical;
    const Progress progress = terminal_progress("methods compare", a.quiet);
    const lab::CompareResult result = lab::run_compare(a.options, progress);
    lab::write_compare(result, a.output);
    std::size_t ok = 0, capped = 0, other = 0;
    for (const lab::Measurement& c : result.cells) {
        (c.status == lab::Status::ok ? ok : c.status == lab::Status::capped ? capped : other) += 1;
    }
    std::printf("%zu cells measured, %zu capped, %zu refused or failed: %s\n", ok, capped, other,
                (std::filesystem::path(a.output) / "report.md").string().c_str());
    return 0;
}

}  // namespace

Command methods_command() {
    return {
        "methods", "The triangulation methods of the source literature: list, run, compare",
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
            one->add_option("-o,--output", args->output,
                            "Output TIN by extension; polygon faces (pseudo: .ply, .gpkg, .shp); a "
                            "folder of t001.ply ... (enumerate)")
                ->required();
            one->add_option("--param", args->params,
                            "Method parameter KEY=VALUE (repeatable; see dtm methods list)");
            for (const char* key : {"swap", "flip", "criterion"}) {
                one->add_option(std::string("--") + key, args->aliases[key],
                                std::string("Same as --param ") + key + "=VALUE");
            }
            one->add_option("--seed", args->seed, "Seed of randomised methods (default 1)");
            one->add_option("--threads", args->threads, "Threads of parallel methods");
            one->add_flag("--stats", args->stats,
                          "Print one JSON object with the counters and seconds");
            one->add_flag("-q,--quiet", args->quiet, "No progress bar");
            one->callback([run, args] { *run = [args] { return run_method(*args); }; });

            auto cmp = std::make_shared<CompareArgs>();
            CLI::App* compare =
                app.add_subcommand("compare", "Run methods side by side and write a report");
            compare
                ->add_option("--methods", cmp->options.methods,
                             "Methods to compare (default: all but enumerate)")
                ->delimiter(',');
            compare
                ->add_option("--n", cmp->options.sizes, "Point counts (default 1000,10000,100000)")
                ->delimiter(',');
            compare
                ->add_option("--dist", cmp->distributions,
                             "Distributions (default uniform,gauss,cluster,arc)")
                ->delimiter(',');
            compare->add_option("--sets", cmp->options.sets, "Point sets per cell (default 1)");
            compare->add_option("--repeat", cmp->options.repeat, "Runs per point set (default 1)");
            compare->add_option("--seed", cmp->options.seed,
                                "Seed of the first point set (default 1)");
            compare->add_option("--threads", cmp->options.threads,
                                "Threads of the parallel methods (default 1)");
            compare->add_option("--cap-seconds", cmp->options.cap_seconds,
                                "Skip a quadratic method where it would take longer (default 10)");
            compare->add_option("--histogram-n", cmp->options.histogram_size,
                                "Angle histograms at the largest N up to this (default 10000)");
            compare->add_flag("--no-historical", cmp->no_historical,
                              "Do not run uniform-grid at the sizes of the thesis' Fig. 36");
            compare->add_option("-o,--output", cmp->output, "Output folder")->required();
            compare->add_flag("-q,--quiet", cmp->quiet, "No progress bar");
            compare->callback([run, cmp] { *run = [cmp] { return run_compare(*cmp); }; });

            return [run] { return (*run)(); };
        }};
}

}  // namespace dtm::cli
