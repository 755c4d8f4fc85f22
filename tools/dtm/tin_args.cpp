// SPDX-License-Identifier: MIT
#include "tin_args.hpp"

#include <tbb/global_control.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dtm::cli {
namespace {

/// Bounds every parallel phase of this run (not only the triangulation's arena) to @p threads.
void limit_threads(unsigned threads) {
    static std::unique_ptr<tbb::global_control> control;
    if (threads > 0) {
        control = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, threads);
    }
}

}  // namespace

void add_tin_options(CLI::App& app, TriangulateOptions& options) {
    const std::map<std::string, DuplicateRule> rules{{"first", DuplicateRule::first},
                                                     {"mean", DuplicateRule::mean},
                                                     {"min", DuplicateRule::min},
                                                     {"max", DuplicateRule::max}};
    app.add_option("--snap", options.snap_distance,
                   "Merge points closer than D in xy (default 0: exact duplicates only)")
        ->check(CLI::NonNegativeNumber);
    app.add_option_function<std::string>(
           "--duplicates",
           [&options, rules](const std::string& name) { options.duplicates = rules.at(name); },
           "z of merged duplicates: first|mean|min|max (default first)")
        ->check(CLI::IsMember({"first", "mean", "min", "max"}));
    app.add_option("--max-edge", options.max_edge,
                   "Trim border triangles with an outward edge longer than L (default 0: off)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--z-tolerance", options.z_tolerance,
                   "Height difference at a breakline crossing reported as a conflict (default "
                   "0.001)")
        ->check(CLI::NonNegativeNumber);
    app.add_option_function<unsigned>(
        "--threads",
        [&options](unsigned threads) {
            options.threads = threads;
            limit_threads(threads);
        },
        "Worker threads for every phase: reading, triangulating, rasters, contours (default "
        "0: all cores)");
    std::vector<std::string> criteria;
    for (const Criterion c : all_criteria()) criteria.emplace_back(criterion_name(c));
    app.add_option_function<std::string>(
           "--optimize",
           [&options](const std::string& name) { options.optimize = *parse_criterion(name); },
           "Lawson flips under a criterion after the CDT, breaklines kept: delaunay (default: "
           "none), maxmin-angle, minmax-angle, shortest-diagonal, maxmin-circumradius, "
           "minmax-circumradius, maxmin-area, maxmin-height, maxmin-inradius, normals-angle, "
           "normal-jump (docs/optimize.md)")
        ->check(CLI::IsMember(criteria));
    app.add_option_function<std::string>(
           "--tiles",
           [&options](const std::string& value) {
               options.tiles = value == "auto" ? 0 : std::stoul(value);
           },
           "Tiles of the parallel triangulation: N or auto (default auto); never changes the "
           "result")
        ->check([](const std::string& value) -> std::string {
            if (value == "auto") return {};
            const bool digits = !value.empty() && value.size() < 10 &&
                                value.find_first_not_of("0123456789") == std::string::npos;
            return digits && std::stoul(value) > 0 ? std::string{}
                                                   : "--tiles takes a positive number or auto";
        });
}

}  // namespace dtm::cli
