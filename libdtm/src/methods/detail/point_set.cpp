// SPDX-License-Identifier: MIT
// Preparing a method's input (distinct points, segments split and checked) and turning a planar
// edge set into a Tin (faces traced through the angular order at every vertex).
#include "methods/detail/point_set.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "dtm/core/error.hpp"
#include "methods/detail/planar.hpp"
#include "methods/detail/uniform_grid.hpp"

namespace dtm::methods::detail {
namespace {

using Edge = std::pair<VertexIndex, VertexIndex>;

std::uint64_t key(VertexIndex a, VertexIndex b) noexcept {
    return (static_cast<std::uint64_t>(a) << 32) | b;
}

Box2 bounds(std::span<const Point3> points) {
    Box2 box;
    for (const Point3& p : points) box.add(p);
    return box;
}

/// Splits every segment at the points strictly inside it.
std::vector<Edge> split_at_points(std::span<const Point3> points,
                                  std::vector<Edge> segments,
                                  CountingPredicates& pred) {
    if (segments.empty()) return segments;
    UniformGrid grid(bounds(points), points.size());
    for (VertexIndex i = 0; i < points.size(); ++i) grid.insert_point(points[i], i);
    std::vector<Edge> out;
    std::vector<VertexIndex> inside;
    for (const auto& [a, b] : segments) {
        inside.clear();
        grid.for_segment_cells(points[a], points[b], [&](std::size_t cell) {
            for (const std::uint32_t k : grid.items(cell)) {
                if (strictly_inside_segment(pred, points[a], points[b], points[k]))
                    inside.push_back(k);
            }
        });
        std::sort(inside.begin(), inside.end());
        inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
        // Points on one line are ordered along it by (x, y) from a.
        const bool forward =
            points[a].x < points[b].x || (points[a].x == points[b].x && points[a].y < points[b].y);
        std::sort(inside.begin(), inside.end(), [&](VertexIndex p, VertexIndex q) {
            const bool less = points[p].x < points[q].x ||
                              (points[p].x == points[q].x && points[p].y < points[q].y);
            return forward ? less : (p != q && !less);
        });
        VertexIndex from = a;
        for (const VertexIndex k : inside) {
            out.emplace_back(std::min(from, k), std::max(from, k));
            from = k;
        }
        out.emplace_back(std::min(from, b), std::max(from, b));
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

void check_crossings(std::span<const Point3> points,
                     std::span<const Edge> segments,
                     std::string_view method,
                     CountingPredicates& pred) {
    if (segments.size() < 2) return;
    UniformGrid grid(bounds(points), segments.size());
    for (std::uint32_t s = 0; s < segments.size(); ++s) {
        grid.for_segment_cells(points[segments[s].first], points[segments[s].second],
                               [&](std::size_t cell) {
                                   auto& items = grid.items(cell);
                                   if (items.empty() || items.back() != s) items.push_back(s);
                               });
    }
    for (int r = 0; r < grid.rows(); ++r) {
        for (int c = 0; c < grid.cols(); ++c) {
            const auto& items = grid.items(grid.index(c, r));
            for (std::size_t i = 0; i < items.size(); ++i) {
                for (std::size_t j = i + 1; j < items.size(); ++j) {
                    const Edge& e = segments[items[i]];
                    const Edge& f = segments[items[j]];
                    if (segments_conflict(pred, points[e.first], points[e.second], points[f.first],
                                          points[f.second])) {
                        throw InputError("method " + std::string(method) + ": segments " +
                                         std::to_string(e.first) + "-" + std::to_string(e.second) +
                                         " and " + std::to_string(f.first) + "-" +
                                         std::to_string(f.second) +
                                         " cross; the methods take non-crossing segments (dtm "
                                         "tin splits crossing breaklines)");
                    }
                }
            }
        }
    }
}

}  // namespace

PreparedInput prepare_input(const MethodInput& input,
                            std::string_view method,
                            CountingPredicates& pred) {
    PreparedInput out;
    const std::size_t n = input.points.size();
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const Point3& p = input.points[a];
        const Point3& q = input.points[b];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        return a < b;
    });
    std::vector<std::uint32_t> representative(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool same = i > 0 && input.points[order[i]].x == input.points[order[i - 1]].x &&
                          input.points[order[i]].y == input.points[order[i - 1]].y;
        representative[order[i]] = same ? representative[order[i - 1]] : order[i];
    }
    out.input_to_vertex.assign(n, no_vertex);
    for (std::size_t i = 0; i < n; ++i) {
        if (representative[i] == i) {
            out.input_to_vertex[i] = static_cast<VertexIndex>(out.points.size());
            out.points.push_back(input.points[i]);
        } else {
            out.input_to_vertex[i] = out.input_to_vertex[representative[i]];
            ++out.duplicates;
        }
    }
    std::vector<Edge> segments;
    for (const auto& [a, b] : input.segments) {
        if (a >= n || b >= n) {
            throw InputError("method " + std::string(method) + ": a segment names point " +
                             std::to_string(std::max(a, b)) + " of " + std::to_string(n));
        }
        const VertexIndex u = out.input_to_vertex[a];
        const VertexIndex v = out.input_to_vertex[b];
        if (u != v) segments.emplace_back(std::min(u, v), std::max(u, v));
    }
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
    out.segments = split_at_points(out.points, std::move(segments), pred);
    check_crossings(out.points, out.segments, method, pred);
    return out;
}

bool all_collinear(std::span<const Point3> points, CountingPredicates& pred) {
    if (points.size() < 3) return true;
    std::size_t j = 1;
    while (j < points.size() && points[j].x == points[0].x && points[j].y == points[0].y) ++j;
    if (j == points.size()) return true;
    for (std::size_t k = j + 1; k < points.size(); ++k) {
        if (pred.orient(points[0], points[j], points[k]) != 0) return false;
    }
    return true;
}

std::vector<VertexIndex> hull_boundary(std::span<const Point3> points, CountingPredicates& pred) {
    std::vector<VertexIndex> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](VertexIndex a, VertexIndex b) {
        return points[a].x < points[b].x ||
               (points[a].x == points[b].x && points[a].y < points[b].y);
    });
    // Andrew's monotone chain, popping only strict right turns (collinear points stay).
    std::vector<VertexIndex> lower;
    std::vector<VertexIndex> upper;
    for (const VertexIndex p : order) {
        while (lower.size() >= 2 &&
               pred.orient(points[lower[lower.size() - 2]], points[lower.back()], points[p]) < 0) {
            lower.pop_back();
        }
        lower.push_back(p);
    }
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        while (upper.size() >= 2 && pred.orient(points[upper[upper.size() - 2]],
                                                points[upper.back()], points[*it]) < 0) {
            upper.pop_back();
        }
        upper.push_back(*it);
    }
    lower.pop_back();
    upper.pop_back();
    lower.insert(lower.end(), upper.begin(), upper.end());
    // Start at the lowest, then leftmost point.
    const auto start =
        std::min_element(lower.begin(), lower.end(), [&](VertexIndex a, VertexIndex b) {
            return points[a].y < points[b].y ||
                   (points[a].y == points[b].y && points[a].x < points[b].x);
        });
    std::rotate(lower.begin(), start, lower.end());
    return lower;
}

Tin tin_from_edges(std::span<const Point3> points,
                   std::span<const Edge> edges,
                   std::span<const Edge> segments,
                   CountingPredicates& pred) {
    const std::size_t n = points.size();
    std::vector<std::vector<VertexIndex>> adj(n);
    for (const auto& [a, b] : edges) {
        adj[a].push_back(b);
        adj[b].push_back(a);
    }
    std::unordered_map<std::uint64_t, std::uint32_t> position;
    position.reserve(edges.size() * 2);
    for (VertexIndex u = 0; u < n; ++u) {
        auto& list = adj[u];
        std::sort(list.begin(), list.end(), [&](VertexIndex p, VertexIndex q) {
            return angle_before(pred, points[u], points[p], points[q]);
        });
        for (std::uint32_t k = 0; k < list.size(); ++k) position[key(u, list[k])] = k;
    }
    auto next_in_face = [&](VertexIndex u, VertexIndex v) {
        const auto& around = adj[v];
        const std::uint32_t k = position.at(key(v, u));
        return around[(k + around.size() - 1) % around.size()];
    };
    Tin tin;
    tin.vertices.assign(points.begin(), points.end());
    std::unordered_map<std::uint64_t, std::pair<TriangleIndex, int>> slot_of;  // directed edge
    std::unordered_map<std::uint64_t, bool> seen;
    seen.reserve(edges.size() * 2);
    int outer_faces = 0;
    for (VertexIndex u = 0; u < n; ++u) {
        for (const VertexIndex v : adj[u]) {
            if (seen[key(u, v)]) continue;
            std::vector<VertexIndex> face{u};
            VertexIndex a = u;
            VertexIndex b = v;
            while (true) {
                seen[key(a, b)] = true;
                const VertexIndex c = next_in_face(a, b);
                a = b;
                b = c;
                if (a == u && b == v) break;
                face.push_back(a);
                if (face.size() > n + 1)
                    throw std::logic_error("tin_from_edges: face does not close");
            }
            if (face.size() == 3 &&
                pred.orient(points[face[0]], points[face[1]], points[face[2]]) > 0) {
                const auto t = static_cast<TriangleIndex>(tin.triangles.size());
                Triangle tri;
                tri.v = {face[0], face[1], face[2]};
                tin.triangles.push_back(tri);
                for (int s = 0; s < 3; ++s) {
                    slot_of[key(tri.v[(s + 1) % 3], tri.v[(s + 2) % 3])] = {t, s};
                }
            } else if (++outer_faces > 1) {
                throw std::logic_error("tin_from_edges: a bounded face with " +
                                       std::to_string(face.size()) + " corners");
            }
        }
    }
    for (Triangle& tri : tin.triangles) {
        for (int s = 0; s < 3; ++s) {
            const auto it = slot_of.find(key(tri.v[(s + 2) % 3], tri.v[(s + 1) % 3]));
            if (it != slot_of.end()) tri.n[s] = it->second.first;
        }
    }
    for (const auto& [a, b] : segments) {
        tin.constraints.push_back({std::min(a, b), std::max(a, b), ConstraintKind::breakline});
    }
    std::sort(tin.constraints.begin(), tin.constraints.end(),
              [](const ConstrainedEdge& x, const ConstrainedEdge& y) {
                  return x.a < y.a || (x.a == y.a && x.b < y.b);
              });
    return tin;
}

}  // namespace dtm::methods::detail
