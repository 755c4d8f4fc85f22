// SPDX-License-Identifier: MIT
//
// Constrained Delaunay editing of the kernel's triangles (with ghosts, ghost_mesh.hpp).
//
// Segment insertion (Anglada 1997; also Shewchuk's and Chew's CDT papers): walk from a towards b
// through the triangles the segment crosses, collecting them (the cavity) and the two chains of
// cavity boundary edges (left and right of a->b). The segment becomes one edge and each side (a
// pseudo-polygon) is retriangulated by the constrained Delaunay rule: for base edge (u, w), the
// apex c is the polygon vertex whose circle through u, w, c holds no other polygon vertex;
// recurse on the two sub-polygons. The new triangles take the cavity's slots (a cavity of k
// crossed edges has k + 1 triangles, and so do the two polygons). A vertex lying exactly on the
// segment splits it there; an existing edge along it is simply marked (overlapping collinear
// constraints merge). A crossed edge that is itself constrained is a crossing of two breaklines:
// the intersection point is inserted as a new vertex (z interpolated along each line; a
// disagreement beyond the tolerance is recorded), both constraints are split there and the
// insertion continues piece by piece.
//
// Point insertion: locate, split the enclosing triangle in three (or the two triangles of the
// edge it lies on in four), then Lawson flips that never flip a constrained edge. Locating uses
// a visibility walk with a random choice between exit edges, which terminates on any
// triangulation (Devillers, Pion, Teillaud, "Walking in a triangulation", 2002).
//
// Constraint bits are kept per half-edge, the same on both halves of an edge.
//
// References:
//   M. V. Anglada, "An improved incremental algorithm for constructing restricted Delaunay
//     triangulations", Computers & Graphics 21(2), 1997.
//   L. P. Chew, "Constrained Delaunay triangulations", Algorithmica 4, 1989.
//   C. L. Lawson, "Software for C1 surface interpolation", 1977 (edge flips).
#include "algo/detail/mesh_edit.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>

#include "algo/detail/big_array.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {

MeshEditor::MeshEditor(GhostMesh& mesh, std::vector<double>& z, double z_tolerance)
    : mesh_(mesh), z_(z), z_tolerance_(z_tolerance) {
    // Fresh arrays of the mesh's size, faulted in on all threads before their initialisation.
    assign_fresh(vertex_edge_, mesh.points.size(), no_half_edge);
    assign_fresh(mesh.bits, mesh.tris.size(), std::array<std::uint8_t, 3>{0, 0, 0});
    // A half-edge out of every vertex, whichever thread writes last: it is only where walks
    // start, and nothing depends on where they start (the sector a segment enters, the triangle
    // or vertex a point lies in are unique, and a point on an edge is reported on the edge's
    // half-edge with the smaller code).
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, mesh.tris.size(), 4096),
                      [&](const auto& range) {
                          for (std::size_t t = range.begin(); t < range.end(); ++t) {
                              for (unsigned i = 0; i < 3; ++i) {
                                  const VertexId v = mesh.tris[t].v[i];
                                  if (v == ghost) continue;
                                  std::atomic_ref<HalfEdge>(vertex_edge_[v])
                                      .store(half_edge(t, i), std::memory_order_relaxed);
                              }
                          }
                      });
}

void MeshEditor::prefetch(VertexId a, VertexId b, bool star) const noexcept {
    if (!star) {
        __builtin_prefetch(&vertex_edge_[a]);
        __builtin_prefetch(&mesh_.points[a]);
        __builtin_prefetch(&mesh_.points[b]);
        return;
    }
    const HalfEdge e = vertex_edge_[a];
    if (e == no_half_edge) return;
    __builtin_prefetch(&mesh_.tris[tri_of(e)]);
    __builtin_prefetch(&mesh_.bits[tri_of(e)]);
}

void MeshEditor::set_triangle(std::size_t t, VertexId a, VertexId b, VertexId c) {
    mesh_.set_triangle(t, a, b, c);
    if (a != ghost) vertex_edge_[a] = half_edge(t, 0);
    if (b != ghost) vertex_edge_[b] = half_edge(t, 1);
    if (c != ghost) vertex_edge_[c] = half_edge(t, 2);
}

void MeshEditor::bond(HalfEdge x, HalfEdge y, std::uint8_t bits) {
    mesh_.bond(x, y);
    mesh_.set_edge_bits(x, bits);
}

std::size_t MeshEditor::new_triangle() {
    mesh_.tris.emplace_back();
    mesh_.bits.push_back({0, 0, 0});
    return mesh_.tris.size() - 1;
}

VertexId MeshEditor::add_vertex(Point2 p, double z) {
    mesh_.points.push_back({p, no_vertex});
    z_.push_back(z);
    vertex_edge_.push_back(no_half_edge);
    return static_cast<VertexId>(mesh_.points.size() - 1);
}

MeshEditor::Quad MeshEditor::quad(HalfEdge x) const {
    const GhostMesh& m = mesh_;
    const HalfEdge y = m.twin(x);
    Quad q;
    q.t1 = tri_of(x);
    q.t2 = tri_of(y);
    q.a = m.org(x);
    q.b = m.dest(x);
    q.c = m.org(prev(x));
    q.d = m.org(prev(y));
    const std::array<HalfEdge, 4> sides{next(x), prev(x), next(y), prev(y)};  // bc, ca, ad, db
    for (std::size_t i = 0; i < 4; ++i) {
        q.outside[i] = m.twin(sides[i]);
        q.bits[i] = m.edge_bits(sides[i]);
    }
    return q;
}

HalfEdge MeshEditor::flip(HalfEdge x) {
    const Quad q = quad(x);
    set_triangle(q.t1, q.c, q.a, q.d);
    set_triangle(q.t2, q.d, q.b, q.c);
    bond(half_edge(q.t1, 0), q.outside[1], q.bits[1]);  // c - a
    bond(half_edge(q.t1, 1), q.outside[2], q.bits[2]);  // a - d
    bond(half_edge(q.t2, 0), q.outside[3], q.bits[3]);  // d - b
    bond(half_edge(q.t2, 1), q.outside[0], q.bits[0]);  // b - c
    bond(half_edge(q.t1, 2), half_edge(q.t2, 2), 0);
    return half_edge(q.t1, 2);
}

void MeshEditor::legalize(HalfEdge first) {
    GhostMesh& m = mesh_;
    std::vector<HalfEdge> stack{first};
    while (!stack.empty()) {
        const HalfEdge e = stack.back();
        stack.pop_back();
        if (m.edge_bits(e) != 0 || !m.is_real(e) || !m.is_real(m.twin(e))) continue;
        const VertexId a = m.org(e);
        const VertexId b = m.dest(e);
        const VertexId c = m.org(prev(e));
        const VertexId d = m.org(prev(m.twin(e)));
        if (geom::incircle(m.p(a), m.p(b), m.p(c), m.p(d)) <= 0) continue;
        const HalfEdge dc = flip(e);
        const std::size_t t1 = tri_of(dc);
        const std::size_t t2 = tri_of(m.twin(dc));
        stack.insert(stack.end(),
                     {half_edge(t1, 0), half_edge(t1, 1), half_edge(t2, 0), half_edge(t2, 1)});
    }
}

Location MeshEditor::locate(Point2 p, HalfEdge e) {
    const GhostMesh& m = mesh_;
    if (!m.is_real(e)) {  // a ghost: start in the real triangle behind its hull edge
        const std::size_t t = tri_of(e);
        for (unsigned i = 0; i < 3; ++i) {
            const HalfEdge h = half_edge(t, i);
            if (m.is_edge(h)) e = m.twin(h);
        }
        if (!m.is_real(e)) return {Location::Kind::outside, e};
    }
    const std::size_t limit = 4 * m.tris.size() + 64;
    for (std::size_t step = 0; step < limit; ++step) {
        const std::size_t t = tri_of(e);
        std::array<HalfEdge, 3> h{half_edge(t, 0), half_edge(t, 1), half_edge(t, 2)};
        std::array<int, 3> o{};
        for (unsigned i = 0; i < 3; ++i) {
            const Point2& q = m.p(m.org(h[i]));
            if (q.x == p.x && q.y == p.y) return {Location::Kind::vertex, h[i]};
        }
        for (unsigned i = 0; i < 3; ++i) o[i] = orient_p(m.org(h[i]), m.dest(h[i]), p);
        rng_ ^= rng_ << 13;
        rng_ ^= rng_ >> 7;
        rng_ ^= rng_ << 17;
        const unsigned first = static_cast<unsigned>(rng_ % 3);
        HalfEdge exit = no_half_edge;
        for (unsigned k = 0; k < 3 && exit == no_half_edge; ++k) {
            const unsigned i = (first + k) % 3;
            if (o[i] < 0) exit = h[i];
        }
        if (exit == no_half_edge) {
            for (unsigned i = 0; i < 3; ++i) {
                if (o[i] != 0) continue;
                // The same half-edge whichever side the walk came from (when both are real).
                const HalfEdge other = m.twin(h[i]);
                return {Location::Kind::edge, other < h[i] && m.is_real(other) ? other : h[i]};
            }
            return {Location::Kind::face, h[0]};
        }
        const HalfEdge across = m.twin(exit);
        if (!m.is_real(across)) return {Location::Kind::outside, exit};
        e = across;
    }
    throw Error("triangulation: point location did not terminate (corrupt mesh)");
}

VertexId MeshEditor::insert_point(Point2 p, double z, HalfEdge hint) {
    const Location loc = locate(p, hint);
    if (loc.kind == Location::Kind::vertex) return mesh_.org(loc.e);
    if (loc.kind == Location::Kind::outside) {
        throw Error("triangulation: a constructed point fell outside the hull");
    }
    GhostMesh& m = mesh_;
    std::vector<HalfEdge> stack;  // edges opposite the new vertex, to test
    VertexId v = 0;
    if (loc.kind == Location::Kind::face) {
        const std::size_t t = tri_of(loc.e);
        const auto [a, b, c] = m.tris[t].v;
        std::array<HalfEdge, 3> outer{};
        std::array<std::uint8_t, 3> outer_bits{};
        for (unsigned i = 0; i < 3; ++i) {
            outer[i] = m.twin(half_edge(t, i));
            outer_bits[i] = m.edge_bits(half_edge(t, i));
        }
        v = add_vertex(p, z);
        const std::size_t t1 = new_triangle();
        const std::size_t t2 = new_triangle();
        set_triangle(t, a, b, v);
        set_triangle(t1, b, c, v);
        set_triangle(t2, c, a, v);
        bond(half_edge(t, 0), outer[0], outer_bits[0]);
        bond(half_edge(t1, 0), outer[1], outer_bits[1]);
        bond(half_edge(t2, 0), outer[2], outer_bits[2]);
        bond(half_edge(t, 1), half_edge(t1, 2), 0);
        bond(half_edge(t1, 1), half_edge(t2, 2), 0);
        bond(half_edge(t2, 1), half_edge(t, 2), 0);
        stack = {half_edge(t, 0), half_edge(t1, 0), half_edge(t2, 0)};
    } else {
        if (!m.is_real(m.twin(loc.e))) {
            throw Error("triangulation: a constructed point fell on the hull");
        }
        const Quad q = quad(loc.e);  // (a, b, c) and (b, a, d) around the edge a -> b
        const std::uint8_t split = m.edge_bits(loc.e);
        const std::size_t t = q.t1;
        const std::size_t u = q.t2;
        v = add_vertex(p, z);
        const std::size_t t1 = new_triangle();
        const std::size_t t2 = new_triangle();
        set_triangle(t, q.a, v, q.c);
        set_triangle(t1, v, q.b, q.c);
        set_triangle(u, q.b, v, q.d);
        set_triangle(t2, v, q.a, q.d);
        bond(half_edge(t, 0), half_edge(t2, 0), split);   // a - v
        bond(half_edge(t1, 0), half_edge(u, 0), split);   // v - b
        bond(half_edge(t, 1), half_edge(t1, 2), 0);       // v - c
        bond(half_edge(u, 1), half_edge(t2, 2), 0);       // v - d
        bond(half_edge(t, 2), q.outside[1], q.bits[1]);   // c - a
        bond(half_edge(t1, 1), q.outside[0], q.bits[0]);  // b - c
        bond(half_edge(u, 2), q.outside[3], q.bits[3]);   // d - b
        bond(half_edge(t2, 1), q.outside[2], q.bits[2]);  // a - d
        stack = {half_edge(t, 2), half_edge(t1, 1), half_edge(u, 2), half_edge(t2, 1)};
    }
    // Lawson flips around the new vertex; constrained edges and the hull stay.
    while (!stack.empty()) {
        const HalfEdge h = stack.back();  // x -> y in (x, y, v)
        stack.pop_back();
        const HalfEdge g = m.twin(h);  // y -> x in (y, x, q)
        if (m.edge_bits(h) != 0 || !m.is_real(g)) continue;
        const VertexId x = m.org(h);
        const VertexId y = m.dest(h);
        const VertexId q = m.org(prev(g));
        if (orient(v, x, q) <= 0 || orient(q, y, v) <= 0) continue;
        if (geom::incircle(m.p(y), m.p(x), m.p(q), p) <= 0) continue;
        const HalfEdge qv = flip(h);  // (v, x, q) and (q, y, v)
        const std::size_t t1 = tri_of(qv);
        const std::size_t t2 = tri_of(m.twin(qv));
        stack.push_back(half_edge(t1, 1));  // x -> q
        stack.push_back(half_edge(t2, 0));  // q -> y
    }
    return v;
}

void MeshEditor::insert_segment(VertexId a, VertexId b, std::uint8_t bits) {
    std::vector<Work>& stack = work_scratch_;
    stack.assign(1, {a, b, bits});
    std::size_t steps = 0;
    const std::size_t limit = 64 * mesh_.points.size() + 1'000'000;
    while (!stack.empty()) {
        if (++steps > limit) throw Error("triangulation: breakline insertion did not converge");
        const Work work = stack.back();
        stack.pop_back();
        if (work.a == work.b) continue;
        insert_piece(work, stack);
    }
}

}  // namespace dtm::detail
