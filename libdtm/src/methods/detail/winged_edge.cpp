// SPDX-License-Identifier: MIT
// Incremental Delaunay insertion on the thesis' winged-edge structure (winged_edge.hpp).
//
// Insertion (000 §3.8, steps 2 (i)-(iv)): the walk finds the triangle containing p; it is
// split in three (or, with p on an edge, the two triangles of that edge in four); each edge
// opposite p is tested (is the far vertex strictly inside the circle through p and the edge?)
// and swapped when it fails, the two edges beyond a swapped one tested next: the informal
// "retriangulate the region whose circle contains the point" of the thesis is Lawson's
// recursive flip (R40). The walk (procedure "cesta"): from the triangle of the start edge,
// test p against the triangle's edges in counter-clockwise order after the one it came in by,
// cross the first edge p lies strictly right of; stop in the triangle where there is none.
// This is the visibility walk, which always ends in a Delaunay triangulation (Edelsbrunner
// 1990); the thesis' stopping rule (an edge visited twice) is that triangle's sides.
#include "methods/detail/winged_edge.hpp"

#include <algorithm>

#include "methods/detail/method_support.hpp"

namespace dtm::methods::detail {

WingedEdgeDelaunay::WingedEdgeDelaunay(const std::vector<Point3>& points,
                                       CountingPredicates& predicates)
    : pts_(points), st_(points, predicates, SuperTriangle::Mode::symbolic) {
    const std::size_t n = points.size();
    edges_.reserve(3 * n + 3);  // a triangulation of n + 3 points with 3 on the hull
    tris_.reserve(2 * n + 1);
    pending_.reserve(64);
    vertex_edge_.assign(n + 3, no_edge);
    const VertexIndex s0 = st_.corner(0), s1 = st_.corner(1), s2 = st_.corner(2);
    const EdgeIndex e0 = new_edge(s0, s1);
    const EdgeIndex e1 = new_edge(s1, s2);
    const EdgeIndex e2 = new_edge(s2, s0);
    const TriangleIndex t = new_triangle();
    tris_[t].e = {e0, e1, e2};
    for (const EdgeIndex e : {e0, e1, e2}) edges_[e].t1 = t;
    wing_triangle(t);
    // Outside T_pom the wings are the neighbouring sides of T_pom; they never change.
    edges_[e0].e11 = e2;
    edges_[e0].e21 = e1;
    edges_[e1].e11 = e0;
    edges_[e1].e21 = e2;
    edges_[e2].e11 = e1;
    edges_[e2].e21 = e0;
    last_ = e0;
}

EdgeIndex WingedEdgeDelaunay::new_edge(VertexIndex a, VertexIndex b) {
    WingedEdgeRecord r;
    r.v1 = a;
    r.v2 = b;
    edges_.push_back(r);
    const auto e = static_cast<EdgeIndex>(edges_.size() - 1);
    vertex_edge_[a] = e;
    vertex_edge_[b] = e;
    return e;
}

TriangleIndex WingedEdgeDelaunay::new_triangle() {
    tris_.emplace_back();
    return static_cast<TriangleIndex>(tris_.size() - 1);
}

void WingedEdgeDelaunay::replace_side(EdgeIndex e, TriangleIndex from, TriangleIndex to) noexcept {
    WingedEdgeRecord& r = edges_[e];
    if (r.t1 == from) {
        r.t1 = to;
    } else {
        r.t2 = to;
    }
}

void WingedEdgeDelaunay::set_wing(EdgeIndex w,
                                  TriangleIndex t,
                                  EdgeIndex next,
                                  EdgeIndex prev) noexcept {
    WingedEdgeRecord& r = edges_[w];
    if (r.t1 == t) {
        r.e12 = prev;  // ends at v1
        r.e22 = next;  // starts at v2
    } else {
        r.e11 = next;  // starts at v1
        r.e21 = prev;  // ends at v2
    }
}

void WingedEdgeDelaunay::wing_triangle(TriangleIndex t) noexcept {
    const auto [a, b, c] = tris_[t].e;
    set_wing(a, t, b, c);
    set_wing(b, t, c, a);
    set_wing(c, t, a, b);
}

std::array<VertexIndex, 3> WingedEdgeDelaunay::corners(TriangleIndex t) const noexcept {
    const auto& e = tris_[t].e;
    return {origin_in(e[0], t), origin_in(e[1], t), origin_in(e[2], t)};
}

TriangleIndex WingedEdgeDelaunay::locate(VertexIndex p, EdgeIndex start, std::uint64_t& steps) {
    TriangleIndex t = edges_[start].t1;
    EdgeIndex entry = start;
    for (;;) {
        ++steps;
        const auto& te = tris_[t].e;
        const int k0 = position(t, entry);
        on_side_ = -1;
        bool moved = false;
        for (int s = 1; s <= 3; ++s) {
            const int k = k0 + s < 3 ? k0 + s : k0 + s - 3;
            const EdgeIndex e = te[static_cast<std::size_t>(k)];
            const WingedEdgeRecord& r = edges_[e];
            const bool forward = r.t1 == t;
            const VertexIndex a = forward ? r.v1 : r.v2;
            const VertexIndex b = forward ? r.v2 : r.v1;
            const int o = st_.orient(a, b, p);
            if (o < 0) {
                t = forward ? r.t2 : r.t1;
                entry = e;
                moved = true;
                break;
            }
            if (o == 0) on_side_ = k;
        }
        if (!moved) {
            last_ = entry;
            return t;
        }
    }
}

std::uint64_t WingedEdgeDelaunay::insert(VertexIndex p, EdgeIndex start) {
    std::uint64_t steps = 0;
    const TriangleIndex t = locate(p, start == no_edge ? last_ : start, steps);
    // The walk tested p against all three sides of t (none strictly right of p): a side with
    // p on its line holds p (p is no corner: the points are distinct).
    if (on_side_ >= 0) {
        split_edge(t, on_side_, p);
    } else {
        split_triangle(t, p);
    }
    legalize(p);
    return steps;
}

void WingedEdgeDelaunay::split_triangle(TriangleIndex t, VertexIndex p) {
    const auto [e0, e1, e2] = tris_[t].e;
    const auto [a, b, c] = corners(t);
    const EdgeIndex pa = new_edge(p, a);
    const EdgeIndex pb = new_edge(p, b);
    const EdgeIndex pc = new_edge(p, c);
    const TriangleIndex t1 = new_triangle();
    const TriangleIndex t2 = new_triangle();
    tris_[t].e = {e0, pb, pa};   // (a, b, p)
    tris_[t1].e = {e1, pc, pb};  // (b, c, p)
    tris_[t2].e = {e2, pa, pc};  // (c, a, p)
    edges_[pa].t1 = t;
    edges_[pa].t2 = t2;
    edges_[pb].t1 = t1;
    edges_[pb].t2 = t;
    edges_[pc].t1 = t2;
    edges_[pc].t2 = t1;
    replace_side(e1, t, t1);
    replace_side(e2, t, t2);
    for (const TriangleIndex u : {t, t1, t2}) wing_triangle(u);
    pending_.assign({e0, e1, e2});
}

void WingedEdgeDelaunay::split_edge(TriangleIndex t, int k, VertexIndex p) {
    const EdgeIndex e = tris_[t].e[static_cast<std::size_t>(k)];
    const TriangleIndex l = edges_[e].t1;
    const TriangleIndex r = edges_[e].t2;
    const int kl = position(l, e);
    const int kr = position(r, e);
    const EdgeIndex l1 = tris_[l].e[static_cast<std::size_t>((kl + 1) % 3)];  // v2 -> x
    const EdgeIndex l2 = tris_[l].e[static_cast<std::size_t>((kl + 2) % 3)];  // x -> v1
    const EdgeIndex r1 = tris_[r].e[static_cast<std::size_t>((kr + 1) % 3)];  // v1 -> y
    const EdgeIndex r2 = tris_[r].e[static_cast<std::size_t>((kr + 2) % 3)];  // y -> v2
    const VertexIndex v2 = edges_[e].v2;
    const VertexIndex x = origin_in(l2, l);
    const VertexIndex y = origin_in(r2, r);
    const EdgeIndex f = new_edge(p, v2);
    const EdgeIndex g = new_edge(p, x);
    const EdgeIndex h = new_edge(p, y);
    edges_[e].v2 = p;
    const TriangleIndex lb = new_triangle();
    const TriangleIndex rb = new_triangle();
    tris_[l].e = {e, g, l2};   // (v1, p, x)
    tris_[lb].e = {f, l1, g};  // (p, v2, x)
    tris_[r].e = {e, r1, h};   // (p, v1, y)
    tris_[rb].e = {f, h, r2};  // (v2, p, y)
    edges_[f].t1 = lb;
    edges_[f].t2 = rb;
    edges_[g].t1 = l;
    edges_[g].t2 = lb;
    edges_[h].t1 = rb;
    edges_[h].t2 = r;
    replace_side(l1, l, lb);
    replace_side(r2, r, rb);
    vertex_edge_[v2] = f;
    vertex_edge_[p] = f;
    for (const TriangleIndex u : {l, lb, r, rb}) wing_triangle(u);
    pending_.assign({l1, l2, r1, r2});
}

void WingedEdgeDelaunay::flip(EdgeIndex e) {
    WingedEdgeRecord& r = edges_[e];
    const TriangleIndex l = r.t1;
    const TriangleIndex rt = r.t2;
    // The quadrilateral's sides are e's wings.
    const EdgeIndex l1 = r.e22;  // v2 -> x
    const EdgeIndex l2 = r.e12;  // x -> v1
    const EdgeIndex r1 = r.e11;  // v1 -> y
    const EdgeIndex r2 = r.e21;  // y -> v2
    const VertexIndex v1 = r.v1;
    const VertexIndex v2 = r.v2;
    const VertexIndex x = far_end(l1, v2);
    const VertexIndex y = far_end(r1, v1);
    // Now e = x -> y; left (v2, x, y) in slot rt, right (v1, y, x) in slot l.
    r.v1 = x;
    r.v2 = y;
    r.t1 = rt;
    r.t2 = l;
    tris_[l].e = {r1, e, l2};
    tris_[rt].e = {l1, e, r2};
    replace_side(r1, rt, l);
    replace_side(l1, l, rt);
    if (vertex_edge_[v1] == e) vertex_edge_[v1] = l2;
    if (vertex_edge_[v2] == e) vertex_edge_[v2] = l1;
    wing_triangle(l);
    wing_triangle(rt);
    ++flips_;
}

void WingedEdgeDelaunay::legalize(VertexIndex p) {
    while (!pending_.empty()) {
        const EdgeIndex e = pending_.back();
        pending_.pop_back();
        const WingedEdgeRecord& r = edges_[e];
        if (r.t2 == no_triangle) continue;  // a side of T_pom
        // The third corners from the wings: x of the left triangle (v1, v2, x), y of the
        // right one (v2, v1, y); p is one of them, the other is tested against the circle
        // through p and the edge (the triangle's corners rotated: the same predicate).
        const VertexIndex x = far_end(r.e22, r.v2);
        const VertexIndex y = far_end(r.e11, r.v1);
        const bool p_left = x == p;
        const int inside = p_left ? st_.incircle(r.v1, r.v2, x, y) : st_.incircle(r.v2, r.v1, y, x);
        if (inside <= 0) continue;
        // The far triangle's other sides, in its counter-clockwise order after e.
        const EdgeIndex f1 = p_left ? r.e11 : r.e22;
        const EdgeIndex f2 = p_left ? r.e21 : r.e12;
        flip(e);
        pending_.push_back(f1);
        pending_.push_back(f2);
    }
}

std::size_t WingedEdgeDelaunay::bytes() const noexcept {
    return edges_.capacity() * sizeof(WingedEdgeRecord) +
           tris_.capacity() * sizeof(WingedTriangle) + vertex_edge_.capacity() * sizeof(EdgeIndex) +
           pending_.capacity() * sizeof(EdgeIndex);
}

std::string WingedEdgeDelaunay::check() const {
    for (EdgeIndex e = 0; e < edges_.size(); ++e) {
        const WingedEdgeRecord& r = edges_[e];
        const std::string name = "edge " + std::to_string(e);
        if (r.v1 == r.v2) return name + ": both ends the same vertex";
        if (r.t1 == no_triangle || (position(r.t1, e) == 2 && tris_[r.t1].e[2] != e)) {
            return name + ": its left triangle does not list it";
        }
        if (r.t2 != no_triangle &&
            tris_[r.t2].e[static_cast<std::size_t>(position(r.t2, e))] != e) {
            return name + ": its right triangle does not list it";
        }
        WingedEdgeRecord expect = r;
        const auto& left = tris_[r.t1].e;
        const int k = position(r.t1, e);
        expect.e12 = left[static_cast<std::size_t>((k + 2) % 3)];
        expect.e22 = left[static_cast<std::size_t>((k + 1) % 3)];
        if (r.t2 != no_triangle) {
            const auto& right = tris_[r.t2].e;
            const int j = position(r.t2, e);
            expect.e11 = right[static_cast<std::size_t>((j + 1) % 3)];
            expect.e21 = right[static_cast<std::size_t>((j + 2) % 3)];
        }
        if (expect.e11 != r.e11 || expect.e12 != r.e12 || expect.e21 != r.e21 ||
            expect.e22 != r.e22) {
            return name + ": wings disagree with its triangles";
        }
    }
    for (TriangleIndex t = 0; t < tris_.size(); ++t) {
        const auto& e = tris_[t].e;
        for (int k = 0; k < 3; ++k) {
            const WingedEdgeRecord& r = edges_[e[static_cast<std::size_t>(k)]];
            if (r.t1 != t && r.t2 != t) {
                return "triangle " + std::to_string(t) + ": an edge does not know it";
            }
            const EdgeIndex next = e[static_cast<std::size_t>((k + 1) % 3)];
            const VertexIndex head = r.t1 == t ? r.v2 : r.v1;
            if (origin_in(next, t) != head) {
                return "triangle " + std::to_string(t) + ": edges do not chain";
            }
        }
    }
    return {};
}

std::vector<TriangleIndex> WingedEdgeDelaunay::corner_triangles() const {
    std::vector<TriangleIndex> dropped;
    for (TriangleIndex t = 0; t < tris_.size(); ++t) {
        const auto c = corners(t);
        if (st_.is_corner(c[0]) || st_.is_corner(c[1]) || st_.is_corner(c[2])) {
            dropped.push_back(t);
        }
    }
    return dropped;
}

TriangleIndex WingedEdgeDelaunay::kept_number(const std::vector<TriangleIndex>& dropped,
                                              TriangleIndex t) {
    if (t == no_triangle) return no_triangle;
    const auto it = std::lower_bound(dropped.begin(), dropped.end(), t);
    if (it != dropped.end() && *it == t) return no_triangle;
    return t - static_cast<TriangleIndex>(it - dropped.begin());
}

std::vector<Triangle> WingedEdgeDelaunay::real_triangles() const {
    // Triangles touching a corner of T_pom are O(hull) many: renumber by counting them.
    const std::vector<TriangleIndex> dropped = corner_triangles();
    auto renumber = [&](TriangleIndex t) { return kept_number(dropped, t); };
    std::vector<Triangle> out;
    out.reserve(tris_.size() - dropped.size());
    for (TriangleIndex t = 0; t < tris_.size(); ++t) {
        if (std::binary_search(dropped.begin(), dropped.end(), t)) continue;
        const auto& e = tris_[t].e;
        Triangle x;
        x.v = corners(t);
        x.n = {renumber(other_side(e[1], t)), renumber(other_side(e[2], t)),
               renumber(other_side(e[0], t))};
        out.push_back(x);
    }
    return out;
}

std::vector<Triangle> WingedEdgeDelaunay::release_triangles() {
    // The triangles touching a corner of T_pom are O(hull) many: a kept triangle's new number
    // is its old one minus the dropped ones before it. The links come from the edges (the
    // triangle across each side), 12 bytes per kept triangle, before the edges are freed;
    // the corners are written over the triangle list (at k <= t, never over a triangle
    // still to be read), then the edges are freed and the output assembled.
    free_storage(vertex_edge_);
    free_storage(pending_);
    const std::vector<TriangleIndex> dropped = corner_triangles();
    auto renumber = [&](TriangleIndex t) { return kept_number(dropped, t); };
    const std::size_t kept = tris_.size() - dropped.size();
    std::vector<std::array<TriangleIndex, 3>> links;
    links.reserve(kept);
    std::size_t k = 0;
    std::size_t d = 0;
    for (TriangleIndex t = 0; t < tris_.size(); ++t) {
        if (d < dropped.size() && dropped[d] == t) {
            ++d;
            continue;
        }
        const auto& e = tris_[t].e;
        links.push_back({renumber(other_side(e[1], t)), renumber(other_side(e[2], t)),
                         renumber(other_side(e[0], t))});
        tris_[k++].e = corners(t);
    }
    free_storage(edges_);
    std::vector<Triangle> out;
    out.reserve(kept);
    for (std::size_t t = 0; t < kept; ++t) out.push_back(Triangle{tris_[t].e, links[t]});
    free_storage(tris_);
    return out;
}

}  // namespace dtm::methods::detail
