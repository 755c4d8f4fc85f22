// SPDX-License-Identifier: MIT
// Cut/fill regions and zero lines of a difference surface (d = top - base on a TIN).
//
// Every triangle has a fill part (where d >= 0, if some corner has d > 0) and a cut part (d <= 0,
// if some corner has d < 0), convex polygons whose corners are triangle vertices and the zero
// points of edges whose ends have strictly opposite signs (t = d_u / (d_u - d_v) from the end with
// the smaller index, so both triangles of the edge compute the same point). A side of a part
// lying on a triangle edge continues into the neighbour's part of the same kind, except
//   - on the border of the surface (no neighbour), and
//   - on an edge with d = 0 at both ends, where the neighbour may lie on the other side of zero
//     (the neighbour's third corner tells);
// a side inside the triangle is the zero segment between its fill and cut parts. Parts that
// continue into each other are merged (union-find); the sides that do not are the regions'
// boundaries, directed with the region on their left, chained into rings (where a region touches
// itself at a point, the ring turns into the wedge it came along: the first side clockwise from
// the way back). Outer rings run counter-clockwise, holes clockwise; each belongs to the region of
// the parts it bounds. Zero lines are the boundary sides that are not on the surface's border,
// each taken once (from the fill side, or from the cut side where it meets unchanged ground),
// chained into polylines that split where three or more meet.
#include "dtm/algo/cut_fill.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "algo/detail/compensated_sum.hpp"
#include "dtm/algo/tin_topology.hpp"

namespace dtm {
namespace {

using Key = std::uint64_t;

Key vertex_key(VertexIndex v) { return (Key{v} << 32) | 0xFFFFFFFFULL; }
Key zero_key(VertexIndex a, VertexIndex b) { return (Key{std::min(a, b)} << 32) | std::max(a, b); }

struct Point {
    Key key;
    double x;
    double y;
    double top;  ///< height of the top surface
    double d;
    int vertex;  ///< local corner 0..2, or -1 for a zero point
    int edge;    ///< zero point: the local edge (corner edge -> edge + 1) it lies on
};

/// A boundary side of a part, region on its left.
struct Side {
    Point from;
    Point to;
    std::uint32_t part;
};

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) {
        std::iota(parent_.begin(), parent_.end(), 0U);
    }
    std::uint32_t find(std::uint32_t x) {
        while (parent_[x] != x) {
            parent_[x] = parent_[parent_[x]];
            x = parent_[x];
        }
        return x;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) {
            parent_[std::max(a, b)] = std::min(a, b);
        }
    }

private:
    std::vector<std::uint32_t> parent_;
};

class Tracer {
public:
    explicit Tracer(const DifferenceSurface& s) : s_(s), parts_(2 * s.tin.triangles.size()) {
        area_.resize(parts_size());
        volume_.resize(parts_size());
        depth_.assign(parts_size(), 0.0);
    }

    void run(const Progress& progress) {
        const std::size_t n = s_.tin.triangles.size();
        for (std::size_t t = 0; t < n; ++t) {
            if ((t & 0xFFFF) == 0) {
                progress.report(0.6 * static_cast<double>(t) / static_cast<double>(n),
                                "tracing cut and fill");
            }
            for (const double sign : {1.0, -1.0}) {
                triangle_part(static_cast<TriangleIndex>(t), sign);
            }
        }
    }

    CutFillMap finish(const Progress& progress) {
        CutFillMap map;
        progress.report(0.6, "tracing cut and fill");
        regions(map);
        progress.report(0.8, "tracing zero lines");
        map.zero_lines = chain_zero_lines();
        progress.report(1.0, "tracing zero lines");
        return map;
    }

private:
    [[nodiscard]] std::size_t parts_size() const { return 2 * s_.tin.triangles.size(); }

    Point corner(const Triangle& tri, int k) const {
        const VertexIndex v = tri.v[static_cast<std::size_t>(k)];
        const Point3& p = s_.tin.vertices[v];
        return {vertex_key(v), p.x, p.y, s_.top_z[v], p.z, k, -1};
    }

    Point zero_point(const Triangle& tri, int j) const {
        VertexIndex u = tri.v[static_cast<std::size_t>(j)];
        VertexIndex v = tri.v[static_cast<std::size_t>((j + 1) % 3)];
        if (v < u) {
            std::swap(u, v);
        }
        const Point3& a = s_.tin.vertices[u];
        const Point3& b = s_.tin.vertices[v];
        const double t = a.z / (a.z - b.z);
        return {zero_key(u, v),
                a.x + t * (b.x - a.x),
                a.y + t * (b.y - a.y),
                s_.top_z[u] + t * (s_.top_z[v] - s_.top_z[u]),
                0.0,
                -1,
                j};
    }

    static bool on_edge(const Point& p, int j) {
        return p.vertex == j || p.vertex == (j + 1) % 3 || (p.vertex < 0 && p.edge == j);
    }

    void triangle_part(TriangleIndex t, double sign) {
        const Triangle& tri = s_.tin.triangles[t];
        std::array<double, 3> d{};
        bool any = false;
        for (std::size_t k = 0; k < 3; ++k) {
            d[k] = sign * s_.tin.vertices[tri.v[k]].z;
            any = any || d[k] > 0.0;
        }
        if (!any) {
            return;
        }
        const auto part = static_cast<std::uint32_t>(2 * t + (sign < 0.0 ? 1 : 0));
        std::array<Point, 6> poly{};
        std::size_t m = 0;
        for (int j = 0; j < 3; ++j) {
            const auto jj = static_cast<std::size_t>(j);
            const std::size_t j1 = (jj + 1) % 3;
            if (d[jj] >= 0.0) {
                poly[m++] = corner(tri, j);
            }
            if ((d[jj] > 0.0 && d[j1] < 0.0) || (d[jj] < 0.0 && d[j1] > 0.0)) {
                poly[m++] = zero_point(tri, j);
            }
        }
        measure(part, poly.data(), m, sign);
        for (std::size_t i = 0; i < m; ++i) {
            const Point& p = poly[i];
            const Point& q = poly[(i + 1) % m];
            int edge = -1;
            for (int j = 0; j < 3 && edge < 0; ++j) {
                if (on_edge(p, j) && on_edge(q, j)) {
                    edge = j;
                }
            }
            if (edge < 0) {  // the zero segment inside the triangle
                sides_.push_back({p, q, part});
                if (sign > 0.0) {
                    zero_.push_back({p, q, part});
                }
                continue;
            }
            const auto je = static_cast<std::size_t>(edge);
            const TriangleIndex nb = tri.n[(je + 2) % 3];
            if (nb == no_triangle) {
                sides_.push_back({p, q, part});
                continue;
            }
            const bool zero_edge = d[je] == 0.0 && d[(je + 1) % 3] == 0.0;
            if (!zero_edge) {
                parts_.join(part, static_cast<std::uint32_t>(2 * nb + (sign < 0.0 ? 1 : 0)));
                continue;
            }
            const double other = sign * third_corner_d(nb, tri.v[je], tri.v[(je + 1) % 3]);
            if (other > 0.0) {
                parts_.join(part, static_cast<std::uint32_t>(2 * nb + (sign < 0.0 ? 1 : 0)));
                continue;
            }
            sides_.push_back({p, q, part});
            if (sign > 0.0 || other == 0.0) {
                zero_.push_back({p, q, part});
            }
        }
    }

    [[nodiscard]] double third_corner_d(TriangleIndex t, VertexIndex a, VertexIndex b) const {
        for (const VertexIndex v : s_.tin.triangles[t].v) {
            if (v != a && v != b) {
                return s_.tin.vertices[v].z;
            }
        }
        return 0.0;
    }

    void measure(std::uint32_t part, const Point* p, std::size_t m, double sign) {
        double area = 0.0;
        double integral = 0.0;
        for (std::size_t i = 1; i + 1 < m; ++i) {
            const double a = 0.5 * ((p[i].x - p[0].x) * (p[i + 1].y - p[0].y) -
                                    (p[i].y - p[0].y) * (p[i + 1].x - p[0].x));
            area += a;
            integral += a * (p[0].d + p[i].d + p[i + 1].d) / 3.0;
        }
        double depth = 0.0;
        for (std::size_t i = 0; i < m; ++i) {
            depth = std::max(depth, sign * p[i].d);
        }
        area_[part] = area;
        volume_[part] = sign * integral;
        depth_[part] = depth;
    }

    /// Index of the sides leaving each key, sorted by key.
    static std::vector<std::pair<Key, std::uint32_t>> leaving(const std::vector<Side>& sides) {
        std::vector<std::pair<Key, std::uint32_t>> out(sides.size());
        for (std::size_t i = 0; i < sides.size(); ++i) {
            out[i] = {sides[i].from.key, static_cast<std::uint32_t>(i)};
        }
        std::sort(out.begin(), out.end());
        return out;
    }

    std::vector<std::vector<std::uint32_t>> chain_rings() {
        const auto index = leaving(sides_);
        std::vector<bool> used(sides_.size(), false);
        std::vector<std::vector<std::uint32_t>> rings;
        for (const auto& [key, first] : index) {
            if (used[first]) {
                continue;
            }
            std::vector<std::uint32_t> ring;
            std::uint32_t e = first;
            while (!used[e]) {
                used[e] = true;
                ring.push_back(e);
                const Side& in = sides_[e];
                auto lo = std::lower_bound(index.begin(), index.end(),
                                           std::pair<Key, std::uint32_t>{in.to.key, 0});
                std::uint32_t best = e;
                double best_turn = 10.0;
                const double back = std::atan2(in.from.y - in.to.y, in.from.x - in.to.x);
                for (auto it = lo; it != index.end() && it->first == in.to.key; ++it) {
                    if (used[it->second] && it->second != first) {
                        continue;
                    }
                    const Side& out = sides_[it->second];
                    double turn = back - std::atan2(out.to.y - out.from.y, out.to.x - out.from.x);
                    while (turn <= 0.0) {
                        turn += 2.0 * 3.14159265358979323846;
                    }
                    if (turn < best_turn) {
                        best_turn = turn;
                        best = it->second;
                    }
                }
                if (best == e) {
                    break;  // open chain (should not happen on a valid surface)
                }
                e = best;
            }
            rings.push_back(std::move(ring));
        }
        return rings;
    }

    void regions(CutFillMap& map) {
        struct Component {
            std::vector<std::vector<Point2>> outers;
            std::vector<std::vector<Point2>> holes;
        };
        std::unordered_map<std::uint32_t, Component> components;
        for (const std::vector<std::uint32_t>& ring : chain_rings()) {
            std::vector<Point2> points;
            points.reserve(ring.size() + 1);
            for (const std::uint32_t e : ring) {
                points.push_back({sides_[e].from.x, sides_[e].from.y});
            }
            points.push_back(points.front());
            if (points.size() < 4) {
                continue;
            }
            Component& c = components[parts_.find(sides_[ring.front()].part)];
            (ring_area(points) > 0.0 ? c.outers : c.holes).push_back(std::move(points));
        }
        // Area, volume and depth per component.
        std::unordered_map<std::uint32_t, std::array<detail::CompensatedSum, 2>> sums;
        std::unordered_map<std::uint32_t, double> depth;
        for (std::uint32_t p = 0; p < parts_size(); ++p) {
            if (area_[p] == 0.0 && volume_[p] == 0.0) {
                continue;
            }
            const std::uint32_t root = parts_.find(p);
            sums[root][0].add(area_[p]);
            sums[root][1].add(volume_[p]);
            depth[root] = std::max(depth[root], depth_[p]);
        }
        std::vector<std::uint32_t> roots;
        for (const auto& [root, c] : components) {
            roots.push_back(root);
        }
        std::sort(roots.begin(), roots.end());
        for (const std::uint32_t root : roots) {
            Component& c = components[root];
            if (c.outers.empty()) {
                continue;
            }
            std::sort(c.outers.begin(), c.outers.end(),
                      [](const auto& a, const auto& b) { return ring_area(a) > ring_area(b); });
            for (std::size_t i = 0; i < c.outers.size(); ++i) {
                CutFillRegion region;
                region.fill = (root % 2) == 0;
                region.rings.push_back(std::move(c.outers[i]));
                if (i == 0) {
                    for (auto& h : c.holes) {
                        region.rings.push_back(std::move(h));
                    }
                    region.area = sums[root][0].value();
                    region.volume = sums[root][1].value();
                    region.max_depth = depth[root];
                } else {
                    region.area = ring_area(region.rings[0]);
                }
                map.regions.push_back(std::move(region));
            }
        }
    }

    std::vector<ZeroLine> chain_zero_lines() const {
        // Undirected adjacency of zero sides by key.
        std::vector<std::pair<Key, std::uint32_t>> ends;
        ends.reserve(2 * zero_.size());
        for (std::size_t i = 0; i < zero_.size(); ++i) {
            ends.push_back({zero_[i].from.key, static_cast<std::uint32_t>(i)});
            ends.push_back({zero_[i].to.key, static_cast<std::uint32_t>(i)});
        }
        std::sort(ends.begin(), ends.end());
        const auto range = [&](Key k) {
            const auto lo =
                std::lower_bound(ends.begin(), ends.end(), std::pair<Key, std::uint32_t>{k, 0});
            auto hi = lo;
            while (hi != ends.end() && hi->first == k) {
                ++hi;
            }
            return std::pair{lo, hi};
        };
        const auto degree = [&](Key k) {
            const auto [lo, hi] = range(k);
            return hi - lo;
        };
        std::vector<bool> used(zero_.size(), false);
        std::vector<ZeroLine> lines;
        const auto walk = [&](std::uint32_t first, Key start) {
            ZeroLine line;
            Key at = start;
            std::uint32_t e = first;
            const auto point = [](const Point& p) { return Point3{p.x, p.y, p.top}; };
            line.points.push_back(point(zero_[e].from.key == at ? zero_[e].from : zero_[e].to));
            while (true) {
                used[e] = true;
                const Point& far = zero_[e].from.key == at ? zero_[e].to : zero_[e].from;
                line.points.push_back(point(far));
                at = far.key;
                if (at == start) {
                    line.closed = true;
                    break;
                }
                if (degree(at) != 2) {
                    break;
                }
                const auto [lo, hi] = range(at);
                std::uint32_t next = e;
                for (auto it = lo; it != hi; ++it) {
                    if (!used[it->second]) {
                        next = it->second;
                    }
                }
                if (next == e) {
                    break;
                }
                e = next;
            }
            lines.push_back(std::move(line));
        };
        for (const auto& [key, side] : ends) {
            if (!used[side] && degree(key) != 2) {
                walk(side, key);
            }
        }
        for (std::size_t i = 0; i < zero_.size(); ++i) {
            if (!used[i]) {
                walk(static_cast<std::uint32_t>(i), zero_[i].from.key);
            }
        }
        return lines;
    }

    const DifferenceSurface& s_;
    UnionFind parts_;
    std::vector<double> area_;
    std::vector<double> volume_;
    std::vector<double> depth_;
    std::vector<Side> sides_;
    std::vector<Side> zero_;
};

}  // namespace

CutFillMap cut_fill_map(const DifferenceSurface& surface, const Progress& progress) {
    Tracer tracer(surface);
    tracer.run(progress);
    return tracer.finish(progress);
}

}  // namespace dtm
