// SPDX-License-Identifier: MIT
// Tracing the contour chains of one level through a TIN.
//
// A vertex is "above" the level when z >= level: a vertex exactly on the level is treated as
// lying slightly above it (a symbolic perturbation of the level downwards), consistently in every
// triangle. Under that rule no vertex is ever on the level, so a triangle is crossed by the level
// on exactly zero or two of its edges, and every crossing edge is shared by at most two crossed
// triangles: the chains are simple paths through the triangle adjacency, traced by walking from
// neighbour to neighbour (no point matching, no hashing, no tolerance).
//
//              c (above)          In a counter-clockwise triangle, the crossing edge whose
//             / \                 below end comes first (a->b) is the entry, the other one
//    exit -> /   \                (c->a) the exit: walking from entry to exit keeps the higher
//           /_____\               ground on the right. The neighbour across the exit edge sees
//    a (below)  b (above)         the same edge reversed, i.e. as its entry.
//             ^ entry
//
// Output points are computed from the edge alone (below vertex to above vertex), so both
// triangles of an edge produce identical bits; when the above vertex is exactly on the level the
// point is that vertex itself. Consequences of the perturbation that the caller cleans up:
// consecutive equal points (a fan of below triangles around a vertex on the level) and a piece
// lying along a TIN edge whose two sides are both below (a ridge exactly on the level), which
// both side chains would produce: the step in the larger-numbered triangle is marked skip.
//
// References: M. van Kreveld, "Efficient methods for isoline extraction from a TIN", IJGIS 10(5),
// 1996 (tracing through triangle adjacency); the "value equal to the level counts as above"
// convention is the one raster contourers (GDAL's contour generator) use as well.
#include "algo/detail/contour_trace.hpp"

#include <algorithm>

namespace dtm::detail {
namespace {

class LevelView {
public:
    LevelView(const Tin& tin, double level, const EdgeCrossing* edge_crossing)
        : tin_(tin), level_(level), edge_crossing_(edge_crossing) {}

    [[nodiscard]] bool above(VertexIndex v) const { return tin_.vertices[v].z >= level_; }

    /// Edge e of triangle t runs from v[e+1] to v[e+2] (counter-clockwise order).
    [[nodiscard]] std::array<VertexIndex, 2> edge(TriangleIndex t, int e) const {
        const Triangle& tri = tin_.triangles[t];
        return {tri.v[static_cast<std::size_t>((e + 1) % 3)],
                tri.v[static_cast<std::size_t>((e + 2) % 3)]};
    }

    /// The edge of @p t crossed from below to above (entry, @p up) or above to below (exit).
    [[nodiscard]] int crossing_edge(TriangleIndex t, bool up) const {
        const auto& v = tin_.triangles[t].v;
        const bool is_above[3] = {above(v[0]), above(v[1]), above(v[2])};
        for (int e = 0; e < 3; ++e) {
            if (is_above[(e + 1) % 3] != up && is_above[(e + 2) % 3] == up) {
                return e;
            }
        }
        return -1;
    }

    /// The crossing point on the edge (a, b), edge e of triangle t, and the edge as (below,
    /// above).
    [[nodiscard]] Point3 point(std::array<VertexIndex, 2>& ab, TriangleIndex tri, int e) const {
        if (above(ab[0])) {
            std::swap(ab[0], ab[1]);
        }
        const Point3& p = tin_.vertices[ab[0]];
        const Point3& q = tin_.vertices[ab[1]];
        if (q.z == level_) {
            return {q.x, q.y, level_};
        }
        if (edge_crossing_ != nullptr) {
            return edge_crossing_->point(tri, e, ab[0], ab[1], level_);
        }
        const double t = (level_ - p.z) / (q.z - p.z);
        return {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y), level_};
    }

    /// True for the second copy of a piece along a TIN edge whose both sides are below.
    [[nodiscard]] bool duplicate_step(TriangleIndex t) const {
        const Triangle& tri = tin_.triangles[t];
        int below = -1;
        for (int i = 0; i < 3; ++i) {
            const double z = tin_.vertices[tri.v[static_cast<std::size_t>(i)]].z;
            if (z < level_) {
                if (below >= 0) {
                    return false;
                }
                below = i;
            } else if (z != level_) {
                return false;
            }
        }
        const TriangleIndex n = tri.n[static_cast<std::size_t>(below)];
        if (n == no_triangle || n > t) {
            return false;
        }
        const Triangle& other = tin_.triangles[n];
        for (std::size_t k = 0; k < 3; ++k) {
            if (other.n[k] == t) {
                return tin_.vertices[other.v[k]].z < level_;
            }
        }
        return false;
    }

    [[nodiscard]] TriangleIndex neighbour(TriangleIndex t, int e) const {
        return tin_.triangles[t].n[static_cast<std::size_t>(e)];
    }

private:
    const Tin& tin_;
    double level_;
    const EdgeCrossing* edge_crossing_;
};

void push_point(const LevelView& view, RawChain& chain, TriangleIndex t, int e) {
    std::array<VertexIndex, 2> ab = view.edge(t, e);
    chain.points.push_back(view.point(ab, t, e));
    chain.edges.push_back(ab);
}

void push_step(const LevelView& view, RawChain& chain, TriangleIndex t) {
    chain.triangles.push_back(t);
    chain.skip.push_back(view.duplicate_step(t) ? 1 : 0);
}

/// Walks forwards (entry to exit) from @p start; returns true when it comes back to @p start.
bool walk_forward(const LevelView& view,
                  TriangleIndex start,
                  RawChain& chain,
                  std::vector<std::uint8_t>& visited) {
    push_point(view, chain, start, view.crossing_edge(start, true));
    for (TriangleIndex cur = start;;) {
        visited[cur] = 1;
        const int out = view.crossing_edge(cur, false);
        push_step(view, chain, cur);
        push_point(view, chain, cur, out);
        cur = view.neighbour(cur, out);
        if (cur == no_triangle) {
            return false;
        }
        if (cur == start) {
            return true;
        }
    }
}

/// One chain through @p start: forwards to the end (or around a ring), then, for an open chain,
/// backwards from @p start to the border, prepended. Each triangle is visited once.
RawChain trace_chain(const LevelView& view,
                     TriangleIndex start,
                     std::vector<std::uint8_t>& visited) {
    RawChain chain;
    chain.closed = walk_forward(view, start, chain, visited);
    if (chain.closed) {
        return chain;
    }
    RawChain back;  // points and steps before start, in reverse order
    for (TriangleIndex cur = view.neighbour(start, view.crossing_edge(start, true));
         cur != no_triangle;) {
        visited[cur] = 1;
        const int in = view.crossing_edge(cur, true);
        push_step(view, back, cur);
        push_point(view, back, cur, in);
        cur = view.neighbour(cur, in);
    }
    if (back.triangles.empty()) {
        return chain;
    }
    const auto prepend = [](auto& to, auto& from) {
        std::reverse(from.begin(), from.end());
        from.insert(from.end(), to.begin(), to.end());
        to = std::move(from);
    };
    prepend(chain.points, back.points);
    prepend(chain.edges, back.edges);
    prepend(chain.triangles, back.triangles);
    prepend(chain.skip, back.skip);
    return chain;
}

}  // namespace

void trace_level(const Tin& tin,
                 double level,
                 std::span<const TriangleIndex> crossing,
                 std::vector<std::uint8_t>& visited,
                 std::vector<RawChain>& chains,
                 const EdgeCrossing* edge_crossing) {
    const LevelView view(tin, level, edge_crossing);
    for (const TriangleIndex t : crossing) {
        if (visited[t] == 0) {
            chains.push_back(trace_chain(view, t, visited));
        }
    }
    for (const TriangleIndex t : crossing) {
        visited[t] = 0;
    }
}

}  // namespace dtm::detail
