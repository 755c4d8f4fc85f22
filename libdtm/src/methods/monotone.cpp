// SPDX-License-Identifier: MIT
// [monotone] Constrained ("bound", vazana) triangulation after Preparata and Shamos,
// "Computational Geometry: An Introduction" (1985), thesis 000 §3.2 (R20-R26).
//
// The planar straight-line graph: the points, the constraint segments (non-crossing, split where
// a point lies on them) and the boundary of the domain: the convex hull (domain=hull, default:
// the output vertices are exactly the distinct input points) or the thesis' bounding rectangle
// PRAV(S) (domain=rectangle: its corners are added as vertices after the input points, with the
// height of the nearest input point).
//
// Vertex order (R21): u is above v iff y_u > y_v, or y equal and x_u < x_v ("larger x first" in
// the thesis' increasing numbering): a symbolic tilt of the sweep line, under which horizontal
// edges need no special case.
// Regularisation (R22), two plane sweeps. Pass 1 sweeps top-down; the status is a balanced tree
// of the edges crossing the sweep line, left to right, and each gap between two of them keeps
// the last vertex swept inside it (P&S: "the interval's vertex"). A vertex without an edge up
// is joined to its gap's vertex: the region between them holds no vertex or edge, so the new
// edge crosses nothing. Pass 2 is pass 1 on the point set turned by 180 degrees (an exact
// negation, which reverses the order and keeps orientations), fixing vertices without an edge
// down. Afterwards every face is a polygon without interior cusps, hence y-monotone (R23,
// checked). Each face is triangulated by the stack method of §3.2.2 in linear time with k - 3
// diagonals (R24; erratum 5: v1 is the bottom of the stack). The edge weights of the chain
// method (R25) are balanced and checked on the regularised graph. The result is no Delaunay
// triangulation: no quality criterion is applied (thesis: "for better triangles, e.g. the
// vertex with the nearer y").
#include "monotone.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "dtm/core/error.hpp"
#include "methods/detail/method_support.hpp"
#include "methods/detail/planar.hpp"
#include "methods/detail/point_set.hpp"

namespace dtm::methods {
namespace {

using Edge = std::pair<VertexIndex, VertexIndex>;

Edge undirected(VertexIndex a, VertexIndex b) { return {std::min(a, b), std::max(a, b)}; }

/// The planar graph being regularised and triangulated.
struct Graph {
    std::vector<Point3> points;
    std::vector<std::vector<VertexIndex>> adj;
    std::set<Edge> edges;

    void add(VertexIndex a, VertexIndex b) {
        if (a == b || !edges.insert(undirected(a, b)).second) return;
        adj[a].push_back(b);
        adj[b].push_back(a);
    }
};

/// u above v in the tilted order, on coordinates p.
bool above(const std::vector<Point3>& p, VertexIndex u, VertexIndex v) {
    return p[u].y > p[v].y || (p[u].y == p[v].y && p[u].x < p[v].x);
}

/// One top-down regularisation sweep over coordinates @p p (the graph's points, possibly turned).
/// Returns the edges it adds.
class Sweep {
public:
    Sweep(const std::vector<Point3>& p, const Graph& g, detail::CountingPredicates& pred)
        : p_(p), g_(g), pred_(pred), status_(Cmp{this}) {}

    std::vector<Edge> run() {
        std::vector<VertexIndex> order(p_.size());
        for (VertexIndex i = 0; i < p_.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(),
                  [&](VertexIndex a, VertexIndex b) { return above(p_, a, b); });
        std::vector<Edge> added;
        for (std::size_t k = 0; k < order.size(); ++k) {
            const VertexIndex v = order[k];
            std::vector<VertexIndex> up;
            std::vector<VertexIndex> down;
            for (const VertexIndex u : g_.adj[v]) (above(p_, u, v) ? up : down).push_back(u);
            for (const VertexIndex u : up) {
                const auto it = where_.find(key(u, v));
                helper_.erase(it->second.id());
                status_.erase(it->second.it);
                where_.erase(it);
            }
            // The edge left of v (its gap's left side), or none.
            auto right = status_.lower_bound(Query{v});
            const std::uint64_t left_id =
                right == status_.begin() ? kOutside : std::prev(right)->id();
            if (up.empty() && k > 0) {
                const auto h = helper_.find(left_id);
                if (h == helper_.end()) throw std::logic_error("monotone: a vertex in no gap");
                added.push_back(undirected(v, h->second));
            }
            helper_[left_id] = v;
            std::sort(down.begin(), down.end(), [&](VertexIndex a, VertexIndex b) {
                return pred_.orient(p_[v], p_[a], p_[b]) < 0;  // left to right below v
            });
            for (const VertexIndex u : down) {
                const ActiveEdge e{v, u};
                const auto it = status_.insert(right, e);
                where_[key(v, u)] = Slot{it};
                helper_[e.id()] = v;
            }
        }
        return added;
    }

private:
    static constexpr std::uint64_t kOutside = ~std::uint64_t{0};
    static std::uint64_t key(VertexIndex top, VertexIndex bottom) {
        return (std::uint64_t{top} << 32) | bottom;
    }

    struct ActiveEdge {
        VertexIndex top, bottom;
        [[nodiscard]] std::uint64_t id() const { return key(top, bottom); }
    };
    struct Query {
        VertexIndex v;
    };
    /// Left-to-right order of non-crossing edges that all cross the sweep line.
    struct Cmp {
        using is_transparent = void;
        const Sweep* s;
        /// p strictly left (west along the sweep line) of e: left of e directed bottom to top.
        [[nodiscard]] int side(const ActiveEdge& e, VertexIndex q) const {
            return s->pred_.orient(s->p_[e.bottom], s->p_[e.top], s->p_[q]);
        }
        bool operator()(const ActiveEdge& a, const ActiveEdge& b) const {
            if (a.top == b.top && a.bottom == b.bottom) return false;
            const int st = side(b, a.top);
            const int sb = side(b, a.bottom);
            if (st >= 0 && sb >= 0 && (st | sb) != 0) return true;
            if (st <= 0 && sb <= 0 && (st | sb) != 0) return false;
            // a straddles b's line, so b lies on one side of a's line.
            const int tt = side(a, b.top);
            const int tb = side(a, b.bottom);
            return !(tt >= 0 && tb >= 0);
        }
        bool operator()(const ActiveEdge& e, const Query& q) const { return side(e, q.v) < 0; }
        bool operator()(const Query& q, const ActiveEdge& e) const { return side(e, q.v) > 0; }
    };
    using Status = std::set<ActiveEdge, Cmp>;
    struct Slot {
        Status::iterator it;
        [[nodiscard]] std::uint64_t id() const { return it->id(); }
    };

    const std::vector<Point3>& p_;
    const Graph& g_;
    detail::CountingPredicates& pred_;
    Status status_;
    std::unordered_map<std::uint64_t, Slot> where_;
    std::unordered_map<std::uint64_t, VertexIndex> helper_;
};

/// Balances the chain-method edge weights (§3.2.1, R25) on the regularised graph; returns the
/// number of monotone chains (W_OUT of the lowest vertex), or throws if a condition fails.
std::uint64_t balance_chains(const Graph& g, detail::CountingPredicates& pred) {
    const auto& p = g.points;
    std::vector<VertexIndex> order(p.size());
    for (VertexIndex i = 0; i < p.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](VertexIndex a, VertexIndex b) { return above(p, b, a); });
    std::unordered_map<std::uint64_t, std::uint64_t> w;  // edge (lower, upper) -> weight
    auto wkey = [](VertexIndex lo, VertexIndex hi) { return (std::uint64_t{lo} << 32) | hi; };
    std::vector<std::vector<VertexIndex>> in(p.size()), out(p.size());  // lower / upper ends
    for (const auto& [a, b] : g.edges) {
        const VertexIndex lo = above(p, a, b) ? b : a;
        const VertexIndex hi = lo == a ? b : a;
        w[wkey(lo, hi)] = 1;
        out[lo].push_back(hi);
        in[hi].push_back(lo);
    }
    // Leftmost edge leaving v (upward) / entering v (from below): the smallest angle turn.
    auto leftmost = [&](VertexIndex v, const std::vector<VertexIndex>& ends, bool upward) {
        VertexIndex best = ends.front();
        for (const VertexIndex u : ends) {
            // Upward edges: leftmost = most counter-clockwise seen from v; downward: most
            // clockwise.
            const int o = pred.orient(p[v], p[best], p[u]);
            if (upward ? o > 0 : o < 0) best = u;
        }
        return best;
    };
    for (std::size_t k = 1; k + 1 < order.size(); ++k) {  // bottom-up
        const VertexIndex v = order[k];
        std::uint64_t win = 0;
        for (const VertexIndex u : in[v]) win += w[wkey(u, v)];
        if (win > out[v].size()) w[wkey(v, leftmost(v, out[v], true))] = win - out[v].size() + 1;
    }
    for (std::size_t k = order.size() - 2; k >= 1; --k) {  // top-down
        const VertexIndex v = order[k];
        std::uint64_t wout = 0;
        std::uint64_t win = 0;
        for (const VertexIndex u : out[v]) wout += w[wkey(v, u)];
        for (const VertexIndex u : in[v]) win += w[wkey(u, v)];
        if (wout > win) w[wkey(leftmost(v, in[v], false), v)] += wout - win;
    }
    for (std::size_t k = 1; k + 1 < order.size(); ++k) {
        const VertexIndex v = order[k];
        std::uint64_t wout = 0;
        std::uint64_t win = 0;
        for (const VertexIndex u : out[v]) wout += w[wkey(v, u)];
        for (const VertexIndex u : in[v]) win += w[wkey(u, v)];
        if (wout != win || in[v].empty() || out[v].empty()) {
            throw std::logic_error("monotone: chain weights do not balance");
        }
    }
    std::uint64_t chains = 0;
    for (const VertexIndex u : out[order.front()]) chains += w[wkey(order.front(), u)];
    return chains;
}

struct FaceStats {
    std::uint64_t polygons = 0;
    std::uint64_t diagonals = 0;
};

/// Triangulates one y-monotone face (counter-clockwise cycle) by the stack method; appends the
/// diagonals. @throws std::logic_error if the face is not y-monotone.
void triangulate_monotone(const std::vector<Point3>& p,
                          const std::vector<VertexIndex>& face,
                          std::vector<Edge>& diagonals,
                          detail::CountingPredicates& pred) {
    const std::size_t k = face.size();
    std::size_t top = 0;
    std::size_t bottom = 0;
    for (std::size_t i = 1; i < k; ++i) {
        if (above(p, face[i], face[top])) top = i;
        if (above(p, face[bottom], face[i])) bottom = i;
    }
    // Counter-clockwise from the top runs down the left chain, then up the right chain.
    enum Chain : std::uint8_t { left, right, both };
    std::vector<std::pair<VertexIndex, Chain>> sorted;
    sorted.reserve(k);
    std::vector<VertexIndex> lchain;
    std::vector<VertexIndex> rchain;
    for (std::size_t i = top; i != bottom; i = (i + 1) % k) lchain.push_back(face[i]);
    for (std::size_t i = bottom; i != top; i = (i + 1) % k) rchain.push_back(face[i]);
    // R23: each chain strictly monotone in the order.
    for (std::size_t i = 1; i < lchain.size(); ++i) {
        if (!above(p, lchain[i - 1], lchain[i]))
            throw std::logic_error("monotone: face not y-monotone");
    }
    for (std::size_t i = 1; i < rchain.size(); ++i) {
        if (!above(p, rchain[i], rchain[i - 1]))
            throw std::logic_error("monotone: face not y-monotone");
    }
    // Merge (top first; the bottom last).
    std::size_t a = 1;
    std::size_t b = rchain.size();  // rchain[0] is the bottom; walk it backwards from the top
    sorted.emplace_back(face[top], both);
    while (a < lchain.size() || b > 1) {
        if (b <= 1 || (a < lchain.size() && above(p, lchain[a], rchain[b - 1]))) {
            sorted.emplace_back(lchain[a++], left);
        } else {
            sorted.emplace_back(rchain[--b], right);
        }
    }
    sorted.emplace_back(face[bottom], both);
    if (k == 3) return;
    std::vector<std::pair<VertexIndex, Chain>> stack{sorted[0], sorted[1]};
    for (std::size_t j = 2; j + 1 < sorted.size(); ++j) {
        const auto u = sorted[j];
        if (u.second != stack.back().second) {
            for (std::size_t s = stack.size() - 1; s >= 1; --s) {
                diagonals.push_back(undirected(u.first, stack[s].first));
            }
            const auto prev = stack.back();
            stack.clear();
            stack.push_back(prev);
            stack.push_back(u);
        } else {
            auto last = stack.back();
            stack.pop_back();
            while (!stack.empty()) {
                const int o = pred.orient(p[stack.back().first], p[last.first], p[u.first]);
                const bool convex = u.second == left ? o > 0 : o < 0;
                if (!convex) break;
                diagonals.push_back(undirected(u.first, stack.back().first));
                last = stack.back();
                stack.pop_back();
            }
            stack.push_back(last);
            stack.push_back(u);
        }
    }
    for (std::size_t s = 1; s + 1 < stack.size(); ++s) {
        diagonals.push_back(undirected(sorted.back().first, stack[s].first));
    }
}

}  // namespace

MethodResult run_monotone(const MethodInput& input,
                          const MethodOptions& options,
                          const Progress& progress) {
    detail::ParamReader params("monotone", options);
    const std::string domain = params.choice("domain", {"hull", "rectangle"}, "hull");
    params.finish();
    detail::CountingPredicates pred;
    detail::PreparedInput prepared = detail::prepare_input(input, "monotone", pred);
    if (detail::all_collinear(prepared.points, pred)) {
        throw InputError("method monotone: fewer than 3 distinct points or all points collinear");
    }
    Graph g;
    g.points = prepared.points;
    const auto n = static_cast<VertexIndex>(g.points.size());
    std::vector<Edge> boundary;
    if (domain == "hull") {
        const auto hull = detail::hull_boundary(g.points, pred);
        for (std::size_t i = 0; i < hull.size(); ++i) {
            boundary.push_back(undirected(hull[i], hull[(i + 1) % hull.size()]));
        }
    } else {
        Box2 box;
        for (const Point3& q : g.points) box.add(q);
        const Point2 corners[4] = {
            {box.xmin, box.ymin}, {box.xmax, box.ymin}, {box.xmax, box.ymax}, {box.xmin, box.ymax}};
        std::vector<VertexIndex> ids;
        for (const Point2& c : corners) {
            VertexIndex id = no_vertex;
            VertexIndex nearest = 0;
            for (VertexIndex i = 0; i < n; ++i) {
                if (g.points[i].x == c.x && g.points[i].y == c.y) id = i;
                if (std::hypot(g.points[i].x - c.x, g.points[i].y - c.y) <
                    std::hypot(g.points[nearest].x - c.x, g.points[nearest].y - c.y)) {
                    nearest = i;
                }
            }
            if (id == no_vertex) {
                id = static_cast<VertexIndex>(g.points.size());
                g.points.push_back({c.x, c.y, g.points[nearest].z});
            }
            ids.push_back(id);
        }
        // The sides, split at the points on them.
        for (int s = 0; s < 4; ++s) {
            const VertexIndex a = ids[s];
            const VertexIndex b = ids[(s + 1) % 4];
            std::vector<VertexIndex> on{a, b};
            for (VertexIndex i = 0; i < n; ++i) {
                if (detail::strictly_inside_segment(pred, g.points[a], g.points[b], g.points[i]))
                    on.push_back(i);
            }
            std::sort(on.begin(), on.end(), [&](VertexIndex u, VertexIndex v) {
                return std::hypot(g.points[u].x - g.points[a].x, g.points[u].y - g.points[a].y) <
                       std::hypot(g.points[v].x - g.points[a].x, g.points[v].y - g.points[a].y);
            });
            for (std::size_t i = 1; i < on.size(); ++i)
                boundary.push_back(undirected(on[i - 1], on[i]));
        }
    }
    g.adj.resize(g.points.size());
    for (const Edge& e : boundary) g.add(e.first, e.second);
    for (const Edge& e : prepared.segments) g.add(e.first, e.second);
    const std::size_t pslg_edges = g.edges.size();
    progress.report(0.1, "monotone");

    // Regularisation: pass 1 top-down, pass 2 on the turned points (bottom-up).
    const std::vector<Edge> pass1 = Sweep(g.points, g, pred).run();
    for (const Edge& e : pass1) g.add(e.first, e.second);
    std::vector<Point3> turned = g.points;
    for (Point3& q : turned) q = {-q.x, -q.y, q.z};
    const std::vector<Edge> pass2 = Sweep(turned, g, pred).run();
    for (const Edge& e : pass2) g.add(e.first, e.second);
    const std::uint64_t chains = balance_chains(g, pred);
    progress.report(0.5, "monotone");

    // Faces of the regular graph: trace them through the angular order at each vertex.
    std::vector<Edge> all(g.edges.begin(), g.edges.end());
    std::vector<std::vector<VertexIndex>> around(g.points.size());
    for (VertexIndex v = 0; v < g.points.size(); ++v) {
        around[v] = g.adj[v];
        std::sort(around[v].begin(), around[v].end(), [&](VertexIndex a, VertexIndex b) {
            return detail::angle_before(pred, g.points[v], g.points[a], g.points[b]);
        });
    }
    auto position = [&](VertexIndex v, VertexIndex u) {
        return static_cast<std::size_t>(std::find(around[v].begin(), around[v].end(), u) -
                                        around[v].begin());
    };
    std::set<std::pair<VertexIndex, VertexIndex>> seen;
    std::vector<Edge> diagonals;
    FaceStats stats;
    for (VertexIndex u = 0; u < g.points.size(); ++u) {
        for (const VertexIndex v0 : around[u]) {
            if (seen.count({u, v0})) continue;
            std::vector<VertexIndex> face;
            VertexIndex a = u;
            VertexIndex b = v0;
            do {
                seen.insert({a, b});
                face.push_back(a);
                const auto& ring = around[b];
                const VertexIndex c = ring[(position(b, a) + ring.size() - 1) % ring.size()];
                a = b;
                b = c;
            } while (!(a == u && b == v0));
            // The outer face runs clockwise; bounded faces counter-clockwise.
            double area2 = 0.0;
            for (std::size_t i = 0; i < face.size(); ++i) {
                const Point3& p0 = g.points[face[i]];
                const Point3& p1 = g.points[face[(i + 1) % face.size()]];
                area2 += (p0.x - g.points[u].x) * (p1.y - g.points[u].y) -
                         (p1.x - g.points[u].x) * (p0.y - g.points[u].y);
            }
            if (area2 <= 0.0) continue;
            ++stats.polygons;
            const std::size_t before = diagonals.size();
            triangulate_monotone(g.points, face, diagonals, pred);
            if (diagonals.size() - before != face.size() - 3) {
                throw std::logic_error("monotone: a polygon got the wrong number of diagonals");
            }
            stats.diagonals += face.size() - 3;
        }
    }
    all.insert(all.end(), diagonals.begin(), diagonals.end());
    MethodResult result;
    result.tin = detail::tin_from_edges(g.points, all, prepared.segments, pred);
    progress.report(1.0, "monotone");
    pred.add_to(result.counters);
    result.counters.extra["duplicates"] = prepared.duplicates;
    result.counters.extra["pslg_edges"] = pslg_edges;
    result.counters.extra["regularisation_pass1"] = pass1.size();
    result.counters.extra["regularisation_pass2"] = pass2.size();
    result.counters.extra["monotone_polygons"] = stats.polygons;
    result.counters.extra["diagonals"] = stats.diagonals;
    result.counters.extra["chains"] = chains;
    result.counters.extra["corners_added"] = g.points.size() - n;
    result.stats_json =
        "\"domain\": \"" + domain + "\", \"monotone_polygons\": " + std::to_string(stats.polygons) +
        ", \"regularisation_edges\": " + std::to_string(pass1.size() + pass2.size());
    return result;
}

}  // namespace dtm::methods
