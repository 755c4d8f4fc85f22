// SPDX-License-Identifier: MIT
// methods_scaling: time of each triangulation method of the registry against the production
// kernel (`dc`, one thread) in the same run, on the lab's point sets, for a list of sizes.
// Prints per method and N: seconds (best of R), ns per N log2 N, the ratio to dc, the
// method's own peak bytes per point, flips and walk steps per point.
//
//   methods_scaling [--methods a,b:key=value:key=value,...] [--n 1000,10000,...] [--dist uniform]
//   [--repeat R]
//                   [--threads T] [--seed S] [--cap SECONDS]
//
// A method whose previous size took longer than --cap seconds (default 20) is skipped at the
// larger sizes (quadratic methods). Used by bench/methods_scaling.sh; figures in
// docs/performance.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "dtm/methods/point_sets.hpp"
#include "dtm/methods/registry.hpp"

namespace {

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ',')) {
        if (!item.empty()) out.push_back(item);
    }
    return out;
}

struct Run {
    double seconds = 0.0;
    dtm::methods::MethodCounters counters;
};

Run time_method(const dtm::methods::MethodInfo& m,
                const std::vector<dtm::Point3>& pts,
                const dtm::methods::MethodOptions& options,
                int repeat) {
    Run best;
    best.seconds = 1e300;
    for (int r = 0; r < repeat; ++r) {
        const auto start = std::chrono::steady_clock::now();
        const dtm::methods::MethodResult result =
            m.run(dtm::methods::MethodInput{pts, {}}, options, dtm::Progress{});
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (s < best.seconds) {
            best.seconds = s;
            best.counters = result.counters;
        }
    }
    return best;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> methods;
    std::vector<std::size_t> sizes{1000, 10000, 100000, 1000000};
    std::string dist = "uniform";
    int repeat = 3;
    unsigned threads = 1;
    std::uint64_t seed = 1;
    double cap = 20.0;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i];
        const std::string value = argv[i + 1];
        if (key == "--methods") {
            methods = split(value);
        } else if (key == "--n") {
            sizes.clear();
            for (const std::string& s : split(value)) sizes.push_back(std::stoull(s));
        } else if (key == "--dist") {
            dist = value;
        } else if (key == "--repeat") {
            repeat = std::max(1, std::stoi(value));
        } else if (key == "--threads") {
            threads = static_cast<unsigned>(std::stoul(value));
        } else if (key == "--seed") {
            seed = std::stoull(value);
        } else if (key == "--cap") {
            cap = std::stod(value);
        } else {
            std::fprintf(stderr, "methods_scaling: unknown option %s\n", key.c_str());
            return 2;
        }
    }
    const auto distribution = dtm::methods::parse_distribution(dist);
    if (!distribution) {
        std::fprintf(stderr, "methods_scaling: unknown distribution %s\n", dist.c_str());
        return 2;
    }
    if (methods.empty()) {
        for (const auto& m : dtm::methods::registry()) {
            if (m.family == dtm::methods::Family::delaunay && m.name != "dc") {
                methods.emplace_back(m.name);
            }
        }
    }
    std::printf("%-24s %9s %10s %12s %8s %8s %8s %8s\n", "method", "n", "seconds", "ns/(nlog2n)",
                "x dc", "B/point", "flips/n", "walk/n");
    std::map<std::string, double> last;
    for (const std::size_t n : sizes) {
        const auto pts = dtm::methods::generate_points(*distribution, n, seed);
        dtm::methods::MethodOptions options;
        options.threads = 1;
        options.seed = seed;
        const Run ref = time_method(*dtm::methods::find_method("dc"), pts, options, repeat);
        const double nlogn = static_cast<double>(n) * std::log2(static_cast<double>(n));
        std::printf("%-24s %9zu %10.4f %12.2f %8.2f %8s %8s %8s\n", "dc (1 thread)", n, ref.seconds,
                    1e9 * ref.seconds / nlogn, 1.0, "-", "-", "-");
        options.threads = threads;
        for (const std::string& spec : methods) {
            // name[:key=value]...
            std::vector<std::string> parts;
            std::stringstream in(spec);
            for (std::string part; std::getline(in, part, ':');) parts.push_back(part);
            const std::string name = spec;
            options.params.clear();
            for (std::size_t k = 1; k < parts.size(); ++k) {
                const auto eq = parts[k].find('=');
                options.params[parts[k].substr(0, eq)] =
                    eq == std::string::npos ? "" : parts[k].substr(eq + 1);
            }
            const dtm::methods::MethodInfo* m = dtm::methods::find_method(parts.at(0));
            if (m == nullptr) {
                std::fprintf(stderr, "methods_scaling: no method %s\n", name.c_str());
                return 2;
            }
            if (last.count(name) && last[name] > cap) {
                std::printf("%-24s %9zu %10s (previous size took %.1f s > cap)\n", name.c_str(), n,
                            "skipped", last[name]);
                continue;
            }
            const Run r = time_method(*m, pts, options, repeat);
            last[name] = r.seconds;
            const double per = static_cast<double>(n);
            std::printf("%-24s %9zu %10.4f %12.2f %8.2f %8.1f %8.2f %8.2f\n", name.c_str(), n,
                        r.seconds, 1e9 * r.seconds / nlogn, r.seconds / ref.seconds,
                        static_cast<double>(r.counters.peak_bytes) / per,
                        static_cast<double>(r.counters.flips) / per,
                        static_cast<double>(r.counters.walk_steps) / per);
            if (std::getenv("METHODS_SCALING_EXTRA") != nullptr) {
                for (const auto& [key, value] : r.counters.extra) {
                    std::printf("    %s = %llu (%.2f per point)\n", key.c_str(),
                                static_cast<unsigned long long>(value),
                                static_cast<double>(value) / per);
                }
            }
            std::fflush(stdout);
        }
    }
    return 0;
}
