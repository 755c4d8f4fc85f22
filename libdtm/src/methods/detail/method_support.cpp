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

void link_in_place(std::span<Triangle> triangles, std::size_t vertex_count) {
    // Each side a -> b with a < b is listed under a (a counting sort, so in triangle order, as
    // 3 t + s); a side with a > b finds its twin b -> a in b's row. About 3 entries of 4 bytes
    // per vertex plus the row starts: the links cost 16 bytes per vertex beyond the triangles.
    const auto from = [&](std::size_t t, std::size_t s) { return triangles[t].v[(s + 1) % 3]; };
    const auto to = [&](std::size_t t, std::size_t s) { return triangles[t].v[(s + 2) % 3]; };
    std::vector<std::uint32_t> start(vertex_count + 1, 0);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        triangles[t].n = {no_triangle, no_triangle, no_triangle};
        for (std::size_t s = 0; s < 3; ++s) {
            if (from(t, s) < to(t, s)) ++start[from(t, s) + 1];
        }
    }
    for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> side(start[vertex_count]);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (std::size_t s = 0; s < 3; ++s) {
            if (from(t, s) < to(t, s))
                side[start[from(t, s)]++] = static_cast<std::uint32_t>(3 * t + s);
        }
    }
    for (std::size_t v = vertex_count; v > 0; --v) start[v] = start[v - 1];  // undo the fill
    start[0] = 0;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (std::size_t s = 0; s < 3; ++s) {
            const VertexIndex a = from(t, s), b = to(t, s);
            if (a < b) continue;
            for (std::uint32_t k = start[b]; k < start[b + 1]; ++k) {
                const std::uint32_t u = side[k] / 3, r = side[k] % 3;
                if (to(u, r) == a) {
                    triangles[t].n[s] = u;
                    triangles[u].n[r] = static_cast<TriangleIndex>(t);
                    break;
                }
            }
        }
    }
}

std::vector<Triangle> link_triangles(std::span<const TriangleCorners> triangles,
                                     std::size_t vertex_count) {
    std::vector<Triangle> out(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) out[t].v = triangles[t];
    link_in_place(out, vertex_count);
    return out;
}

Tin tin_from_triangles(std::vector<Point3> vertices, std::span<const TriangleCorners> triangles) {
    Tin tin;
    tin.triangles = link_triangles(triangles, vertices.size());
    tin.vertices = std::move(vertices);
    return tin;
}

Tin tin_from_triangles(std::vector<Point3> vertices, std::vector<TriangleCorners>&& triangles) {
    Tin tin;
    tin.triangles.resize(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) tin.triangles[t].v = triangles[t];
    free_storage(triangles);  // the corners are in the Tin now: free them before the links are made
    link_in_place(tin.triangles, vertices.size());
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
