// SPDX-License-Identifier: MIT
// Sibson's natural-neighbour interpolation by the Bowyer-Watson cavity.
//
// Inserting p into the Delaunay triangulation would delete the cavity: the triangles whose
// circumcircle contains p (they form a star-shaped polygon around p; in a constrained TIN the
// search does not cross constrained edges, which gives the cavity of the constrained
// insertion). Their circumcentres are the Voronoi vertices p's cell swallows. For a vertex v of
// the cavity border, with border edges u -> v -> w (counter-clockwise around p), the area p's
// cell takes from v's cell is the polygon
//     cc(v, w, p), cc(t_1), ..., cc(t_r), cc(u, v, p)
// where t_1 .. t_r are the cavity triangles around v, counter-clockwise from the one on the
// edge v -> w to the one on u -> v, and cc() is a circumcentre. Sibson's coordinate of v is its
// area over the sum of all of them.
//
// Decisions are exact: the cavity by incircle, a point on a vertex or on a barrier edge by
// orient2d. Only the areas are floating point, computed relative to p. A point on a barrier edge
// gets the linear interpolation along the edge, which is the limit of the coordinates from
// either side (the cell of p becomes an infinite strip whose parts in the cells of the edge's
// ends have the edge's barycentric widths).
//
// References: R. Sibson, "A brief description of natural neighbour interpolation", in
// Interpreting Multivariate Data, 1981; D. F. Watson, "Contouring: a guide to the analysis and
// display of spatial data", 1992 (the circumcentre construction); J.-D. Boissonnat and F.
// Cazals, "Smooth surface reconstruction via natural neighbour interpolation of distance
// functions", 2002 (properties).
#include "dtm/algo/natural_neighbour.hpp"

#include <cmath>

#include "algo/detail/edge_kinds.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

struct Xy {
    double x;
    double y;
};

/// Circumcentre of (0, 0), u, v.
Xy circumcentre0(double ux, double uy, double vx, double vy) {
    const double d = 2.0 * (ux * vy - uy * vx);
    const double u2 = ux * ux + uy * uy, v2 = vx * vx + vy * vy;
    return {(vy * u2 - uy * v2) / d, (ux * v2 - vx * u2) / d};
}

}  // namespace

double NaturalNeighbourSurface::linear(TriangleIndex t, double x, double y) const {
    const Triangle& tri = tin_.triangles[t];
    const Point3& a = tin_.vertices[tri.v[0]];
    const Point3& b = tin_.vertices[tri.v[1]];
    const Point3& c = tin_.vertices[tri.v[2]];
    const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    const double det = bx * cy - cx * by;
    const double px = x - a.x, py = y - a.y;
    const double l1 = (cy * px - cx * py) / det, l2 = (bx * py - by * px) / det;
    return a.z + l1 * (b.z - a.z) + l2 * (c.z - a.z);
}

double NaturalNeighbourSurface::value(TriangleIndex t0, double x, double y, Workspace& ws) const {
    const Triangle& first = tin_.triangles[t0];
    for (const VertexIndex v : first.v) {
        if (tin_.vertices[v].x == x && tin_.vertices[v].y == y) {
            return tin_.vertices[v].z;
        }
    }
    if (ws.stamp.size() != tin_.triangles.size()) {
        ws.stamp.assign(tin_.triangles.size(), 0);
        ws.epoch = 0;
    }
    if (++ws.epoch == 0) {
        std::fill(ws.stamp.begin(), ws.stamp.end(), 0);
        ws.epoch = 1;
    }
    const Point2 p{x, y};
    ws.cavity.assign(1, t0);
    ws.border.clear();
    ws.stamp[t0] = ws.epoch;
    for (std::size_t k = 0; k < ws.cavity.size(); ++k) {
        const TriangleIndex t = ws.cavity[k];
        for (std::size_t e = 0; e < 3; ++e) {
            const TriangleIndex u = tin_.triangles[t].n[e];
            if (!barrier(t, e) && ws.stamp[u] == ws.epoch) {
                continue;
            }
            if (!barrier(t, e)) {
                const auto& uv = tin_.triangles[u].v;
                if (geom::incircle(tin_.vertices[uv[0]], tin_.vertices[uv[1]], tin_.vertices[uv[2]],
                                   p) > 0) {
                    ws.stamp[u] = ws.epoch;
                    ws.cavity.push_back(u);
                    continue;
                }
            }
            ws.border.push_back({t, static_cast<int>((e + 1) % 3)});
        }
    }
    // A border edge that p lies on (a barrier: any other edge through p is inside the cavity):
    // the limit from both sides, linear along the edge.
    for (const auto& b : ws.border) {
        const auto& tv = tin_.triangles[b.t].v;
        const Point3& a = tin_.vertices[tv[static_cast<std::size_t>(b.corner)]];
        const Point3& c = tin_.vertices[tv[static_cast<std::size_t>((b.corner + 1) % 3)]];
        const int side = geom::orient2d(a, c, p);
        if (side == 0) {
            const double dx = c.x - a.x, dy = c.y - a.y;
            const double s = ((x - a.x) * dx + (y - a.y) * dy) / (dx * dx + dy * dy);
            return a.z + s * (c.z - a.z);
        }
        if (side < 0) {
            return linear(t0, x, y);  // not star-shaped around p: cannot happen on a valid TIN
        }
    }
    const auto cc_new = [&](const Point3& a, const Point3& b) {  // circumcentre of (a, b, p)
        return circumcentre0(a.x - x, a.y - y, b.x - x, b.y - y);
    };
    const auto cc_old = [&](TriangleIndex t) {
        const auto& tv = tin_.triangles[t].v;
        const Point3& a = tin_.vertices[tv[0]];
        const Point3& b = tin_.vertices[tv[1]];
        const Point3& c = tin_.vertices[tv[2]];
        const Xy r = circumcentre0(b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y);
        return Xy{r.x + (a.x - x), r.y + (a.y - y)};
    };
    double total = 0.0, weighted = 0.0;
    for (const auto& b : ws.border) {
        const auto& tv = tin_.triangles[b.t].v;
        const VertexIndex v = tv[static_cast<std::size_t>(b.corner)];
        const Point3& pv = tin_.vertices[v];
        Xy prev = cc_new(pv, tin_.vertices[tv[static_cast<std::size_t>((b.corner + 1) % 3)]]);
        const Xy start = prev;
        double twice_area = 0.0;
        const auto add = [&](Xy q) {
            twice_area += prev.x * q.y - prev.y * q.x;
            prev = q;
        };
        TriangleIndex cur = b.t;
        for (std::size_t guard = 0; guard <= ws.cavity.size(); ++guard) {
            add(cc_old(cur));
            const auto& cv = tin_.triangles[cur].v;
            const std::size_t k = cv[0] == v ? 0 : (cv[1] == v ? 1 : 2);
            const std::size_t e = (k + 1) % 3;  // the edge to cv[k + 2], counter-clockwise
            const TriangleIndex u = tin_.triangles[cur].n[e];
            if (barrier(cur, e) || ws.stamp[u] != ws.epoch) {
                add(cc_new(tin_.vertices[cv[(k + 2) % 3]], pv));
                break;
            }
            cur = u;
        }
        add(start);
        total += twice_area;
        weighted += twice_area * pv.z;
    }
    if (!(total > 0.0) || !std::isfinite(weighted)) {
        return linear(t0, x, y);
    }
    return weighted / total;
}

std::vector<std::uint8_t> natural_neighbour_barriers(const Tin& tin) {
    const detail::TriangleEdgeKinds kinds = detail::triangle_edge_kinds(tin);
    std::vector<std::uint8_t> bits(kinds.size(), 0);
    for (std::size_t t = 0; t < kinds.size(); ++t) {
        for (std::size_t e = 0; e < 3; ++e) {
            if (kinds[t][e] != detail::plain_edge) {
                bits[t] |= static_cast<std::uint8_t>(1U << e);
            }
        }
    }
    return bits;
}

}  // namespace dtm
