// SPDX-License-Identifier: MIT
// Shared parts of the greedy triangulations (greedy_common.hpp).
#include "methods/detail/greedy_common.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"
#include "methods/detail/method_support.hpp"

namespace dtm::methods::detail {
namespace {

double total_length(std::span<const Point3> p, std::span<const GreedyEdge> edges) {
    double sum = 0.0;
    double c = 0.0;
    for (const auto& [a, b] : edges) {
        const double v = std::hypot(p[b].x - p[a].x, p[b].y - p[a].y) - c;
        const double t = sum + v;
        c = (t - sum) - v;
        sum = t;
    }
    return sum;
}

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

}  // namespace

GreedySetup greedy_setup(const MethodInput& input,
                         const MethodOptions& options,
                         std::string_view method) {
    ParamReader(method, options).finish();
    GreedySetup s;
    s.input = prepare_input(input, method, s.pred);
    if (all_collinear(s.input.points, s.pred)) {
        throw InputError("method " + std::string(method) +
                         ": fewer than 3 distinct points or all points collinear");
    }
    const std::size_t n = s.input.points.size();
    const std::size_t h = hull_boundary(s.input.points, s.pred).size();
    s.target_edges = 3 * n - 3 - h;
    return s;
}

MethodResult greedy_result(GreedySetup& setup,
                           std::vector<GreedyEdge> edges,
                           std::string extra_json) {
    MethodResult result;
    const auto& points = setup.input.points;
    std::sort(edges.begin(), edges.end());
    result.tin = tin_from_edges(points, edges, setup.input.segments, setup.pred);
    // The reference: the constrained Delaunay triangulation of the same points and segments.
    TerrainInput terrain;
    terrain.points = points;
    for (const auto& [a, b] : setup.input.segments) {
        terrain.breaklines.push_back(Polyline{{points[a], points[b]}, false, {}});
    }
    const Tin cdt = triangulate(std::move(terrain)).tin;
    std::vector<GreedyEdge> cdt_edges;
    for (TriangleIndex t = 0; t < cdt.triangles.size(); ++t) {
        const Triangle& tri = cdt.triangles[t];
        for (int s = 0; s < 3; ++s) {
            if (tri.n[s] != no_triangle && tri.n[s] < t) continue;
            const VertexIndex a = tri.v[(s + 1) % 3];
            const VertexIndex b = tri.v[(s + 2) % 3];
            cdt_edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    const double greedy_len = total_length(points, edges);
    const double cdt_len = total_length(cdt.vertices, cdt_edges);
    setup.pred.add_to(result.counters);
    result.counters.extra["duplicates"] = setup.input.duplicates;
    result.counters.extra["edges"] = edges.size();
    result.stats_json = "\"edges\": " + std::to_string(edges.size()) +
                        ", \"total_length\": " + number(greedy_len) +
                        ", \"delaunay_total_length\": " + number(cdt_len) +
                        ", \"length_ratio\": " + number(greedy_len / cdt_len);
    if (!extra_json.empty()) result.stats_json += ", " + extra_json;
    return result;
}

}  // namespace dtm::methods::detail
