// SPDX-License-Identifier: MIT
// Heights of a TIN at arbitrary points.
//
// Location. A visibility walk: from the current triangle, cross an edge that has the query point
// strictly on its outer side (exact orient2d), until no edge does; the triangle then contains
// the point, on its interior, an edge or a vertex. The edge entered through is never tested
// again, and the first edge tried is chosen pseudo-randomly from the triangle and the step, so
// the walk terminates in constrained triangulations too, where a walk with a fixed edge order
// can cycle (Devillers, Pion and Teillaud, "Walking in a triangulation", 2002). The walk starts
// from the caller's Cursor (the previous answer: queries along a line take a step or two) or
// from a grid of start triangles over the vertex bounding box (about four triangles per cell).
// Leaving the TIN across a border edge proves the point is outside only when the TIN is convex
// (one border loop turning left throughout, as a triangulation without a domain is); otherwise
// a grid of the triangles by bounding box, built on first need, answers exactly.
//
// Heights. In a triangle, barycentric interpolation of its vertices in their stored order; on an
// edge, linear interpolation along it from the lower-numbered vertex; on a vertex, its z. Either
// triangle of an edge therefore gives the same value.
//
// Nearest vertex. A k-d tree of the vertices used by triangles (median splits on alternating
// axes), searched exactly on squared distances, ties going to the lower vertex index.
#include "dtm/algo/surface_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <vector>

#include "dtm/geom/predicates.hpp"

namespace dtm {

/// A uniform grid over a box.
struct CellGrid {
    Box2 box;
    std::size_t cols = 0;
    std::size_t rows = 0;
    double cell_w = 1.0;
    double cell_h = 1.0;

    void fit(const Box2& b, std::size_t target_cells) {
        box = b;
        const double w = std::max(b.xmax - b.xmin, std::numeric_limits<double>::min());
        const double h = std::max(b.ymax - b.ymin, std::numeric_limits<double>::min());
        const double n = static_cast<double>(std::max<std::size_t>(target_cells, 1));
        const double side = std::sqrt(w * h / n);
        cols = std::clamp<std::size_t>(static_cast<std::size_t>(w / side), 1, 1 << 13);
        rows = std::clamp<std::size_t>(static_cast<std::size_t>(h / side), 1, 1 << 13);
        cell_w = w / static_cast<double>(cols);
        cell_h = h / static_cast<double>(rows);
    }
    [[nodiscard]] std::size_t col(double x) const {
        const double c = std::floor((x - box.xmin) / cell_w);
        return c <= 0.0 ? 0 : std::min(cols - 1, static_cast<std::size_t>(c));
    }
    [[nodiscard]] std::size_t row(double y) const {
        const double r = std::floor((y - box.ymin) / cell_h);
        return r <= 0.0 ? 0 : std::min(rows - 1, static_cast<std::size_t>(r));
    }
    [[nodiscard]] bool contains(Point2 p) const {
        return p.x >= box.xmin && p.x <= box.xmax && p.y >= box.ymin && p.y <= box.ymax;
    }
};

/// Every triangle listed in each cell its bounding box meets (about one cell per triangle).
struct TriangleGrid {
    CellGrid grid;
    std::vector<std::size_t> first;  ///< per cell, into items; one more at the end
    std::vector<TriangleIndex> items;

    void build(const Tin& tin, const Box2& box);
};

struct SurfaceSampler::Indices {
    CellGrid grid;
    std::vector<TriangleIndex> start;  ///< per cell of `grid`, a triangle to walk from
    bool convex = false;               ///< the TIN covers exactly its convex hull
    std::once_flag triangles_once;
    TriangleGrid triangles;  ///< built on first need
    std::once_flag vertices_once;
    std::vector<VertexIndex> kd;  ///< k-d tree: the median of [lo, hi) at lo + (hi - lo) / 2
};

namespace {

Point2 xy(const Point3& p) { return {p.x, p.y}; }

/// Orientations of @p p against the three sides of @p t (side s: v[s+1] -> v[s+2]).
std::array<int, 3> sides_of(const Tin& tin, const Triangle& t, Point2 p) {
    std::array<int, 3> o{};
    for (unsigned s = 0; s < 3; ++s) {
        o[s] = geom::orient2d(tin.vertex(t.v[(s + 1) % 3]), tin.vertex(t.v[(s + 2) % 3]), p);
    }
    return o;
}

/// The location of @p p in triangle @p t, given that no side has it strictly outside.
TinLocation classify(TriangleIndex t, const std::array<int, 3>& o) {
    const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    for (std::uint8_t s = 0; s < 3; ++s) {
        if (zeros == 1 && o[s] == 0) return {TinLocation::Kind::edge, {t, s}};
        if (zeros == 2 && o[s] != 0) {  // on the vertex v[s]: the side starting there
            return {TinLocation::Kind::vertex, {t, static_cast<std::uint8_t>((s + 2) % 3)}};
        }
    }
    return {TinLocation::Kind::triangle, {t, 0}};
}

/// True if the border of @p tin is one loop that never turns right: the TIN is its convex hull.
bool covers_its_hull(const Tin& tin) {
    std::vector<VertexIndex> next(tin.vertices.size(), no_vertex);
    std::size_t border = 0;
    VertexIndex any = no_vertex;
    for (TriangleIndex t = 0; t < tin.triangles.size(); ++t) {
        for (std::uint8_t s = 0; s < 3; ++s) {
            if (tin.triangles[t].n[s] != no_triangle) continue;
            const HalfEdge e{t, s};
            if (next[origin(tin, e)] != no_vertex) return false;  // two loops touch
            next[origin(tin, e)] = destination(tin, e);
            any = origin(tin, e);
            ++border;
        }
    }
    if (border == 0) return false;
    std::size_t walked = 0;
    VertexIndex prev = any;
    VertexIndex v = next[any];
    do {
        const VertexIndex after = next[v];
        if (after == no_vertex) return false;
        if (geom::orient2d(tin.vertex(prev), tin.vertex(v), tin.vertex(after)) < 0) return false;
        prev = v;
        v = after;
        ++walked;
    } while (prev != any && walked <= border);
    return walked == border;
}

}  // namespace

SurfaceSampler::SurfaceSampler(const Tin& tin) : tin_(&tin), indices_(std::make_unique<Indices>()) {
    Box2 box;
    for (const Triangle& t : tin.triangles) {
        for (const VertexIndex v : t.v) box.add(tin.vertex(v));
    }
    if (tin.triangles.empty()) return;
    Indices& ix = *indices_;
    ix.grid.fit(box, tin.triangles.size() / 4);
    ix.start.assign(ix.grid.cols * ix.grid.rows, no_triangle);
    for (TriangleIndex t = 0; t < tin.triangles.size(); ++t) {
        const Point3& a = tin.vertex(tin.triangles[t].v[0]);
        TriangleIndex& slot = ix.start[ix.grid.row(a.y) * ix.grid.cols + ix.grid.col(a.x)];
        if (slot == no_triangle) slot = t;
    }
    TriangleIndex last = 0;  // empty cells walk from the previous cell's triangle
    for (TriangleIndex& slot : ix.start) {
        if (slot == no_triangle) slot = last;
        last = slot;
    }
    ix.convex = covers_its_hull(tin);
}

SurfaceSampler::SurfaceSampler(SurfaceSampler&&) noexcept = default;
SurfaceSampler& SurfaceSampler::operator=(SurfaceSampler&&) noexcept = default;
SurfaceSampler::~SurfaceSampler() = default;

TinLocation SurfaceSampler::locate(Point2 p, Cursor& cursor) const {
    const Tin& tin = *tin_;
    const Indices& ix = *indices_;
    if (tin.triangles.empty() || !ix.grid.contains(p)) return {};
    TriangleIndex t = cursor.triangle < tin.triangles.size()
                          ? cursor.triangle
                          : ix.start[ix.grid.row(p.y) * ix.grid.cols + ix.grid.col(p.x)];
    TriangleIndex came_from = no_triangle;
    bool left_the_tin = false;
    for (std::size_t step = 0; step <= tin.triangles.size() + 8; ++step) {
        const Triangle& tri = tin.triangles[t];
        const unsigned first = static_cast<unsigned>((t * 2654435761U + step) >> 7) % 3;
        int exit = -1;
        for (unsigned k = 0; k < 3 && exit < 0; ++k) {
            const unsigned s = (first + k) % 3;
            if (tri.n[s] == came_from && came_from != no_triangle) continue;
            const Point3& a = tin.vertex(tri.v[(s + 1) % 3]);
            const Point3& b = tin.vertex(tri.v[(s + 2) % 3]);
            if (geom::orient2d(a, b, p) < 0) exit = static_cast<int>(s);
        }
        if (exit < 0) {
            cursor.triangle = t;
            return classify(t, sides_of(tin, tri, p));
        }
        const TriangleIndex next = tri.n[static_cast<std::size_t>(exit)];
        if (next == no_triangle) {
            left_the_tin = true;
            break;
        }
        came_from = t;
        t = next;
    }
    if (left_the_tin && ix.convex) return {};
    // A non-convex TIN, or a walk that did not settle: the triangle grid decides.
    Indices& lazy = *indices_;
    std::call_once(lazy.triangles_once, [&] { lazy.triangles.build(tin, ix.grid.box); });
    const TriangleGrid& tg = ix.triangles;
    const std::size_t cell = tg.grid.row(p.y) * tg.grid.cols + tg.grid.col(p.x);
    for (std::size_t k = tg.first[cell]; k < tg.first[cell + 1]; ++k) {
        const TriangleIndex c = tg.items[k];
        const std::array<int, 3> o = sides_of(tin, tin.triangles[c], p);
        if (o[0] >= 0 && o[1] >= 0 && o[2] >= 0) {
            cursor.triangle = c;
            return classify(c, o);
        }
    }
    return {};
}

double SurfaceSampler::height_at(const TinLocation& where, Point2 q) const {
    const Tin& tin = *tin_;
    switch (where.kind) {
        case TinLocation::Kind::outside:
            return std::numeric_limits<double>::quiet_NaN();
        case TinLocation::Kind::vertex:
            return tin.vertex(origin(tin, where.edge)).z;
        case TinLocation::Kind::edge: {
            const VertexIndex u = origin(tin, where.edge);
            const VertexIndex w = destination(tin, where.edge);
            const Point3& a = tin.vertex(std::min(u, w));
            const Point3& b = tin.vertex(std::max(u, w));
            const double dx = b.x - a.x;
            const double dy = b.y - a.y;
            const double t = ((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy);
            return a.z + t * (b.z - a.z);
        }
        case TinLocation::Kind::triangle:
            break;
    }
    const Triangle& tri = tin.triangles[where.edge.triangle];
    const Point3& a = tin.vertex(tri.v[0]);
    const Point3& b = tin.vertex(tri.v[1]);
    const Point3& c = tin.vertex(tri.v[2]);
    const double d = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double u = ((b.x - q.x) * (c.y - q.y) - (c.x - q.x) * (b.y - q.y)) / d;
    const double v = ((c.x - q.x) * (a.y - q.y) - (a.x - q.x) * (c.y - q.y)) / d;
    return u * a.z + v * b.z + (1.0 - u - v) * c.z;
}

double SurfaceSampler::height(Point2 p, Cursor& cursor) const {
    return height_at(locate(p, cursor), p);
}

double SurfaceSampler::height_or_nearest(Point2 p, Cursor& cursor) const {
    const TinLocation where = locate(p, cursor);
    if (where.kind != TinLocation::Kind::outside) return height_at(where, p);
    const VertexIndex v = nearest_vertex(p);
    return v == no_vertex ? std::numeric_limits<double>::quiet_NaN() : tin_->vertex(v).z;
}

void TriangleGrid::build(const Tin& tin, const Box2& box) {
    CellGrid& g = grid;
    g.fit(box, tin.triangles.size());
    const auto span = [&](const Triangle& t, auto&& visit) {
        Box2 b;
        for (const VertexIndex v : t.v) b.add(tin.vertex(v));
        for (std::size_t r = g.row(b.ymin); r <= g.row(b.ymax); ++r) {
            for (std::size_t c = g.col(b.xmin); c <= g.col(b.xmax); ++c) visit(r * g.cols + c);
        }
    };
    first.assign(g.cols * g.rows + 1, 0);
    for (const Triangle& t : tin.triangles) span(t, [&](std::size_t cell) { ++first[cell + 1]; });
    for (std::size_t c = 0; c + 1 < first.size(); ++c) first[c + 1] += first[c];
    items.resize(first.back());
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (TriangleIndex t = 0; t < tin.triangles.size(); ++t) {
        span(tin.triangles[t], [&](std::size_t cell) { items[fill[cell]++] = t; });
    }
}

namespace {

void build_kd(
    std::vector<VertexIndex>& kd, std::size_t lo, std::size_t hi, int axis, const Tin& tin) {
    if (hi - lo < 2) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    std::nth_element(
        kd.begin() + static_cast<std::ptrdiff_t>(lo), kd.begin() + static_cast<std::ptrdiff_t>(mid),
        kd.begin() + static_cast<std::ptrdiff_t>(hi), [&](VertexIndex a, VertexIndex b) {
            const double ka = axis == 0 ? tin.vertex(a).x : tin.vertex(a).y;
            const double kb = axis == 0 ? tin.vertex(b).x : tin.vertex(b).y;
            return ka < kb || (ka == kb && a < b);
        });
    build_kd(kd, lo, mid, 1 - axis, tin);
    build_kd(kd, mid + 1, hi, 1 - axis, tin);
}

struct Nearest {
    const Tin& tin;
    const std::vector<VertexIndex>& kd;
    Point2 p;
    double best = std::numeric_limits<double>::infinity();
    VertexIndex best_vertex = no_vertex;

    void search(std::size_t lo, std::size_t hi, int axis) {
        if (lo >= hi) return;
        const std::size_t mid = lo + (hi - lo) / 2;
        const VertexIndex v = kd[mid];
        const Point2 q = xy(tin.vertex(v));
        const double dx = q.x - p.x;
        const double dy = q.y - p.y;
        const double d = dx * dx + dy * dy;
        if (d < best || (d == best && v < best_vertex)) {
            best = d;
            best_vertex = v;
        }
        const double along = axis == 0 ? p.x - q.x : p.y - q.y;
        const bool low_first = along < 0.0;
        if (low_first) {
            search(lo, mid, 1 - axis);
        } else {
            search(mid + 1, hi, 1 - axis);
        }
        if (along * along <= best) {
            if (low_first) {
                search(mid + 1, hi, 1 - axis);
            } else {
                search(lo, mid, 1 - axis);
            }
        }
    }
};

}  // namespace

VertexIndex SurfaceSampler::nearest_vertex(Point2 p) const {
    const Tin& tin = *tin_;
    if (tin.triangles.empty()) return no_vertex;
    Indices& ix = *indices_;
    std::call_once(ix.vertices_once, [&] {
        std::vector<bool> used(tin.vertices.size(), false);
        for (const Triangle& t : tin.triangles) {
            for (const VertexIndex v : t.v) used[v] = true;
        }
        for (VertexIndex v = 0; v < tin.vertices.size(); ++v) {
            if (used[v]) ix.kd.push_back(v);
        }
        build_kd(ix.kd, 0, ix.kd.size(), 0, tin);
    });
    Nearest search{tin, ix.kd, p};
    search.search(0, ix.kd.size(), 0);
    return search.best_vertex;
}

}  // namespace dtm
