// SPDX-License-Identifier: MIT
// Smoothing contour lines without letting them cross or leave their triangle strip.
//
// Chaikin's corner cutting replaces every segment PQ by the points 3/4 P + 1/4 Q and
// 1/4 P + 3/4 Q; repeated, it converges to the quadratic B-spline of the polyline. Every
// iterate stays inside the union of the "corner triangles" H_i = (P_{i-1}, P_i, P_{i+1}) of the
// original polyline (convex hull property: each new segment either lies on an old one or joins
// two adjacent old segments, which share a corner triangle).
//
//        P_{i-1}            P_i lies on the TIN edge E_i = (u, w) shared by the triangles
//          \   t_{i-1}       t_{i-1} and t_i the line crosses. H_i is inside t_{i-1} u t_i when
//    u -----P_i----X--- w    the chord P_{i-1} P_{i+1} meets E_i at a point X inside the edge;
//          /   t_i          the surface height in H_i then lies between the level and z(X).
//        P_{i+1}
//
// A corner is cut only if X is strictly inside E_i and z(X) is strictly inside the height band
// of the level (half-way to the neighbouring levels). Otherwise, and at points that coincide
// with a TIN vertex, the point is pinned and the line is smoothed piecewise between pinned
// points. Hence every smoothed vertex stays in the triangles the line crosses, and the regions
// of different levels have disjoint heights on the surface: lines never cross.
//
// Reference: G. Chaikin, "An algorithm for high-speed curve generation", Computer Graphics and
// Image Processing 3, 1974.
#include "algo/detail/contour_smooth.hpp"

#include <cmath>

#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

/// Whether the corner at points[i] may be cut (see the file comment).
bool corner_is_free(const Tin& tin,
                    const RawChain& piece,
                    std::size_t prev,
                    std::size_t i,
                    std::size_t next,
                    std::pair<double, double> band) {
    const Point3& a = piece.points[prev];
    const Point3& p = piece.points[i];
    const Point3& b = piece.points[next];
    const Point3& u = tin.vertices[piece.edges[i][0]];
    const Point3& w = tin.vertices[piece.edges[i][1]];
    if (p.x == w.x && p.y == w.y) {
        return false;  // on a TIN vertex: other lines of this level may touch it
    }
    // The decision (are the neighbours on opposite sides of the edge?) is exact; the crossing
    // point X is a construction and only needs to be close.
    if (geom::orient2d(u, w, a) * geom::orient2d(u, w, b) >= 0) {
        return false;
    }
    const double ex = w.x - u.x, ey = w.y - u.y;
    const double da = ex * (a.y - u.y) - ey * (a.x - u.x);
    const double db = ex * (b.y - u.y) - ey * (b.x - u.x);
    const double s = da / (da - db);
    if (!(s > 0.0 && s < 1.0)) {
        return false;  // round-off disagrees with the exact sides: do not cut this corner
    }
    const double xx = a.x + s * (b.x - a.x), xy = a.y + s * (b.y - a.y);
    const double tau = ((xx - u.x) * ex + (xy - u.y) * ey) / (ex * ex + ey * ey);
    constexpr double margin = 1e-9;
    if (!(tau > margin && tau < 1.0 - margin)) {
        return false;
    }
    const double z = u.z + tau * (w.z - u.z);
    return z > band.first && z < band.second;
}

/// Chaikin on an open run of points with fixed ends.
std::vector<Point3> chaikin_open(std::vector<Point3> run, unsigned iterations) {
    for (unsigned it = 0; it < iterations && run.size() > 2; ++it) {
        std::vector<Point3> next;
        next.reserve(2 * run.size());
        next.push_back(run.front());
        for (std::size_t k = 0; k + 1 < run.size(); ++k) {
            const Point3& p = run[k];
            const Point3& q = run[k + 1];
            if (k > 0) {
                next.push_back({0.75 * p.x + 0.25 * q.x, 0.75 * p.y + 0.25 * q.y, p.z});
            }
            if (k + 2 < run.size()) {
                next.push_back({0.25 * p.x + 0.75 * q.x, 0.25 * p.y + 0.75 * q.y, p.z});
            }
        }
        next.push_back(run.back());
        run = std::move(next);
    }
    return run;
}

/// Chaikin on a closed ring (first point repeated last) with no pinned point.
std::vector<Point3> chaikin_closed(std::vector<Point3> ring, unsigned iterations) {
    for (unsigned it = 0; it < iterations && ring.size() > 3; ++it) {
        std::vector<Point3> next;
        next.reserve(2 * ring.size());
        for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
            const Point3& p = ring[k];
            const Point3& q = ring[k + 1];
            next.push_back({0.75 * p.x + 0.25 * q.x, 0.75 * p.y + 0.25 * q.y, p.z});
            next.push_back({0.25 * p.x + 0.75 * q.x, 0.25 * p.y + 0.75 * q.y, p.z});
        }
        next.push_back(next.front());
        ring = std::move(next);
    }
    return ring;
}

}  // namespace

std::vector<Point3> smooth_chain(const Tin& tin,
                                 const RawChain& piece,
                                 std::pair<double, double> band,
                                 unsigned iterations) {
    const std::vector<Point3>& pts = piece.points;
    const std::size_t n = pts.size();
    if (n < 3 || iterations == 0) {
        return pts;
    }
    std::vector<bool> pinned(n, false);
    pinned[0] = pinned[n - 1] = true;
    bool any_pinned = !piece.closed;
    for (std::size_t i = piece.closed ? 0 : 1; i + 1 < n; ++i) {
        const std::size_t prev = i > 0 ? i - 1 : n - 2;  // closed: points[n-1] == points[0]
        pinned[i] = !corner_is_free(tin, piece, prev, i, i + 1, band);
        any_pinned = any_pinned || pinned[i];
    }
    if (piece.closed && !any_pinned) {
        return chaikin_closed(pts, iterations);
    }
    // Rotate a closed ring so it starts at a pinned point, then smooth between pinned points.
    std::size_t start = 0;
    if (piece.closed) {
        while (!pinned[start]) {
            ++start;
        }
    }
    std::vector<Point3> order;
    const std::size_t m = piece.closed ? n - 1 : n;
    for (std::size_t k = 0; k < m; ++k) {
        order.push_back(pts[(start + k) % m]);
    }
    std::vector<bool> pin(m + (piece.closed ? 1 : 0));
    for (std::size_t k = 0; k < m; ++k) {
        pin[k] = pinned[(start + k) % m];
    }
    if (piece.closed) {
        order.push_back(order.front());
        pin[m] = true;
    }
    pin.front() = pin.back() = true;
    std::vector<Point3> out{order.front()};
    std::size_t from = 0;
    for (std::size_t k = 1; k < order.size(); ++k) {
        if (pin[k]) {
            const std::vector<Point3> run(order.begin() + static_cast<std::ptrdiff_t>(from),
                                          order.begin() + static_cast<std::ptrdiff_t>(k) + 1);
            const std::vector<Point3> smoothed = chaikin_open(run, iterations);
            out.insert(out.end(), smoothed.begin() + 1, smoothed.end());
            from = k;
        }
    }
    return out;
}

}  // namespace dtm::detail
