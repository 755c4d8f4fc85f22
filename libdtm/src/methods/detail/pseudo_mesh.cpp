// SPDX-License-Identifier: MIT
// The pseudo-triangulation structure and its point location (pseudo_mesh.hpp).
//
// Location is a straight walk from the inserted vertex nearest to the query (a bucket grid, or
// the last inserted vertex): the face around the start vertex whose angle holds the direction of
// the query, then face by face across the boundary edge the segment crosses first, restarting
// at a vertex the segment passes through. Every decision is an exact orientation or distance
// comparison; the thesis' random walk [Trcka07] is replaced because a visibility walk can cycle
// in faces that are not convex.
#include "methods/detail/pseudo_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "methods/detail/planar.hpp"

namespace dtm::methods::detail {

bool is_corner(std::span<const Point3> p, const Cycle& c, std::size_t i, CountingPredicates& pred) {
    const std::size_t k = c.size();
    return pred.orient(p[c[(i + k - 1) % k]], p[c[i]], p[c[(i + 1) % k]]) > 0;
}

std::vector<std::size_t> corners(std::span<const Point3> p,
                                 const Cycle& c,
                                 CountingPredicates& pred) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < c.size(); ++i) {
        if (is_corner(p, c, i, pred)) out.push_back(i);
    }
    return out;
}

PseudoMesh::PseudoMesh(std::span<const Point3> points, CountingPredicates& pred)
    : p_(points), pred_(pred) {
    const std::size_t n = points.size();
    some_face_.assign(n, kOuterFace);
    hull_next_.assign(n, no_vertex);
    hull_prev_.assign(n, no_vertex);
    inserted_.assign(n, false);
    Box2 box;
    for (const Point3& q : points) box.add(q);
    grid_.reset(box, std::max<std::size_t>(1, n / 2));
    left_.reserve(6 * n);
}

void PseudoMesh::mark_inserted(VertexIndex v) {
    if (!inserted_[v]) {
        inserted_[v] = true;
        grid_.insert_point(p_[v], v);
    }
}

void PseudoMesh::start(VertexIndex a, VertexIndex b, VertexIndex c) {
    add_face({a, b, c});
    hull_link(a, b);
    hull_link(b, c);
    hull_link(c, a);
    for (const VertexIndex v : {a, b, c}) mark_inserted(v);
}

FaceId PseudoMesh::left_face(VertexIndex a, VertexIndex b) const {
    const auto it = left_.find(key(a, b));
    if (it != left_.end()) return it->second;
    if (hull_next_[b] == a) return kOuterFace;
    return kOuterFace - 1;  // no such edge
}

bool PseudoMesh::has_edge(VertexIndex a, VertexIndex b) const {
    return left_.count(key(a, b)) > 0 || left_.count(key(b, a)) > 0;
}

void PseudoMesh::set_edges(FaceId f, const Cycle& c) {
    for (std::size_t i = 0; i < c.size(); ++i) {
        left_[key(c[i], c[(i + 1) % c.size()])] = f;
        some_face_[c[i]] = f;
    }
}

void PseudoMesh::clear_edges(FaceId f) {
    const Cycle& c = faces_[f];
    for (std::size_t i = 0; i < c.size(); ++i) {
        const auto it = left_.find(key(c[i], c[(i + 1) % c.size()]));
        if (it != left_.end() && it->second == f) left_.erase(it);
    }
}

FaceId PseudoMesh::add_face(Cycle cycle) {
    FaceId f;
    if (!free_.empty()) {
        f = free_.back();
        free_.pop_back();
        faces_[f] = std::move(cycle);
        alive_[f] = true;
    } else {
        f = static_cast<FaceId>(faces_.size());
        faces_.push_back(std::move(cycle));
        alive_.push_back(true);
    }
    ++face_count_;
    set_edges(f, faces_[f]);
    return f;
}

std::vector<FaceId> PseudoMesh::replace(std::span<const FaceId> old,
                                        std::span<const Cycle> cycles) {
    for (const FaceId f : old) {
        clear_edges(f);
        alive_[f] = false;
        free_.push_back(f);
        --face_count_;
    }
    std::vector<FaceId> out;
    for (const Cycle& c : cycles) out.push_back(add_face(c));
    return out;
}

std::vector<Cycle> PseudoMesh::faces() const {
    std::vector<Cycle> out;
    for (FaceId f = 0; f < faces_.size(); ++f) {
        if (alive_[f]) out.push_back(faces_[f]);
    }
    return out;
}

VertexIndex PseudoMesh::nearest_inserted(const Point3& q) const {
    const int c0 = grid_.col(q.x);
    const int r0 = grid_.row(q.y);
    VertexIndex best = no_vertex;
    double best_d = INFINITY;
    for (int ring = 0; ring <= 3 && best == no_vertex; ++ring) {
        for (int r = r0 - ring; r <= r0 + ring; ++r) {
            for (int c = c0 - ring; c <= c0 + ring; ++c) {
                if (r < 0 || c < 0 || r >= grid_.rows() || c >= grid_.cols()) continue;
                if (std::max(std::abs(r - r0), std::abs(c - c0)) != ring) continue;
                for (const std::uint32_t v : grid_.items(grid_.index(c, r))) {
                    const double d = std::hypot(p_[v].x - q.x, p_[v].y - q.y);
                    if (d < best_d) {
                        best_d = d;
                        best = v;
                    }
                }
            }
        }
    }
    return best;
}

FaceId PseudoMesh::face_towards(VertexIndex s, const Point3& q, VertexIndex& along) {
    along = no_vertex;
    const bool on_hull = hull_next_[s] != no_vertex;
    FaceId f = on_hull ? left_face(s, hull_next_[s]) : some_face_[s];
    const FaceId first = f;
    for (std::size_t guard = 0; guard < faces_.size() + 2; ++guard) {
        const Cycle& c = faces_[f];
        const std::size_t k = c.size();
        const std::size_t i =
            static_cast<std::size_t>(std::find(c.begin(), c.end(), s) - c.begin());
        const VertexIndex next = c[(i + 1) % k];
        const VertexIndex prev = c[(i + k - 1) % k];
        const int on_next = pred_.orient(p_[s], p_[next], q);
        // Along one of the face's edges at s (the edge to prev matters on the hull, where no
        // face has it as its next).
        for (const VertexIndex e : {next, prev}) {
            if ((e == next ? on_next : pred_.orient(p_[s], p_[e], q)) == 0 &&
                (q.x - p_[s].x) * (p_[e].x - p_[s].x) + (q.y - p_[s].y) * (p_[e].y - p_[s].y) > 0) {
                along = e;
                return f;
            }
        }
        const int wedge = pred_.orient(p_[s], p_[next], p_[prev]);
        const int on_prev = pred_.orient(p_[s], q, p_[prev]);
        const bool inside = wedge > 0   ? on_next > 0 && on_prev > 0
                            : wedge < 0 ? on_next > 0 || on_prev > 0
                                        : on_next > 0;
        if (inside) return f;
        f = left_face(s, prev);  // the next face counter-clockwise around s
        if (f >= kOuterFace - 1 || f == first) break;
    }
    return kOuterFace;
}

Location PseudoMesh::locate(VertexIndex qv) {
    const Point3& q = p_[qv];
    VertexIndex s = nearest_inserted(q);
    if (s == no_vertex) {
        // Fall back to any vertex of the last face.
        for (FaceId f = static_cast<FaceId>(faces_.size()); f-- > 0;) {
            if (alive_[f]) {
                s = faces_[f][0];
                break;
            }
        }
    }
    auto same = [&](VertexIndex v) { return p_[v].x == q.x && p_[v].y == q.y; };
    for (std::size_t restart = 0; restart <= p_.size() + 1; ++restart) {
        if (same(s)) return {Location::on_vertex, kOuterFace, s, no_vertex};
        VertexIndex along = no_vertex;
        FaceId f = face_towards(s, q, along);
        if (along != no_vertex) {
            if (same(along)) return {Location::on_vertex, kOuterFace, along, no_vertex};
            if (strictly_inside_segment(pred_, p_[s], p_[along], q)) {
                return {Location::on_edge, kOuterFace, s, along};
            }
            s = along;
            continue;
        }
        if (f == kOuterFace) {
            // q lies outside, seen past the hull vertex s: one of its hull edges faces q, or
            // further along the hull.
            VertexIndex a = s;
            for (std::size_t k = 0; k < p_.size(); ++k) {
                if (pred_.orient(p_[a], p_[hull_next_[a]], q) < 0) {
                    return {Location::outside, kOuterFace, a, hull_next_[a]};
                }
                if (pred_.orient(p_[hull_prev_[a]], p_[a], q) < 0) {
                    return {Location::outside, kOuterFace, hull_prev_[a], a};
                }
                a = hull_next_[a];
            }
            throw std::logic_error("pseudo: no hull edge faces an outside point");
        }
        // Walk from s through f and its successors.
        VertexIndex in_a = no_vertex;  // the edge we entered the current face through
        VertexIndex in_b = no_vertex;
        bool restarted = false;
        for (std::size_t step = 0; step <= 4 * faces_.size() + 4 && !restarted; ++step) {
            const Cycle& c = faces_[f];
            const std::size_t k = c.size();
            // Nearest hit beyond the entry: a vertex strictly inside segment s-q, or an edge
            // crossed properly.
            VertexIndex hit_v = no_vertex;
            VertexIndex hit_a = no_vertex;
            VertexIndex hit_b = no_vertex;
            auto edge_nearer = [&](VertexIndex a1, VertexIndex b1, VertexIndex a2, VertexIndex b2) {
                // Edge a1b1 crosses s-q before a2b2 (non-crossing edges).
                const int si = pred_.orient(p_[a2], p_[b2], p_[s]);
                const int s1 = pred_.orient(p_[a2], p_[b2], p_[a1]);
                const int s2 = pred_.orient(p_[a2], p_[b2], p_[b1]);
                if (s1 * s2 >= 0 && (s1 != 0 || s2 != 0)) return (s1 != 0 ? s1 : s2) == si;
                const int ti = pred_.orient(p_[a1], p_[b1], p_[s]);
                const int t1 = pred_.orient(p_[a1], p_[b1], p_[a2]);
                const int t2 = pred_.orient(p_[a1], p_[b1], p_[b2]);
                return (t1 != 0 ? t1 : t2) != ti;
            };
            auto vertex_before_edge = [&](VertexIndex w, VertexIndex a1, VertexIndex b1) {
                return pred_.orient(p_[a1], p_[b1], p_[w]) == pred_.orient(p_[a1], p_[b1], p_[s]);
            };
            auto beyond_entry_vertex = [&](VertexIndex w) {
                return in_a == no_vertex || !vertex_before_edge(w, in_a, in_b);
            };
            auto beyond_entry_edge = [&](VertexIndex a1, VertexIndex b1) {
                return in_a == no_vertex || edge_nearer(in_a, in_b, a1, b1);
            };
            for (std::size_t i = 0; i < k; ++i) {
                const VertexIndex u = c[i];
                const VertexIndex v = c[(i + 1) % k];
                if ((u == in_a && v == in_b) || (u == in_b && v == in_a)) continue;
                if (u != s && strictly_inside_segment(pred_, p_[s], q, p_[u]) &&
                    beyond_entry_vertex(u)) {
                    bool better = true;
                    if (hit_v != no_vertex) {
                        better = pred_.compare_distances(p_[s], p_[u], p_[s], p_[hit_v]) < 0;
                    } else if (hit_a != no_vertex) {
                        better = vertex_before_edge(u, hit_a, hit_b);
                    }
                    if (better) {
                        hit_v = u;
                        hit_a = hit_b = no_vertex;
                    }
                }
                if (u != s && v != s && properly_cross(pred_, p_[s], q, p_[u], p_[v]) &&
                    beyond_entry_edge(u, v)) {
                    bool better = true;
                    if (hit_v != no_vertex) {
                        better = !vertex_before_edge(hit_v, u, v);
                    } else if (hit_a != no_vertex) {
                        better = edge_nearer(u, v, hit_a, hit_b);
                    }
                    if (better) {
                        hit_a = u;
                        hit_b = v;
                        hit_v = no_vertex;
                    }
                }
            }
            if (hit_v != no_vertex) {
                s = hit_v;
                restarted = true;
                break;
            }
            if (hit_a == no_vertex) {
                // q is in f, on its boundary or inside.
                for (std::size_t i = 0; i < k; ++i) {
                    const VertexIndex u = c[i];
                    const VertexIndex v = c[(i + 1) % k];
                    if (same(u)) return {Location::on_vertex, kOuterFace, u, no_vertex};
                    if (strictly_inside_segment(pred_, p_[u], p_[v], q)) {
                        return {Location::on_edge, kOuterFace, u, v};
                    }
                }
                return {Location::inside, f, no_vertex, no_vertex};
            }
            const FaceId g = left_face(hit_b, hit_a);
            if (g == kOuterFace) return {Location::outside, kOuterFace, hit_a, hit_b};
            in_a = hit_b;
            in_b = hit_a;
            f = g;
        }
        if (!restarted) throw std::logic_error("pseudo: the location walk did not end");
    }
    throw std::logic_error("pseudo: the location walk did not end");
}

}  // namespace dtm::methods::detail
