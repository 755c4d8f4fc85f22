// SPDX-License-Identifier: MIT
// Quality of the issue-12 triangulations against the constrained Delaunay TIN (dc), on the lab's
// distributions (bench/methods_quality.sh; docs/performance.md):
//
//   methods_quality [N] [SEEDS]
//
// Per method and distribution: the mean over triangles of the smallest angle and of the largest
// angle (degrees), the smallest angle anywhere, the edges a max-min-angle flip would improve
// (0 = Delaunay), the total edge length against dc's and the seconds. With constraints (every
// fourth Delaunay edge of the set, a stand-in for dense breaklines) for the methods that take them.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dtm/algo/criteria.hpp"
#include "dtm/methods/point_sets.hpp"
#include "dtm/methods/registry.hpp"

namespace {

using namespace dtm;
using namespace dtm::methods;

struct Quality {
    double mean_min = 0, mean_max = 0, min = 180, length = 0, seconds = 0;
    std::size_t improvable = 0;
};

Quality measure(const Tin& tin) {
    Quality q;
    const double deg = 180.0 / 3.14159265358979323846;
    const auto mins = quality_vector(tin, Criterion::maxmin_angle);
    const auto maxs = quality_vector(tin, Criterion::minmax_angle);
    for (const double v : mins) q.mean_min += v * deg;
    for (const double v : maxs) q.mean_max += v * deg;
    q.mean_min /= double(mins.size());
    q.mean_max /= double(maxs.size());
    q.min = mins.front() * deg;
    q.improvable = count_improvable_edges(tin, Criterion::maxmin_angle);
    q.length = summarize_quality(quality_vector(tin, Criterion::shortest_diagonal)).sum;
    return q;
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 5000;
    const unsigned seeds = argc > 2 ? static_cast<unsigned>(std::stoul(argv[2])) : 3;
    const std::vector<std::string> names{"dc", "greedy", "monotone"};
    for (const bool constrained : {false, true}) {
        std::printf("\n### %s, %zu points, mean of %u sets\n\n",
                    constrained ? "With every fourth Delaunay edge as a constraint" : "Points only",
                    n, seeds);
        std::printf(
            "| distribution | method | mean min angle | mean max angle | min angle | "
            "improvable (max-min) | length / dc | seconds |\n|---|---|---|---|---|---|---|---|\n");
        for (const Distribution d : lab_distributions()) {
            std::vector<Quality> sum(names.size());
            for (Quality& q : sum) q.min = 0.0;
            for (unsigned s = 1; s <= seeds; ++s) {
                const auto pts = generate_points(d, n, s);
                std::vector<Segment> segments;
                if (constrained) {
                    const Tin dt = find_method("dc")->run(MethodInput{pts, {}}, {}, {}).tin;
                    // dc's vertices are the distinct points in input order; map back by position.
                    std::vector<VertexIndex> first(dt.vertices.size());
                    for (std::size_t i = 0, v = 0; i < pts.size() && v < dt.vertices.size(); ++i) {
                        if (pts[i].x == dt.vertices[v].x && pts[i].y == dt.vertices[v].y)
                            first[v++] = static_cast<VertexIndex>(i);
                    }
                    std::size_t k = 0;
                    for (TriangleIndex ti = 0; ti < dt.triangles.size(); ++ti) {
                        const Triangle& t = dt.triangles[ti];
                        for (int e = 0; e < 3; ++e) {
                            if (t.n[e] != no_triangle && t.n[e] > ti && (k++ % 4) == 0) {
                                segments.emplace_back(first[t.v[(e + 1) % 3]],
                                                      first[t.v[(e + 2) % 3]]);
                            }
                        }
                    }
                }
                double dc_length = 0;
                for (std::size_t m = 0; m < names.size(); ++m) {
                    const MethodInfo* info = find_method(names[m]);
                    const auto t0 = std::chrono::steady_clock::now();
                    const MethodResult r = info->run(MethodInput{pts, segments}, {}, {});
                    const double sec =
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
                            .count();
                    Quality q = measure(r.tin);
                    if (m == 0) dc_length = q.length;
                    sum[m].mean_min += q.mean_min;
                    sum[m].mean_max += q.mean_max;
                    sum[m].min += q.min;
                    sum[m].improvable += q.improvable;
                    sum[m].length += q.length / dc_length;
                    sum[m].seconds += sec;
                }
            }
            for (std::size_t m = 0; m < names.size(); ++m) {
                const double k = seeds;
                std::printf("| %s | %s | %.2f | %.2f | %.3f | %.0f | %.4f | %.3f |\n",
                            std::string(distribution_name(d)).c_str(), names[m].c_str(),
                            sum[m].mean_min / k, sum[m].mean_max / k, sum[m].min / k,
                            double(sum[m].improvable) / k, sum[m].length / k, sum[m].seconds / k);
            }
        }
    }
    return 0;
}
