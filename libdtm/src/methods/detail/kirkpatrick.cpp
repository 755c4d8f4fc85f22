// SPDX-License-Identifier: MIT
// Kirkpatrick's hierarchy (kirkpatrick.hpp): D. G. Kirkpatrick, "Optimal search in planar
// subdivisions", SIAM J. Comput. 12 (1983); thesis 000 §3.8.2 after Preparata and Shamos.
//
// Build, level by level, on a working copy of the triangulation (triangles with neighbour
// links): choose greedily an independent set of removable vertices of degree < 12 (K = 12:
// total degree < 6N, so at least half the vertices qualify and each choice blocks at most 11,
// the thesis' alpha < 0.955 bound); remove each, triangulating its hole (a simple polygon of
// at most 11 vertices, star-shaped from the removed vertex) by ear clipping with exact
// orientations, and give every new triangle the old triangles of the star it overlaps
// (interiors meet; tested by separating edges) as children. The last level is the big
// triangle. A query is Kirkpatrick's Locate: from the big triangle into the child that
// contains the point, down to the triangulation the hierarchy was built on.
#include "methods/detail/kirkpatrick.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "methods/detail/method_support.hpp"
#include "methods/detail/tri_mesh.hpp"

namespace dtm::methods::detail {
namespace {

using Corners = KirkpatrickHierarchy::Corners;

/// The interiors of two counter-clockwise triangles do not meet: an edge of one has the other
/// entirely on its closed outer side.
bool separated(const Corners& t, const Corners& u, SuperTriangle& st) {
    auto outside = [&st](const Corners& a, const Corners& b) {
        for (int i = 0; i < 3; ++i) {
            const VertexIndex p = a[static_cast<std::size_t>(i)];
            const VertexIndex q = a[static_cast<std::size_t>((i + 1) % 3)];
            if (st.orient(p, q, b[0]) <= 0 && st.orient(p, q, b[1]) <= 0 &&
                st.orient(p, q, b[2]) <= 0) {
                return true;
            }
        }
        return false;
    };
    return outside(t, u) || outside(u, t);
}

bool contains(const Corners& t, VertexIndex q, SuperTriangle& st) {
    return st.orient(t[0], t[1], q) >= 0 && st.orient(t[1], t[2], q) >= 0 &&
           st.orient(t[2], t[0], q) >= 0;
}

/// Triangulates the simple counter-clockwise polygon @p poly (at most 11 vertices) by ear
/// clipping: an ear is a strictly convex corner whose triangle holds no other vertex.
std::vector<Corners> clip_ears(std::vector<VertexIndex> poly, SuperTriangle& st) {
    std::vector<Corners> out;
    while (poly.size() > 3) {
        const std::size_t m = poly.size();
        bool cut = false;
        for (std::size_t j = 0; j < m && !cut; ++j) {
            const Corners ear{poly[(j + m - 1) % m], poly[j], poly[(j + 1) % m]};
            if (st.orient(ear[0], ear[1], ear[2]) <= 0) continue;
            bool empty = true;
            for (std::size_t k = 0; k < m && empty; ++k) {
                const VertexIndex w = poly[k];
                if (w != ear[0] && w != ear[1] && w != ear[2] && contains(ear, w, st)) {
                    empty = false;
                }
            }
            if (!empty) continue;
            out.push_back(ear);
            poly.erase(poly.begin() + static_cast<long>(j));
            cut = true;
        }
        if (!cut) throw std::logic_error("Kirkpatrick: a hole polygon without an ear");
    }
    out.push_back({poly[0], poly[1], poly[2]});
    return out;
}

}  // namespace

void KirkpatrickHierarchy::build(std::vector<Corners> triangles,
                                 std::size_t vertex_count,
                                 SuperTriangle& st) {
    free_storage(first_child_);
    free_storage(children_);
    corners_ = std::move(triangles);
    leaves_ = corners_.size();
    levels_ = 1;
    max_children_ = 0;
    TriMesh mesh;
    mesh.tri = link_triangles(corners_, vertex_count);
    std::vector<std::uint32_t> node_of(mesh.tri.size());
    corners_.reserve(3 * leaves_);  // 2.7 nodes per leaf measured
    first_child_.reserve(2 * leaves_ + 1);
    children_.reserve(6 * leaves_);
    for (TriangleIndex t = 0; t < mesh.tri.size(); ++t) node_of[t] = t;
    std::vector<TriangleIndex> vtri(vertex_count, no_triangle);
    for (TriangleIndex t = 0; t < mesh.tri.size(); ++t) {
        for (const VertexIndex v : mesh[t].v) vtri[v] = t;
    }
    std::vector<VertexIndex> remaining;
    for (VertexIndex v = 0; v < vertex_count; ++v) {
        if (!st.is_corner(v) && vtri[v] != no_triangle) remaining.push_back(v);
    }
    std::vector<std::uint32_t> blocked(vertex_count, 0);
    std::vector<TriangleIndex> star_t;
    std::vector<VertexIndex> link;
    std::vector<VertexIndex> chosen;
    std::vector<TriangleIndex> free_slots;
    auto star = [&](VertexIndex v) {
        star_t.clear();
        link.clear();
        const TriangleIndex first = vtri[v];
        TriangleIndex t = first;
        do {
            const Triangle& x = mesh[t];
            const int i = x.v[0] == v ? 0 : (x.v[1] == v ? 1 : 2);
            star_t.push_back(t);
            link.push_back(x.v[static_cast<std::size_t>(next3(i))]);
            t = x.n[static_cast<std::size_t>(next3(i))];  // across (v, w_j+1)
            if (star_t.size() > mesh.tri.size() || t == no_triangle) {
                throw std::logic_error("Kirkpatrick: broken star");
            }
        } while (t != first);
    };
    for (std::uint32_t level = 1; !remaining.empty(); ++level) {
        // The independent set of this level: degree < 12, no two adjacent.
        chosen.clear();
        for (const VertexIndex v : remaining) {
            if (blocked[v] == level) continue;
            star(v);
            if (star_t.size() >= 12) continue;
            chosen.push_back(v);
            blocked[v] = level;
            for (const VertexIndex w : link) blocked[w] = level;
        }
        for (const VertexIndex v : chosen) {
            star(v);
            const std::size_t d = star_t.size();
            // Outer neighbour across each hole side (w_j, w_j+1).
            std::vector<TriangleIndex> outer(d);
            std::vector<std::uint32_t> old_nodes(d);
            for (std::size_t j = 0; j < d; ++j) {
                const Triangle& x = mesh[star_t[j]];
                const int i = x.v[0] == v ? 0 : (x.v[1] == v ? 1 : 2);
                outer[j] = x.n[static_cast<std::size_t>(i)];
                old_nodes[j] = node_of[star_t[j]];
            }
            const std::vector<Corners> fresh = clip_ears(link, st);
            // New triangles into d - 2 of the star's slots; links inside the hole and out.
            std::vector<TriangleIndex> slot(fresh.size());
            for (std::size_t k = 0; k < fresh.size(); ++k) slot[k] = star_t[k];
            for (std::size_t k = fresh.size(); k < d; ++k) free_slots.push_back(star_t[k]);
            for (std::size_t k = 0; k < fresh.size(); ++k) {
                Triangle& x = mesh[slot[k]];
                x.v = fresh[k];
                for (int i = 0; i < 3; ++i) {
                    const VertexIndex a = fresh[k][static_cast<std::size_t>(next3(i))];
                    const VertexIndex b = fresh[k][static_cast<std::size_t>(prev3(i))];
                    TriangleIndex across = no_triangle;
                    for (std::size_t j = 0; j < d && across == no_triangle; ++j) {
                        if (link[j] == a && link[(j + 1) % d] == b) {
                            across = outer[j];
                            if (across != no_triangle) {
                                // The outer triangle's link back across (b, a); by the edge,
                                // not by the old id, which a reused slot may alias.
                                Triangle& o = mesh[across];
                                for (int q = 0; q < 3; ++q) {
                                    if (o.v[static_cast<std::size_t>(next3(q))] == b &&
                                        o.v[static_cast<std::size_t>(prev3(q))] == a) {
                                        o.n[static_cast<std::size_t>(q)] = slot[k];
                                    }
                                }
                            }
                        }
                    }
                    for (std::size_t m = 0; m < fresh.size() && across == no_triangle; ++m) {
                        for (int q = 0; q < 3; ++q) {
                            if (m != k && fresh[m][static_cast<std::size_t>(next3(q))] == b &&
                                fresh[m][static_cast<std::size_t>(prev3(q))] == a) {
                                across = slot[m];
                            }
                        }
                    }
                    x.n[static_cast<std::size_t>(i)] = across;
                }
                for (const VertexIndex w : fresh[k]) vtri[w] = slot[k];
                // The node of the new triangle, children: the old star triangles it overlaps.
                const auto first = static_cast<std::uint32_t>(children_.size());
                for (std::size_t j = 0; j < d; ++j) {
                    if (!separated(fresh[k], corners_[old_nodes[j]], st)) {
                        children_.push_back(old_nodes[j]);
                    }
                }
                max_children_ = std::max<std::size_t>(max_children_, children_.size() - first);
                node_of[slot[k]] = static_cast<std::uint32_t>(corners_.size());
                corners_.push_back(fresh[k]);
                first_child_.push_back(first);
            }
            vtri[v] = no_triangle;
        }
        std::erase_if(remaining, [&](VertexIndex v) { return vtri[v] == no_triangle; });
        ++levels_;
    }
    first_child_.push_back(static_cast<std::uint32_t>(children_.size()));
    // The big triangle is the one live triangle left.
    std::vector<bool> is_free(mesh.tri.size(), false);
    for (const TriangleIndex t : free_slots) is_free[t] = true;
    for (TriangleIndex t = 0; t < mesh.tri.size(); ++t) {
        if (!is_free[t]) root_ = node_of[t];
    }
}

KirkpatrickHierarchy::Corners KirkpatrickHierarchy::locate(VertexIndex q,
                                                           SuperTriangle& st,
                                                           std::uint64_t& steps) const {
    std::uint32_t at = root_;
    while (at >= leaves_) {
        const std::uint32_t begin = first_child_[at - leaves_];
        const std::uint32_t end = first_child_[at - leaves_ + 1];
        if (begin == end) break;
        std::uint32_t next = children_[begin];  // the children cover the node: one holds q
        for (std::uint32_t c = begin; c < end; ++c) {
            ++steps;
            next = children_[c];
            if (contains(corners_[next], q, st)) break;
        }
        at = next;
    }
    return corners_[at];
}

}  // namespace dtm::methods::detail
