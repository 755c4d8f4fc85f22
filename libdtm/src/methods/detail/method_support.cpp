// SPDX-License-Identifier: MIT
// Shared plumbing of the Delaunay methods (method_support.hpp).
#include "methods/detail/method_support.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "algo/detail/exact_duplicates.hpp"
#include "dtm/core/error.hpp"

namespace dtm::methods::detail {

ParamReader::ParamReader(std::string_view method, const MethodOptions& options)
    : method_(method), options_(options) {}

std::string ParamReader::choice(std::string_view key,
                                std::initializer_list<std::string_view> allowed,
                                std::string_view fallback) {
    read_.insert(std::string(key));
    const auto it = options_.params.find(std::string(key));
    if (it == options_.params.end()) return std::string(fallback);
    std::string list;
    for (const std::string_view a : allowed) {
        if (a == it->second) return it->second;
        list += (list.empty() ? "" : "|") + std::string(a);
    }
    throw UsageError("method " + method_ + ": parameter " + std::string(key) + " is '" +
                     it->second + "', expected " + list);
}

double ParamReader::number(std::string_view key, double fallback, double lo, double hi) {
    read_.insert(std::string(key));
    const auto it = options_.params.find(std::string(key));
    if (it == options_.params.end()) return fallback;
    const std::string& text = it->second;
    double v = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc{} || end != text.data() + text.size() || !(v >= lo && v <= hi)) {
        throw UsageError("method " + method_ + ": parameter " + std::string(key) + " is '" + text +
                         "', expected a number in [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "]");
    }
    return v;
}

void ParamReader::finish() const {
    for (const auto& [key, value] : options_.params) {
        if (read_.count(key) == 0) {
            throw UsageError("method " + method_ + " has no parameter '" + key + "'");
        }
    }
}

PreparedPoints prepare_points(std::string_view method,
                              const MethodInput& input,
                              CountingPredicates& predicates) {
    if (!input.segments.empty()) {
        throw UsageError("method " + std::string(method) + " takes no breaklines");
    }
    for (std::size_t i = 0; i < input.points.size(); ++i) {
        const Point3& p = input.points[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            throw InputError("point " + std::to_string(i + 1) + " has a non-finite coordinate");
        }
    }
    if (input.points.size() >= no_vertex) {
        throw InputError("method " + std::string(method) + ": too many points");
    }
    PreparedPoints out;
    const auto first = dtm::detail::first_occurrences(input.points);
    out.vertices.reserve(input.points.size());
    for (std::size_t i = 0; i < input.points.size(); ++i) {
        if (first[i] == i) {
            out.vertices.push_back(input.points[i]);
        } else {
            ++out.duplicates;
        }
    }
    const std::size_t n = out.vertices.size();
    if (n < 3) {
        throw InputError("triangulation needs at least 3 distinct points; the input has " +
                         std::to_string(n));
    }
    for (std::size_t i = 2; i < n; ++i) {
        if (predicates.orient(out.vertices[0], out.vertices[1], out.vertices[i]) != 0) {
            return out;
        }
    }
    throw InputError("all " + std::to_string(n) +
                     " distinct points are collinear: there is no surface to triangulate");
}

std::vector<Triangle> link_triangles(std::span<const TriangleCorners> triangles,
                                     std::size_t vertex_count) {
    std::vector<Triangle> out(triangles.size());
    // Directed edges bucketed by origin: start[v] .. start[v + 1].
    std::vector<std::uint32_t> start(vertex_count + 1, 0);
    for (const TriangleCorners& t : triangles) {
        for (const VertexIndex v : t) ++start[v + 1];
    }
    for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    struct Out {
        VertexIndex to;
        std::uint32_t triangle;
    };
    std::vector<Out> edges(3 * triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        out[t].v = triangles[t];
        for (int i = 0; i < 3; ++i) {
            const VertexIndex a = triangles[t][static_cast<std::size_t>((i + 1) % 3)];
            const VertexIndex b = triangles[t][static_cast<std::size_t>((i + 2) % 3)];
            edges[fill[a]++] = {b, static_cast<std::uint32_t>(t)};
        }
    }
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (int i = 0; i < 3; ++i) {
            const VertexIndex a = triangles[t][static_cast<std::size_t>((i + 1) % 3)];
            const VertexIndex b = triangles[t][static_cast<std::size_t>((i + 2) % 3)];
            for (std::uint32_t k = start[b]; k < start[b + 1]; ++k) {
                if (edges[k].to == a) {
                    out[t].n[static_cast<std::size_t>(i)] = edges[k].triangle;
                    break;
                }
            }
        }
    }
    return out;
}

Tin tin_from_triangles(std::vector<Point3> vertices, std::span<const TriangleCorners> triangles) {
    Tin tin;
    tin.triangles = link_triangles(triangles, vertices.size());
    tin.vertices = std::move(vertices);
    return tin;
}

void finish_counters(MethodResult& result,
                     const CountingPredicates& predicates,
                     std::size_t duplicates,
                     std::size_t peak_bytes) {
    predicates.add_to(result.counters);
    result.counters.extra["duplicates"] = duplicates;
    result.counters.peak_bytes = std::max(result.counters.peak_bytes, peak_bytes);
}

}  // namespace dtm::methods::detail
