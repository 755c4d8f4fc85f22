// SPDX-License-Identifier: MIT
// The Voronoi diagram's exact validator, edge directions and the Preparata-Shamos edge-node form
// (dtm/methods/voronoi.hpp). Thesis 000 §3.3 (properties), §3.3.2 (DCEL, VRCHOL, OBLAST; its
// erratum 6, "a := a", is read as a := HV[j]).
#include "dtm/methods/voronoi.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "algo/detail/exact_duplicates.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::methods {
namespace {

using HalfEdge = VoronoiDiagram::HalfEdge;
constexpr std::uint32_t none = VoronoiDiagram::none;

class Checker {
public:
    Checker(const VoronoiDiagram& d, std::span<const Point3> g)
        : d_(d), g_(g), first_(dtm::detail::first_occurrences(g)) {}

    CheckReport run(bool geometry) {
        if (!structure()) return std::move(report_);
        cycles();
        vertices();
        if (geometry && report_.ok()) geometry_checks();
        return std::move(report_);
    }

private:
    const VoronoiDiagram& d_;
    std::span<const Point3> g_;
    dtm::detail::BigArray<VertexIndex> first_;
    CheckReport report_;
    std::vector<std::uint32_t> prev_;

    void fail(const std::string& what) {
        if (report_.problems.size() < 8) report_.problems.push_back(what);
    }
    [[nodiscard]] std::uint32_t dest(std::uint32_t h) const { return d_.half_edges[h ^ 1u].origin; }
    [[nodiscard]] const Point3& site(std::uint32_t h) const { return g_[d_.half_edges[h].face]; }

    bool structure() {
        const auto& he = d_.half_edges;
        if (he.size() % 2 != 0) fail("odd number of half-edges");
        if (d_.face_edge.size() != g_.size()) fail("face_edge is not one per generator");
        for (std::uint32_t h = 0; h < he.size(); ++h) {
            const HalfEdge& e = he[h];
            if (e.origin != none && e.origin >= d_.vertices.size()) fail("origin out of range");
            if (e.next >= he.size()) fail("next out of range");
            if (e.face >= g_.size()) fail("face out of range");
        }
        if (!report_.ok()) return false;
        prev_.assign(he.size(), none);
        for (std::uint32_t h = 0; h < he.size(); ++h) {
            const HalfEdge& e = he[h];
            if (prev_[e.next] != none) fail("two half-edges share a next");
            prev_[e.next] = h;
            if (he[e.next].face != e.face) fail("next leaves the face");
            if (he[e.next].origin != dest(h)) fail("next does not start where the half-edge ends");
            if (he[h ^ 1u].face == e.face) fail("an edge has the same generator on both sides");
        }
        return report_.ok();
    }

    void cycles() {
        const auto& he = d_.half_edges;
        std::vector<bool> seen(he.size(), false);
        std::size_t faces = 0;
        for (std::uint32_t f = 0; f < d_.face_edge.size(); ++f) {
            const std::uint32_t start = d_.face_edge[f];
            const bool duplicate = is_duplicate(f);
            if (start == none) {
                if (!duplicate && he.size() > 0)
                    fail("generator " + std::to_string(f) + " has no region");
                continue;
            }
            if (duplicate) fail("a duplicate generator has a region");
            if (start >= he.size() || he[start].face != f) {
                fail("face_edge of " + std::to_string(f) + " is not on its region");
                continue;
            }
            ++faces;
            std::set<std::uint32_t> neighbours;
            std::uint32_t h = start;
            std::size_t guard = 0;
            do {
                if (seen[h]) {
                    fail("region " + std::to_string(f) + " does not close");
                    return;
                }
                seen[h] = true;
                if (!neighbours.insert(he[h ^ 1u].face).second) {
                    fail("regions " + std::to_string(f) + " and " +
                         std::to_string(he[h ^ 1u].face) + " share two edges");
                }
                h = he[h].next;
            } while (h != start && ++guard <= he.size());
        }
        if (std::find(seen.begin(), seen.end(), false) != seen.end()) {
            fail("a half-edge is on no region's cycle (two cycles in one region?)");
        }
        const auto v = static_cast<long long>(d_.vertices.size());
        const auto e = static_cast<long long>(he.size() / 2);
        if (he.size() > 0 && v - e + static_cast<long long>(faces) != 1) {
            fail("V - E + F = " + std::to_string(v - e + static_cast<long long>(faces)) +
                 ", expected 1");
        }
    }

    [[nodiscard]] bool is_duplicate(std::uint32_t f) const { return first_[f] != f; }

    /// The half-edges out of each vertex, in counter-clockwise order.
    [[nodiscard]] std::vector<std::vector<std::uint32_t>> rotations() {
        const auto& he = d_.half_edges;
        std::vector<std::uint32_t> out(d_.vertices.size(), none);
        std::vector<std::size_t> degree(d_.vertices.size(), 0);
        for (std::uint32_t h = 0; h < he.size(); ++h) {
            if (he[h].origin != none) {
                out[he[h].origin] = h;
                ++degree[he[h].origin];
            }
        }
        std::vector<std::vector<std::uint32_t>> rot(d_.vertices.size());
        for (std::uint32_t v = 0; v < rot.size(); ++v) {
            if (out[v] == none) {
                fail("vertex " + std::to_string(v) + " has no edge");
                continue;
            }
            std::uint32_t h = out[v];
            do {
                rot[v].push_back(h);
                h = prev_[h] ^ 1u;  // counter-clockwise: the twin of the half-edge before
            } while (h != out[v] && rot[v].size() <= degree[v]);
            if (rot[v].size() != degree[v]) fail("the edges around a vertex form two cycles");
            if (degree[v] < 3)
                fail("vertex " + std::to_string(v) + " has degree " + std::to_string(degree[v]));
        }
        return rot;
    }

    void vertices() {
        const auto rot = rotations();
        for (const auto& r : rot) {
            std::set<std::uint32_t> faces;
            for (std::uint32_t h : r) {
                if (!faces.insert(d_.half_edges[h].face).second)
                    fail("a region meets a vertex twice");
            }
        }
        rot_ = rot;
    }
    std::vector<std::vector<std::uint32_t>> rot_;

    void geometry_checks() {
        const auto& he = d_.half_edges;
        for (std::uint32_t v = 0; v < rot_.size(); ++v) {
            const auto& r = rot_[v];
            const std::size_t k = r.size();
            const Point3& a = site(r[0]);
            const Point3& b = site(r[1]);
            const Point3& c = site(r[2]);
            for (std::size_t i = 0; i < k; ++i) {
                const Point3& p = site(r[i]);
                const Point3& q = site(r[(i + 1) % k]);
                const Point3& s = site(r[(i + 2) % k]);
                if (geom::orient2d(p, q, s) <= 0) {
                    fail("the generators around vertex " + std::to_string(v) + " are not ccw");
                }
                if (i >= 3 && geom::incircle(a, b, c, p) != 0) {
                    fail("the generators around vertex " + std::to_string(v) +
                         " are not cocircular");
                }
            }
            check_position(v, a, b, c);
        }
        for (std::uint32_t h = 0; h < he.size(); ++h) {
            // Local Delaunay: beyond the end of h, the next generator around the end vertex is
            // not inside the circle of the vertex at h's origin.
            const std::uint32_t u = he[h].origin;
            const std::uint32_t w = dest(h);
            if (u == none && w == none) {
                // Only collinear generators have whole lines, and then no vertices.
                if (!d_.vertices.empty()) fail("a whole line in a diagram with vertices");
                continue;
            }
            if (u == none || w == none) {
                unbounded(h);
                continue;
            }
            const Point3& a = site(h);
            const Point3& b = site(h ^ 1u);
            const Point3& c = site(prev_[h] ^ 1u);    // a further region at u
            const Point3& d = site(he[h].next ^ 1u);  // a further region at w
            // Around u counter-clockwise come b, a, c: (b, a, c) is ccw on u's circle, and d
            // must be strictly outside it (on it, the edge would have length zero).
            if (geom::incircle(b, a, c, d) >= 0) {
                fail("edge " + std::to_string(h) + " is not strictly locally Delaunay");
            }
        }
    }

    /// An unbounded edge separates two hull neighbours: no generator is strictly on the outer
    /// side of the line through them... checked locally: the neighbours beyond its finite end
    /// lie on the inner side.
    void unbounded(std::uint32_t h) {
        const auto& he = d_.half_edges;
        // Orient h so that it runs to infinity.
        const std::uint32_t out = he[h].origin == none ? (h ^ 1u) : h;
        const Point3& p = site(out);       // on its left
        const Point3& q = site(out ^ 1u);  // on its right
        // Running to infinity with p on the left: the hull edge is q -> p (ccw), and the third
        // generator at the finite end must be strictly left of q -> p.
        const Point3& c = site(prev_[out] ^ 1u);
        if (geom::orient2d(q, p, c) <= 0)
            fail("an unbounded edge does not separate hull neighbours");
    }

    void check_position(std::uint32_t v, const Point3& a, const Point3& b, const Point3& c) {
        const Point2 x = d_.vertices[v];
        const double ra = std::hypot(x.x - a.x, x.y - a.y);
        const double rb = std::hypot(x.x - b.x, x.y - b.y);
        const double rc = std::hypot(x.x - c.x, x.y - c.y);
        const double scale = std::max({ra, rb, rc, 1e-300});
        if (!(std::abs(ra - rb) <= 1e-6 * scale && std::abs(ra - rc) <= 1e-6 * scale)) {
            fail("vertex " + std::to_string(v) + " is not at its generators' circumcentre");
        }
    }
};

}  // namespace

Point2 voronoi_direction(const VoronoiDiagram& diagram,
                         std::span<const Point3> generators,
                         std::uint32_t h) {
    const Point3& p = generators[diagram.half_edges[h].face];
    const Point3& q = generators[diagram.half_edges[h ^ 1u].face];
    return {-(q.y - p.y), q.x - p.x};
}

CheckReport verify_voronoi(const VoronoiDiagram& diagram,
                           std::span<const Point3> generators,
                           bool exact_geometry) {
    return Checker(diagram, generators).run(exact_geometry);
}

EdgeNodeDcel edge_node_dcel(const VoronoiDiagram& diagram) {
    const auto& he = diagram.half_edges;
    std::vector<std::uint32_t> prev(he.size(), none);
    for (std::uint32_t h = 0; h < he.size(); ++h) prev[he[h].next] = h;
    EdgeNodeDcel d;
    const std::size_t m = he.size() / 2;
    d.v1.resize(m);
    d.v2.resize(m);
    d.f1.resize(m);
    d.f2.resize(m);
    d.p1.resize(m);
    d.p2.resize(m);
    d.hv.assign(diagram.vertices.size(), none);
    d.hf.assign(diagram.face_edge.size(), none);
    for (std::uint32_t e = 0; e < m; ++e) {
        d.v1[e] = he[2 * e].origin;
        d.v2[e] = he[2 * e + 1].origin;
        d.f1[e] = he[2 * e].face;
        d.f2[e] = he[2 * e + 1].face;
        // Around V1 counter-clockwise after e comes the other edge of F1 at V1: the one F1's
        // cycle arrives at V1 by (across the arc at infinity when V1 is there).
        d.p1[e] = prev[2 * e] / 2;
        d.p2[e] = prev[2 * e + 1] / 2;
        if (d.v1[e] != none) d.hv[d.v1[e]] = e;
        if (d.v2[e] != none) d.hv[d.v2[e]] = e;
        d.hf[d.f1[e]] = e;
        d.hf[d.f2[e]] = e;
    }
    return d;
}

std::vector<std::uint32_t> vrchol(const EdgeNodeDcel& dcel, std::uint32_t j) {
    std::vector<std::uint32_t> a_list;
    const std::uint32_t a0 = dcel.hv[j];
    std::uint32_t a = a0;
    do {
        a_list.push_back(a);
        a = dcel.v1[a] == j ? dcel.p1[a] : dcel.p2[a];
    } while (a != a0 && a_list.size() <= dcel.v1.size());
    return a_list;
}

std::vector<std::uint32_t> oblast(const EdgeNodeDcel& dcel, std::uint32_t j) {
    std::vector<std::uint32_t> a_list;
    const std::uint32_t a0 = dcel.hf[j];
    if (a0 == EdgeNodeDcel::none) return a_list;
    std::uint32_t a = a0;
    do {
        a_list.push_back(a);
        a = dcel.f1[a] == j ? dcel.p1[a] : dcel.p2[a];
    } while (a != a0 && a_list.size() <= dcel.v1.size());
    return a_list;
}

}  // namespace dtm::methods
