// SPDX-License-Identifier: MIT
// [pseudo] The independent check of a pseudo-triangulation (pseudo.hpp): face shape, corners,
// edge pairing, boundary = convex hull, area, no crossing edges. Used by the tests and the lab.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "methods/detail/counting_predicates.hpp"
#include "methods/detail/planar.hpp"
#include "methods/detail/point_set.hpp"
#include "methods/detail/uniform_grid.hpp"
#include "pseudo.hpp"

namespace dtm::methods {
namespace {

double twice_area(std::span<const Point3> p, const std::vector<VertexIndex>& c) {
    double s = 0.0;
    const Point3& o = p[c[0]];
    for (std::size_t i = 1; i + 1 < c.size(); ++i) {
        s += (p[c[i]].x - o.x) * (p[c[i + 1]].y - o.y) - (p[c[i + 1]].x - o.x) * (p[c[i]].y - o.y);
    }
    return s;
}

}  // namespace

std::vector<std::string> check_pseudo_triangulation(std::span<const Point3> points,
                                                    const PolygonFaces& faces,
                                                    std::size_t limit) {
    std::vector<std::string> problems;
    auto report = [&](const std::string& s) {
        if (problems.size() < limit) problems.push_back(s);
    };
    detail::CountingPredicates pred;
    const std::size_t n = points.size();
    std::vector<bool> used(n, false);
    std::map<std::pair<VertexIndex, VertexIndex>, int> directed;
    double area = 0.0;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto& c = faces[f];
        const std::string name = "face " + std::to_string(f);
        if (c.size() < 3) {
            report(name + " has fewer than 3 vertices");
            continue;
        }
        std::set<VertexIndex> distinct(c.begin(), c.end());
        if (distinct.size() != c.size()) report(name + " repeats a vertex");
        std::size_t convex = 0;
        const std::size_t k = c.size();
        for (std::size_t i = 0; i < k; ++i) {
            if (c[i] >= n) {
                report(name + " names a missing vertex");
                return problems;
            }
            used[c[i]] = true;
            convex +=
                pred.orient(points[c[(i + k - 1) % k]], points[c[i]], points[c[(i + 1) % k]]) > 0;
            if (++directed[{c[i], c[(i + 1) % k]}] > 1) report(name + " repeats a directed edge");
        }
        if (convex != 3) report(name + " has " + std::to_string(convex) + " convex corners");
        const double a = twice_area(points, c);
        if (!(a > 0.0)) report(name + " is not counter-clockwise");
        area += a;
        for (std::size_t i = 0; i < k; ++i) {  // simple: no two non-adjacent edges meet
            for (std::size_t j = i + 2; j < k; ++j) {
                if (i == 0 && j == k - 1) continue;
                if (detail::segments_conflict(pred, points[c[i]], points[c[(i + 1) % k]],
                                              points[c[j]], points[c[(j + 1) % k]])) {
                    report(name + " is not a simple polygon");
                    i = k;
                    break;
                }
            }
        }
    }
    for (std::size_t v = 0; v < n; ++v) {
        if (!used[v]) {
            report("point " + std::to_string(v) + " is in no face");
            break;
        }
    }
    // Boundary edges (no reverse) must be the hull's, counter-clockwise.
    std::set<std::pair<VertexIndex, VertexIndex>> boundary;
    std::vector<std::pair<VertexIndex, VertexIndex>> undirected;
    for (const auto& [e, count] : directed) {
        if (!directed.count({e.second, e.first})) boundary.insert(e);
        if (e.first < e.second || !directed.count({e.second, e.first})) undirected.push_back(e);
    }
    if (!detail::all_collinear(points, pred)) {
        const auto hull = detail::hull_boundary(points, pred);
        std::set<std::pair<VertexIndex, VertexIndex>> hull_edges;
        for (std::size_t i = 0; i < hull.size(); ++i)
            hull_edges.emplace(hull[i], hull[(i + 1) % hull.size()]);
        if (boundary != hull_edges) report("the boundary of the faces is not the convex hull");
        double hull_area = 0.0;
        for (std::size_t i = 1; i + 1 < hull.size(); ++i) {
            const Point3& o = points[hull[0]];
            hull_area += (points[hull[i]].x - o.x) * (points[hull[i + 1]].y - o.y) -
                         (points[hull[i + 1]].x - o.x) * (points[hull[i]].y - o.y);
        }
        if (std::abs(area - hull_area) > 1e-9 * std::abs(hull_area)) {
            report("the faces' area differs from the hull's");
        }
    }
    // No two edges cross (bucket grid over the edges).
    Box2 box;
    for (const Point3& q : points) box.add(q);
    detail::UniformGrid grid(box, undirected.size());
    for (std::uint32_t e = 0; e < undirected.size(); ++e) {
        grid.for_segment_cells(points[undirected[e].first], points[undirected[e].second],
                               [&](std::size_t cell) {
                                   auto& items = grid.items(cell);
                                   if (items.empty() || items.back() != e) items.push_back(e);
                               });
    }
    std::size_t crossings = 0;
    for (int r = 0; r < grid.rows(); ++r) {
        for (int col = 0; col < grid.cols(); ++col) {
            const auto& items = grid.items(grid.index(col, r));
            for (std::size_t i = 0; i < items.size(); ++i) {
                for (std::size_t j = i + 1; j < items.size(); ++j) {
                    const auto& e = undirected[items[i]];
                    const auto& g = undirected[items[j]];
                    crossings += detail::segments_conflict(pred, points[e.first], points[e.second],
                                                           points[g.first], points[g.second]);
                }
            }
        }
    }
    if (crossings > 0) report(std::to_string(crossings) + " pairs of edges cross");
    return problems;
}

}  // namespace dtm::methods
