// SPDX-License-Identifier: MIT
// The test design of thesis 001 chapter 4 on today's machine (bench/pseudo_thesis.sh).
//
//   pseudo_thesis [--sizes 1000,5000,...] [--sets 3] [--runs 3] [--dists uniform,gauss,cluster,arc]
//                 [--arc-max 30000] [--angles 10000]
//
// Timing tables (001 Tables 4.1-4.21): for the criteria MinLength, MaxMinAngle and MinMaxAngle,
// the incremental and the post-processing swap, each with the fast and the brute-force flip: the
// mean build time in ms over sets x runs per distribution and size (arc only up to --arc-max, as
// in the thesis), time/N, time/(N log10 N) and time/N^(4/3) in microseconds for uniform (the
// thesis' complexity tables, ms / N etc. there), the incremental swap's time against
// post-processing and the fast flip's against brute force in percent. Angle tables (001 §4.2,
// App. C): mean smallest and largest corner angle on uniform, gauss and cluster --angles points
// without swap, with post-processing and with the incremental swap, for all nine criteria.
// Every pseudo-triangulation built is checked (check_pseudo_triangulation).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "dtm/methods/point_sets.hpp"
#include "dtm/methods/registry.hpp"
#include "methods/pseudo.hpp"

namespace {

using namespace dtm;
using namespace dtm::methods;

struct Config {
    std::string swap, flip, criterion;
};

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ',')) out.push_back(item);
    return out;
}

double stat(const std::string& json, const std::string& key) {
    const auto k = json.find("\"" + key + "\": ");
    return std::stod(json.substr(k + key.size() + 4));
}

MethodResult run(const std::vector<Point3>& pts, const Config& c, double& seconds) {
    MethodOptions o;
    o.params = {{"swap", c.swap}, {"flip", c.flip}, {"criterion", c.criterion}};
    const auto t0 = std::chrono::steady_clock::now();
    MethodResult r = run_pseudo(MethodInput{pts, {}}, o, Progress{});
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto problems = check_pseudo_triangulation(r.tin.vertices, r.faces, 1);
    if (!problems.empty()) {
        std::fprintf(stderr, "INVALID pseudo-triangulation (%s %s %s, n=%zu): %s\n", c.swap.c_str(),
                     c.flip.c_str(), c.criterion.c_str(), pts.size(), problems[0].c_str());
    }
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::size_t> sizes{1000, 5000, 10000, 30000, 50000, 75000};
    unsigned sets = 3;
    unsigned runs = 3;
    std::vector<std::string> dists{"uniform", "gauss", "cluster", "arc"};
    std::size_t arc_max = 30000;
    std::size_t angle_n = 10000;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i];
        const std::string value = argv[i + 1];
        if (key == "--sizes") {
            sizes.clear();
            for (const auto& s : split(value)) sizes.push_back(std::stoul(s));
        } else if (key == "--sets") {
            sets = static_cast<unsigned>(std::stoul(value));
        } else if (key == "--runs") {
            runs = static_cast<unsigned>(std::stoul(value));
        } else if (key == "--dists") {
            dists = split(value);
        } else if (key == "--arc-max") {
            arc_max = std::stoul(value);
        } else if (key == "--angles") {
            angle_n = std::stoul(value);
        } else {
            std::fprintf(stderr, "pseudo_thesis: unknown option %s\n", key.c_str());
            return 2;
        }
    }
    const std::vector<std::string> criteria{"min-length", "maxmin-angle", "minmax-angle"};
    // time[config key][dist][n] = mean ms
    std::map<std::string, std::map<std::string, std::map<std::size_t, double>>> ms;
    for (const std::string& crit : criteria) {
        for (const std::string swap : {"incremental", "post"}) {
            for (const std::string flip : {"fast", "brute"}) {
                const Config c{swap, flip, crit};
                const std::string key = swap + "/" + flip + "/" + crit;
                for (const std::string& d : dists) {
                    for (const std::size_t n : sizes) {
                        if (d == "arc" && n > arc_max) continue;
                        double total = 0;
                        for (unsigned s = 0; s < sets; ++s) {
                            const auto pts = generate_points(*parse_distribution(d), n, 1 + s);
                            for (unsigned r = 0; r < runs; ++r) {
                                double sec = 0;
                                (void)run(pts, c, sec);
                                total += sec;
                            }
                        }
                        ms[key][d][n] = 1000.0 * total / double(sets * runs);
                        std::fprintf(stderr, "%s %s %zu: %.1f ms\n", key.c_str(), d.c_str(), n,
                                     ms[key][d][n]);
                    }
                }
            }
        }
    }
    std::printf("# Thesis 001 chapter 4 on today's machine\n\n");
    std::printf("Mean build time including the swap, %u sets x %u runs per cell, one thread.\n\n",
                sets, runs);
    for (const std::string& crit : criteria) {
        for (const std::string swap : {"incremental", "post"}) {
            for (const std::string flip : {"fast", "brute"}) {
                const std::string key = swap + "/" + flip + "/" + crit;
                std::printf("## %s, %s swap, %s flip [ms]\n\n| N |", crit.c_str(), swap.c_str(),
                            flip.c_str());
                for (const auto& d : dists) std::printf(" %s |", d.c_str());
                std::printf(" uniform t/N [us] | t/(N log N) [us] | t/N^(4/3) [us] |\n|---|");
                for (std::size_t i = 0; i < dists.size() + 3; ++i) std::printf("---|");
                std::printf("\n");
                for (const std::size_t n : sizes) {
                    std::printf("| %zu |", n);
                    for (const auto& d : dists) {
                        const auto it = ms[key][d].find(n);
                        if (it == ms[key][d].end()) {
                            std::printf(" |");
                        } else {
                            std::printf(" %.1f |", it->second);
                        }
                    }
                    const double t = ms[key]["uniform"][n] * 1000.0;  // us
                    const double x = double(n);
                    std::printf(" %.3f | %.4f | %.5f |\n", t / x, t / (x * std::log10(x)),
                                t / std::pow(x, 4.0 / 3.0));
                }
                std::printf("\n");
            }
        }
    }
    std::printf("## Incremental swap against post-processing (fast flip; %% faster)\n\n| N |");
    for (const auto& c : criteria) std::printf(" %s |", c.c_str());
    std::printf("\n|---|---|---|---|\n");
    for (const std::size_t n : sizes) {
        std::printf("| %zu |", n);
        for (const auto& c : criteria) {
            const double inc = ms["incremental/fast/" + c]["uniform"][n];
            const double post = ms["post/fast/" + c]["uniform"][n];
            std::printf(" %.0f |", 100.0 * (post - inc) / post);
        }
        std::printf("\n");
    }
    for (const std::string swap : {"incremental", "post"}) {
        std::printf("\n## Fast flip against brute force, %s swap (%% faster)\n\n| N |",
                    swap.c_str());
        for (const auto& c : criteria) std::printf(" %s |", c.c_str());
        std::printf("\n|---|---|---|---|\n");
        for (const std::size_t n : sizes) {
            std::printf("| %zu |", n);
            for (const auto& c : criteria) {
                const double fast = ms[swap + "/fast/" + c]["uniform"][n];
                const double brute = ms[swap + "/brute/" + c]["uniform"][n];
                std::printf(" %.0f |", 100.0 * (brute - fast) / brute);
            }
            std::printf("\n");
        }
    }
    std::printf("\n## Mean corner angles, %zu points [degrees: min / max]\n\n", angle_n);
    const std::vector<std::string> all{
        "random",           "min-length",        "max-length",
        "maxmin-angle",     "minmax-angle",      "maxmin-sum-angle",
        "minmax-sum-angle", "maxmin-angle-hull", "minmax-angle-hull"};
    for (const std::string d : {"uniform", "gauss", "cluster"}) {
        std::printf(
            "### %s\n\n| criterion | no swap | post-processing | incremental "
            "|\n|---|---|---|---|\n",
            d.c_str());
        const auto pts = generate_points(*parse_distribution(d), angle_n, 1);
        for (const auto& crit : all) {
            std::printf("| %s |", crit.c_str());
            for (const std::string swap : {"none", "post", "incremental"}) {
                double sec = 0;
                const MethodResult r = run(pts, {swap, "fast", crit}, sec);
                std::printf(" %.1f / %.1f |", stat(r.stats_json, "mean_min_angle"),
                            stat(r.stats_json, "mean_max_angle"));
            }
            std::printf("\n");
        }
        std::printf("\n");
    }
    return 0;
}
