// SPDX-License-Identifier: MIT
/// @file
/// @brief Shared helpers of the methods tests: point sets (the library's generators plus the
/// test-only ones), running a method by name, triangle-set equality with the production
/// kernel, and one validator of "a Delaunay triangulation of these points".
///
/// is_delaunay_triangulation is stricter than verify_topology + verify_constrained_delaunay
/// alone: it also checks that every input point is a vertex (distinct points, in input order),
/// that every edge shared by two triangles is linked, that the boundary is one convex cycle
/// (the union of the triangles is the convex hull), and the counts 2n - 2 - h triangles and
/// 3n - 3 - h edges (h boundary vertices, collinear ones included).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"
#include "dtm/methods/point_sets.hpp"
#include "dtm/methods/registry.hpp"
#include "support/terrain_fixtures.hpp"

namespace dtm::methods::test {

using dtm::test::triangle_set;
using Params = std::map<std::string, std::string>;

/// S-JTSK magnitudes with survey millimetres: a 1 km square at (-750000, -1050000).
inline PointSetOptions sjtsk_mm(double size = 1000.0) {
    return PointSetOptions{-750000.0, -1050000.0, size, 0.001};
}

inline std::vector<Point3> points(Distribution d,
                                  std::size_t n,
                                  std::uint64_t seed = 1,
                                  const PointSetOptions& options = {}) {
    return generate_points(d, n, seed, options);
}

/// The distinct xy positions of @p input in order of first occurrence (what a method's Tin
/// has as vertices).
inline std::vector<Point3> distinct_points(std::span<const Point3> input) {
    std::set<std::pair<double, double>> seen;
    std::vector<Point3> out;
    for (const Point3& p : input) {
        // -0.0 and 0.0 are one position.
        const std::pair<double, double> key{p.x == 0.0 ? 0.0 : p.x, p.y == 0.0 ? 0.0 : p.y};
        if (seen.insert(key).second) out.push_back(p);
    }
    return out;
}

inline MethodResult run_method(std::string_view name,
                               std::span<const Point3> pts,
                               const Params& params = {},
                               std::uint64_t seed = 1,
                               unsigned threads = 1) {
    const MethodInfo* m = find_method(name);
    if (m == nullptr) throw std::invalid_argument("no method " + std::string(name));
    MethodOptions options;
    options.params = params;
    options.seed = seed;
    options.threads = threads;
    return m->run(MethodInput{pts, {}}, options, Progress{});
}

inline std::uint64_t undirected(VertexIndex a, VertexIndex b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | b;
}

/// Number of boundary edges of @p tin (= boundary vertices when the boundary is one cycle).
inline std::size_t boundary_edge_count(const Tin& tin) {
    std::size_t count = 0;
    for (const Triangle& t : tin.triangles) {
        for (const TriangleIndex n : t.n) count += n == no_triangle ? 1 : 0;
    }
    return count;
}

/// @p tin is a triangulation of @p input (see the file comment), and a Delaunay one when
/// @p delaunay is set.
inline ::testing::AssertionResult is_triangulation_of(const Tin& tin,
                                                      std::span<const Point3> input,
                                                      bool delaunay) {
    const CheckReport topo = verify_topology(tin);
    if (!topo.ok()) return ::testing::AssertionFailure() << "topology: " << topo.text();
    if (delaunay) {
        const CheckReport del = verify_constrained_delaunay(tin);
        if (!del.ok()) return ::testing::AssertionFailure() << "Delaunay: " << del.text();
    }
    const std::vector<Point3> expected = distinct_points(input);
    if (tin.vertices.size() != expected.size()) {
        return ::testing::AssertionFailure() << tin.vertices.size() << " vertices, expected "
                                             << expected.size() << " distinct points";
    }
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (tin.vertices[i].x != expected[i].x || tin.vertices[i].y != expected[i].y) {
            return ::testing::AssertionFailure() << "vertex " << i << " is not input point "
                                                 << "in order of first occurrence";
        }
    }
    // Edges: each shared one linked, boundary edges collected.
    std::unordered_map<std::uint64_t, int> uses;
    std::vector<bool> used(tin.vertices.size(), false);
    std::unordered_map<VertexIndex, VertexIndex> boundary_next;
    for (const Triangle& t : tin.triangles) {
        for (int i = 0; i < 3; ++i) {
            const VertexIndex a = t.v[static_cast<std::size_t>((i + 1) % 3)];
            const VertexIndex b = t.v[static_cast<std::size_t>((i + 2) % 3)];
            used[a] = true;
            ++uses[undirected(a, b)];
            if (t.n[static_cast<std::size_t>(i)] == no_triangle) {
                if (!boundary_next.emplace(a, b).second) {
                    return ::testing::AssertionFailure()
                           << "vertex " << a << " starts two boundary edges";
                }
            }
        }
    }
    std::size_t shared = 0;
    for (const auto& [key, count] : uses) shared += count == 2 ? 1 : 0;
    std::size_t linked = 0;
    for (const Triangle& t : tin.triangles) {
        for (const TriangleIndex n : t.n) linked += n != no_triangle ? 1 : 0;
    }
    if (linked != 2 * shared) {
        return ::testing::AssertionFailure()
               << shared << " shared edges but " << linked << " neighbour links";
    }
    for (std::size_t v = 0; v < used.size(); ++v) {
        if (!used[v]) return ::testing::AssertionFailure() << "vertex " << v << " in no triangle";
    }
    // The boundary is one convex cycle.
    if (boundary_next.empty()) return ::testing::AssertionFailure() << "no boundary";
    const VertexIndex start = boundary_next.begin()->first;
    VertexIndex prev = start;
    VertexIndex cur = boundary_next.at(start);
    std::size_t steps = 1;
    while (cur != start) {
        const auto it = boundary_next.find(cur);
        if (it == boundary_next.end()) return ::testing::AssertionFailure() << "open boundary";
        if (geom::orient2d(tin.vertices[prev], tin.vertices[cur], tin.vertices[it->second]) < 0) {
            return ::testing::AssertionFailure()
                   << "boundary turns right at vertex " << cur << ": not the convex hull";
        }
        prev = cur;
        cur = it->second;
        if (++steps > boundary_next.size()) break;
    }
    if (steps != boundary_next.size()) {
        return ::testing::AssertionFailure() << "the boundary is not one cycle";
    }
    if (geom::orient2d(tin.vertices[prev], tin.vertices[start],
                       tin.vertices[boundary_next.at(start)]) < 0) {
        return ::testing::AssertionFailure() << "boundary turns right: not the convex hull";
    }
    const std::size_t n = tin.vertices.size();
    const std::size_t h = boundary_next.size();
    if (tin.triangles.size() != 2 * n - 2 - h) {
        return ::testing::AssertionFailure() << tin.triangles.size() << " triangles, expected "
                                             << "2n - 2 - h = " << 2 * n - 2 - h;
    }
    if (uses.size() != 3 * n - 3 - h) {
        return ::testing::AssertionFailure()
               << uses.size() << " edges, expected 3n - 3 - h = " << 3 * n - 3 - h;
    }
    return ::testing::AssertionSuccess();
}

/// @p tin is a Delaunay triangulation of @p input: see the file comment.
inline ::testing::AssertionResult is_delaunay_triangulation(const Tin& tin,
                                                            std::span<const Point3> input) {
    return is_triangulation_of(tin, input, true);
}

/// @p tin is a triangulation of @p input (any triangulation of the convex hull with every
/// distinct point a vertex): greedy, monotone, optimised ones.
inline ::testing::AssertionResult is_triangulation(const Tin& tin, std::span<const Point3> input) {
    return is_triangulation_of(tin, input, false);
}

/// Every interior edge is strictly locally Delaunay: no four cocircular points decide the
/// triangulation, so it is the unique Delaunay triangulation of its vertices.
inline bool delaunay_is_unique(const Tin& tin) {
    for (TriangleIndex t = 0; t < tin.triangles.size(); ++t) {
        const Triangle& tri = tin.triangles[t];
        for (int i = 0; i < 3; ++i) {
            const TriangleIndex o = tri.n[static_cast<std::size_t>(i)];
            if (o == no_triangle || o < t) continue;
            const Triangle& other = tin.triangles[o];
            VertexIndex apex = no_vertex;
            for (int j = 0; j < 3; ++j) {
                if (other.n[static_cast<std::size_t>(j)] == t) {
                    apex = other.v[static_cast<std::size_t>(j)];
                }
            }
            const auto& v = tri.v;
            if (geom::incircle(tin.vertices[v[0]], tin.vertices[v[1]], tin.vertices[v[2]],
                               tin.vertices[apex]) >= 0) {
                return false;
            }
        }
    }
    return true;
}

/// Same triangles (as sets of positions) in both TINs.
inline ::testing::AssertionResult same_triangles(const Tin& a, const Tin& b) {
    const auto sa = triangle_set(a);
    const auto sb = triangle_set(b);
    if (sa == sb) return ::testing::AssertionSuccess();
    std::size_t only_a = 0;
    for (const auto& t : sa) only_a += sb.count(t) == 0 ? 1 : 0;
    std::size_t only_b = 0;
    for (const auto& t : sb) only_b += sa.count(t) == 0 ? 1 : 0;
    return ::testing::AssertionFailure()
           << sa.size() << " vs " << sb.size() << " triangles; " << only_a << " only in the first, "
           << only_b << " only in the second";
}

/// The production kernel's TIN of @p pts (the reference).
inline Tin reference_tin(std::span<const Point3> pts) { return run_method("dc", pts).tin; }

/// Expect @p name to give a valid Delaunay triangulation of @p pts, equal to the production
/// kernel's when the Delaunay triangulation is unique.
inline void expect_delaunay_like_dc(std::string_view name,
                                    std::span<const Point3> pts,
                                    const Params& params = {},
                                    std::uint64_t seed = 1,
                                    unsigned threads = 1) {
    const MethodResult r = run_method(name, pts, params, seed, threads);
    EXPECT_TRUE(is_delaunay_triangulation(r.tin, pts)) << name;
    const Tin ref = reference_tin(pts);
    if (delaunay_is_unique(ref)) {
        EXPECT_TRUE(same_triangles(r.tin, ref)) << name;
    }
}

/// A hand-made broken TIN for testing the validator: the triangles of @p tin without its
/// first one.
inline Tin without_first_triangle(Tin tin) {
    const TriangleIndex gone = 0;
    tin.triangles.erase(tin.triangles.begin());
    for (Triangle& t : tin.triangles) {
        for (TriangleIndex& n : t.n) {
            if (n == gone) {
                n = no_triangle;
            } else if (n != no_triangle) {
                --n;
            }
        }
    }
    return tin;
}

}  // namespace dtm::methods::test
