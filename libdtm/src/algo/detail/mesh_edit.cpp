// SPDX-License-Identifier: MIT
//
// Constrained Delaunay editing of the kernel's edge mesh.
//
// Segment insertion (Anglada 1997; also Shewchuk's and Chew's CDT papers): walk from a towards b
// through the triangles the segment crosses, collecting the crossed edges and the two chains of
// cavity boundary edges (left and right of a->b). The crossed edges are deleted, the segment is
// added as one edge, and each side (a pseudo-polygon) is retriangulated by the constrained
// Delaunay rule: for base edge (u, w), the apex c is the polygon vertex whose circle through
// u, w, c holds no other polygon vertex; recurse on the two sub-polygons. A vertex lying exactly on
// the segment splits it there; an existing edge along it is simply marked (overlapping collinear
// constraints merge). A crossed edge that is itself constrained is a crossing of two breaklines:
// the intersection point is inserted as a new vertex (z interpolated along each line; a
// disagreement beyond the tolerance is recorded), both constraints are split there and the
// insertion continues piece by piece.
//
// Point insertion is Guibas and Stolfi's InsertSite: locate, connect the new vertex to the
// enclosing triangle (or quadrilateral, on an edge), then Lawson flips that never flip a
// constrained edge. Locating uses a visibility walk with a random choice between exit edges,
// which terminates on any triangulation (Devillers, Pion, Teillaud, "Walking in a
// triangulation", 2002).
//
// References:
//   M. V. Anglada, "An improved incremental algorithm for constructing restricted Delaunay
//     triangulations", Computers & Graphics 21(2), 1997.
//   L. P. Chew, "Constrained Delaunay triangulations", Algorithmica 4, 1989.
//   L. Guibas, J. Stolfi, ACM TOG 4(2), 1985.
#include "algo/detail/mesh_edit.hpp"

#include <cmath>

#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {

MeshEditor::MeshEditor(EdgeMesh& mesh, EdgeSlots& slots, std::vector<double>& z,
                       double z_tolerance)
    : mesh_(mesh), slots_(slots), z_(z), z_tolerance_(z_tolerance),
      vertex_edge_(mesh.points.size(), no_edge)
{
    const std::size_t directed = 2 * mesh.slot_count();
    for (EdgeId e = 0; e < directed; ++e) {
        if (mesh.alive[e >> 1]) vertex_edge_[mesh.org[e]] = e;
    }
}

EdgeId MeshEditor::find_edge(VertexId a, VertexId b) const
{
    const EdgeId start = vertex_edge_[a];
    if (start == no_edge) return no_edge;
    EdgeId e = start;
    do {
        if (mesh_.dest(e) == b) return e;
        e = mesh_.onext[e];
    } while (e != start);
    return no_edge;
}

void MeshEditor::ensure_slots(std::size_t count)
{
    if (slots_.available() >= count) return;
    const std::size_t grown = mesh_.slot_count() + mesh_.slot_count() / 2 + count + 64;
    mesh_.grow_slots(grown);
    slots_.end = static_cast<EdgeId>(grown);
}

VertexId MeshEditor::add_vertex(Point2 p, double z)
{
    mesh_.points.push_back({p, no_edge});
    z_.push_back(z);
    vertex_edge_.push_back(no_edge);
    return static_cast<VertexId>(mesh_.points.size() - 1);
}

void MeshEditor::delete_edge(EdgeId e, EdgeSlots& slots)
{
    for (const EdgeId d : {e, EdgeMesh::sym(e)}) {
        const VertexId v = mesh_.org[d];
        if (vertex_edge_[v] == d) vertex_edge_[v] = mesh_.onext[d] != d ? mesh_.onext[d] : no_edge;
    }
    mesh_.delete_edge(slots, e);
}

void MeshEditor::flip(EdgeId e)
{
    for (const EdgeId d : {e, EdgeMesh::sym(e)}) {
        const VertexId v = mesh_.org[d];
        if (vertex_edge_[v] == d) vertex_edge_[v] = mesh_.onext[d];
    }
    mesh_.swap(e);
    vertex_edge_[mesh_.org[e]] = e;
    vertex_edge_[mesh_.dest(e)] = EdgeMesh::sym(e);
}

Location MeshEditor::locate(Point2 p, EdgeId e)
{
    if (orient_p(mesh_.org[e], mesh_.dest(e), p) < 0) e = EdgeMesh::sym(e);
    const std::size_t limit = 4 * mesh_.slot_count() + 64;
    for (std::size_t step = 0; step < limit; ++step) {
        if (!is_triangle(e)) return {Location::Kind::outside, e};
        const EdgeId e1 = mesh_.lnext(e);
        const EdgeId e2 = mesh_.lnext(e1);
        for (const EdgeId d : {e, e1, e2}) {
            const Point2& q = mesh_.p(mesh_.org[d]);
            if (q.x == p.x && q.y == p.y) return {Location::Kind::vertex, d};
        }
        const int o1 = orient_p(mesh_.org[e1], mesh_.dest(e1), p);
        const int o2 = orient_p(mesh_.org[e2], mesh_.dest(e2), p);
        rng_ ^= rng_ << 13;
        rng_ ^= rng_ >> 7;
        rng_ ^= rng_ << 17;
        const bool first_e1 = (rng_ & 1u) != 0;
        if (o1 < 0 && (o2 >= 0 || first_e1)) {
            e = EdgeMesh::sym(e1);
        } else if (o2 < 0) {
            e = EdgeMesh::sym(e2);
        } else {
            const int o0 = orient_p(mesh_.org[e], mesh_.dest(e), p);
            if (o0 == 0) return {Location::Kind::edge, e};
            if (o1 == 0) return {Location::Kind::edge, e1};
            if (o2 == 0) return {Location::Kind::edge, e2};
            return {Location::Kind::face, e};
        }
    }
    throw Error("triangulation: point location did not terminate (corrupt mesh)");
}

VertexId MeshEditor::insert_point(Point2 p, double z, EdgeId hint)
{
    const Location loc = locate(p, hint);
    if (loc.kind == Location::Kind::vertex) return mesh_.org[loc.e];
    if (loc.kind == Location::Kind::outside) {
        throw Error("triangulation: a constructed point fell outside the hull");
    }
    ensure_slots(8);
    EdgeMesh& m = mesh_;
    EdgeId e = loc.e;
    std::uint8_t split_bits = 0;
    VertexId split_a = no_edge;
    VertexId split_b = no_edge;
    if (loc.kind == Location::Kind::edge) {
        if (!is_triangle(EdgeMesh::sym(e))) {
            throw Error("triangulation: a constructed point fell on the hull");
        }
        split_bits = m.constrained[e >> 1];
        split_a = m.org[e];
        split_b = m.dest(e);
        const EdgeId t = m.oprev[e];
        delete_edge(e, slots_);
        e = t;
    }
    const VertexId v = add_vertex(p, z);
    EdgeId base = m.make_edge(slots_, m.org[e], v);
    m.splice(base, e);
    vertex_edge_[v] = EdgeMesh::sym(base);
    const EdgeId start = base;
    do {
        base = m.connect(slots_, e, EdgeMesh::sym(base));
        e = m.oprev[base];
    } while (m.lnext(e) != start);
    if (split_bits != 0) {
        m.constrained[find_edge(v, split_a) >> 1] = split_bits;
        m.constrained[find_edge(v, split_b) >> 1] = split_bits;
    }
    // Lawson flips around the new vertex; constrained edges stay.
    for (;;) {
        const EdgeId t = m.oprev[e];
        if (!m.is_constrained(e) && orient_p(m.dest(t), m.dest(e), m.p(m.org[e])) > 0 &&
            geom::incircle(m.p(m.org[e]), m.p(m.dest(t)), m.p(m.dest(e)), p) > 0) {
            flip(e);
            e = m.oprev[e];
        } else if (m.onext[e] == start) {
            break;
        } else {
            e = m.lprev(m.onext[e]);
        }
    }
    return v;
}

void MeshEditor::legalize(EdgeId first)
{
    std::vector<EdgeId> stack{first};
    while (!stack.empty()) {
        const EdgeId e = stack.back();
        stack.pop_back();
        if (!mesh_.alive[e >> 1] || mesh_.is_constrained(e)) continue;
        if (!is_triangle(e) || !is_triangle(EdgeMesh::sym(e))) continue;
        const VertexId a = mesh_.org[e];
        const VertexId b = mesh_.dest(e);
        const VertexId c = mesh_.dest(mesh_.lnext(e));
        const VertexId d = mesh_.dest(mesh_.lnext(EdgeMesh::sym(e)));
        if (geom::incircle(mesh_.p(a), mesh_.p(b), mesh_.p(c), mesh_.p(d)) <= 0) continue;
        flip(e);
        const EdgeId s = EdgeMesh::sym(e);
        stack.insert(stack.end(), {mesh_.lnext(e), mesh_.lprev(e), mesh_.lnext(s), mesh_.lprev(s)});
    }
}

void MeshEditor::insert_segment(VertexId a, VertexId b, std::uint8_t bits)
{
    std::vector<Work> stack{{a, b, bits}};
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
