// SPDX-License-Identifier: MIT
// Exact clipping of a Voronoi region against a triangle, and the merge of a region's pieces
// (thiessen_clip.hpp).
//
// Decisions. A piece vertex is tested against the half-plane of site k (points at least as near
// to the cell's site g as to k) by the predicate that fits its kind: an input point by
// compare_distances; the crossing X of region edge a-b with the bisector of g and h by
// crossing_order(a, b, g, h, k) (degree 4); the Voronoi vertex where the bisectors of g with
// h1 and h2 meet by incircle(g, h1, h2, k) (k strictly inside their circle means X is nearer to
// k). New vertices are only made where an edge's ends lie strictly on opposite sides, so a point
// exactly on a bisector keeps its first representation; the half-planes are applied in
// increasing site order, so the two triangles on either side of a region edge cut it into the
// same symbolic pieces, and the two copies of each shared piece of region edge cancel exactly.
//
// Coordinates. Crossings and Voronoi vertices are computed from the sites and region vertices
// in a fixed (sorted) order, so every cell sharing a point writes the same double.
#include "algo/detail/thiessen_clip.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>

#include "dtm/geom/bisector_predicates.hpp"
#include "dtm/geom/constructions.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

}  // namespace

int CellClipper::side(std::uint32_t g, const Sym& v, std::uint32_t k) const {
    const Point3& pg = sites_[g];
    const Point3& pk = sites_[k];
    switch (v.kind) {
        case Sym::input: {
            const Point3& p = region_[v.a];
            return geom::compare_distances(p, pg, p, pk);
        }
        case Sym::edge:
            return geom::crossing_order(region_[v.a].xy(), region_[v.b].xy(), pg.xy(),
                                        sites_[v.c].xy(), pk.xy());
        case Sym::bisectors: {
            const Point3& h1 = sites_[v.a];
            const Point3& h2 = sites_[v.b];
            return geom::incircle(pg, h1, h2, pk) * geom::orient2d(pg, h1, h2);
        }
    }
    return 0;
}

Sym CellClipper::crossing(const Support& s, std::uint32_t k) const {
    if (s.kind == Support::region_edge) {
        return Sym{Sym::edge, std::min(s.a, s.b), std::max(s.a, s.b), k};
    }
    return Sym{Sym::bisectors, std::min(s.a, k), std::max(s.a, k), 0};
}

void CellClipper::clip(std::uint32_t g,
                       std::span<const VertexIndex> neighbours,
                       const std::array<VertexIndex, 3>& tri,
                       Piece& out) const {
    out.clear();
    for (int i = 0; i < 3; ++i) {
        out.push_back({Sym{Sym::input, tri[i], 0, 0},
                       Support{Support::region_edge, tri[i], tri[(i + 1) % 3]}});
    }
    Piece next;
    std::vector<int> s;
    for (const VertexIndex k : neighbours) {
        const std::size_t m = out.size();
        s.resize(m);
        bool any_out = false, any_in = false;
        for (std::size_t i = 0; i < m; ++i) {
            s[i] = side(g, out[i].at, k);
            any_out = any_out || s[i] > 0;
            any_in = any_in || s[i] < 0;
        }
        if (!any_out) continue;
        if (!any_in) {  // outside, or touching the bisector only
            out.clear();
            return;
        }
        next.clear();
        for (std::size_t i = 0; i < m; ++i) {
            const std::size_t j = (i + 1) % m;
            const PieceVertex& u = out[i];
            if (s[i] <= 0) {
                PieceVertex kept = u;
                if (s[i] == 0 && s[j] > 0) kept.out = Support{Support::bisector, k, 0};
                next.push_back(kept);
            }
            if (s[i] < 0 && s[j] > 0) {
                next.push_back({crossing(u.out, k), Support{Support::bisector, k, 0}});
            } else if (s[i] > 0 && s[j] < 0) {
                next.push_back({crossing(u.out, k), u.out});
            }
        }
        out.swap(next);
        if (out.size() < 3) {
            out.clear();
            return;
        }
    }
}

Point2 CellClipper::position(std::uint32_t g, const Sym& v) const {
    switch (v.kind) {
        case Sym::input:
            return region_[v.a].xy();
        case Sym::edge: {
            const Point3& p = sites_[std::min(g, v.c)];
            const Point3& q = sites_[std::max(g, v.c)];
            const Point3& a = region_[v.a];
            const Point3& b = region_[v.b];
            // F(x) = |x - p|^2 - |x - q|^2 = (q - p) . ((x - p) + (x - q)), zero at the crossing.
            const auto f = [&](const Point3& x) {
                return (q.x - p.x) * ((x.x - p.x) + (x.x - q.x)) +
                       (q.y - p.y) * ((x.y - p.y) + (x.y - q.y));
            };
            const double fa = f(a), fb = f(b);
            const double t = fa / (fa - fb);
            return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        }
        case Sym::bisectors: {
            std::array<std::uint32_t, 3> t{g, v.a, v.b};
            std::sort(t.begin(), t.end());
            return geom::circumcentre(sites_[t[0]].xy(), sites_[t[1]].xy(), sites_[t[2]].xy());
        }
    }
    return {};
}

namespace {

struct Edge {
    Sym from, to;
    Support support;
    std::uint32_t piece;
    bool used = false;
};

double signed_area(const std::vector<Point2>& ring) {
    double a = 0.0;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
        const Point2& p = ring[i];
        const Point2& q = ring[(i + 1) % n];
        a += (p.x - ring[0].x) * (q.y - ring[0].y) - (q.x - ring[0].x) * (p.y - ring[0].y);
    }
    return 0.5 * a;
}

}  // namespace

void merge_pieces(std::uint32_t g,
                  const std::vector<Piece>& pieces,
                  const CellClipper& clipper,
                  std::span<const Point3> region_vertices,
                  ThiessenCell& out) {
    std::vector<Edge> edges;
    for (std::uint32_t p = 0; p < pieces.size(); ++p) {
        const Piece& piece = pieces[p];
        for (std::size_t i = 0; i < piece.size(); ++i) {
            edges.push_back({piece[i].at, piece[(i + 1) % piece.size()].at, piece[i].out, p});
        }
    }
    // The two copies of a region edge between two pieces: same ends, opposite directions.
    std::vector<std::uint32_t> parent(pieces.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::map<std::pair<Sym, Sym>, std::uint32_t> region_edges;
    for (std::uint32_t e = 0; e < edges.size(); ++e) {
        if (edges[e].support.kind != Support::region_edge) continue;
        const auto reverse = region_edges.find({edges[e].to, edges[e].from});
        if (reverse != region_edges.end() && !edges[reverse->second].used) {
            edges[e].used = edges[reverse->second].used = true;
            parent[find_root(parent, edges[e].piece)] =
                find_root(parent, edges[reverse->second].piece);
        } else {
            region_edges[{edges[e].from, edges[e].to}] = e;
        }
    }
    std::multimap<Sym, std::uint32_t> starting;
    for (std::uint32_t e = 0; e < edges.size(); ++e) {
        if (!edges[e].used) starting.emplace(edges[e].from, e);
    }
    // Rings. Where several edges leave one point (pieces touching there), take the first one
    // clockwise from the way back: it bounds the same piece of area.
    struct Ring {
        std::vector<Point2> points;
        bool outer = false;
        std::uint32_t component = 0;
    };
    std::vector<Ring> rings;
    for (std::uint32_t first = 0; first < edges.size(); ++first) {
        if (edges[first].used) continue;
        Ring ring;
        bool bisector = false;
        std::vector<Sym> syms;
        std::uint32_t e = first;
        while (!edges[e].used) {
            edges[e].used = true;
            bisector = bisector || edges[e].support.kind == Support::bisector;
            syms.push_back(edges[e].from);
            ring.points.push_back(clipper.position(g, edges[e].from));
            const auto [lo, hi] = starting.equal_range(edges[e].to);
            std::uint32_t best = e;
            double best_turn = 10.0;
            const Point2 at = clipper.position(g, edges[e].to);
            const Point2 back = ring.points.back();
            const double a_back = std::atan2(back.y - at.y, back.x - at.x);
            for (auto it = lo; it != hi; ++it) {
                if (edges[it->second].used) continue;
                const Point2 to = clipper.position(g, edges[it->second].to);
                double turn = a_back - std::atan2(to.y - at.y, to.x - at.x);
                while (turn <= 0.0) turn += 2 * std::numbers::pi;
                while (turn > 2 * std::numbers::pi) turn -= 2 * std::numbers::pi;
                if (turn < best_turn) {
                    best_turn = turn;
                    best = it->second;
                }
            }
            e = best;
        }
        ring.component = find_root(parent, edges[first].piece);
        if (bisector) {
            ring.outer = true;
        } else {
            // Region edges only: its orientation is the region's, decided exactly at the
            // lexicographically smallest corner (an input point).
            std::size_t m = 0;
            for (std::size_t i = 1; i < syms.size(); ++i) {
                const Point3& p = region_vertices[syms[i].a];
                const Point3& q = region_vertices[syms[m].a];
                if (p.x < q.x || (p.x == q.x && p.y < q.y)) m = i;
            }
            const std::size_t k = syms.size();
            ring.outer =
                geom::orient2d(region_vertices[syms[(m + k - 1) % k].a], region_vertices[syms[m].a],
                               region_vertices[syms[(m + 1) % k].a]) > 0;
        }
        rings.push_back(std::move(ring));
    }
    // Polygons: per connected group of pieces, its outer ring and its holes.
    std::map<std::uint32_t, std::size_t> polygon_of;
    for (const Ring& r : rings) {
        if (!r.outer) continue;
        polygon_of.emplace(r.component, out.polygons.size());
        out.polygons.push_back({{r.points}});
        out.area += signed_area(r.points);
    }
    for (const Ring& r : rings) {
        if (r.outer) continue;
        const auto it = polygon_of.find(r.component);
        if (it == polygon_of.end()) continue;  // cannot happen: a hole lies inside its piece
        out.polygons[it->second].rings.push_back(r.points);
        out.area += signed_area(r.points);
    }
}

}  // namespace dtm::detail
