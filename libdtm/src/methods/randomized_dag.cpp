// SPDX-License-Identifier: MIT
// [randomized-dag] Randomized incremental Delaunay triangulation with the history DAG for
// point location (lecture 003, Alg. 1 RANDOMIZEDINCREMENTALDT, Alg. 3 LEGALIZEEDGE, Alg. 4
// the legality test; after de Berg, van Kreveld, Overmars, Schwarzkopf, "Computational
// Geometry", ch. 9; Guibas, Knuth, Sharir 1992 for the analysis).
//
// Idea: start from a triangle holding every point; insert the points in random order; locate
// each in the current triangle containing it, split that triangle in three (or the two at an
// edge in four), and legalize the edges opposite the new point by flips, recursively. The
// location structure is the history of the triangulation: every triangle ever made is a node;
// a split or flip makes the destroyed triangles' nodes point to the triangles that replaced
// them; a query descends from the first triangle to a current one.
// Super-triangle: symbolic by default (detail/super_triangle.hpp: corners at infinity of
// different orders, every predicate its limit), so all hull edges survive the corners'
// removal; `super-triangle=finite` is the lecture's literal d = 100 x extent, which can lose
// hull edges near an almost straight part of the hull (shown by a test).
// Data structure, compact: per triangle ever made one 32-bit "fate" word: a live triangle's
// slot in the mesh (the output layout, slots reused by flips and splits), or a record of how
// it was replaced: a two-way record (x, y, first child) for flips and edge splits (the two
// children on either side of the segment x-y), or a three-way record (p, a, b, c, first
// child) for a split at p. About 9n triangles, n three-way and 3n two-way records for random
// input: ~95 bytes per point for the history, ~175 with the mesh and the points.
// Expected O(n log n) time and O(n) memory (003).
#include "randomized_dag.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "dtm/core/error.hpp"
#include "methods/detail/method_support.hpp"
#include "methods/detail/paged_array.hpp"
#include "methods/detail/spatial_order.hpp"
#include "methods/detail/super_triangle.hpp"
#include "methods/detail/tri_mesh.hpp"

namespace dtm::methods {
namespace {

using detail::SuperTriangle;
using detail::TriMesh;

constexpr std::uint32_t tag_live = 0u << 30;
constexpr std::uint32_t tag_two = 1u << 30;
constexpr std::uint32_t tag_three = 2u << 30;
constexpr std::uint32_t tag_mask = 3u << 30;
constexpr std::uint32_t index_mask = ~tag_mask;

struct TwoWay {
    VertexIndex x, y;     ///< children: first on the right of x->y, first + 1 on the left
    std::uint32_t first;  ///< triangle id of the first child
};
struct ThreeWay {
    VertexIndex p, a, b, c;  ///< split of (a, b, c) at p into (a,b,p), (b,c,p), (c,a,p)
    std::uint32_t first;
};

class RandomizedDag {
public:
    RandomizedDag(const std::vector<Point3>& pts,
                  detail::CountingPredicates& pred,
                  SuperTriangle::Mode mode)
        : pts_(pts), st_(pts, pred, mode) {
        const std::size_t n = pts.size();
        mesh_.tri.reserve(2 * n + 1);
        slot_id_.reserve(2 * n + 1);
        Triangle root;
        root.v = {st_.corner(0), st_.corner(1), st_.corner(2)};
        mesh_.tri.push_back(root);
        slot_id_.push_back(0);
        fate_.push_back(tag_live | 0u);
    }

    void insert(VertexIndex q) {
        const TriangleIndex t = locate(q);
        const Triangle& x = mesh_[t];
        for (int i = 0; i < 3; ++i) {
            const VertexIndex a = x.v[static_cast<std::size_t>(detail::next3(i))];
            const VertexIndex b = x.v[static_cast<std::size_t>(detail::prev3(i))];
            if (st_.orient(a, b, q) == 0) {
                split_edge(t, i, q);
                return;
            }
        }
        split_triangle(t, q);
    }

    [[nodiscard]] std::uint64_t flips() const { return flips_; }
    [[nodiscard]] std::uint64_t steps() const { return steps_; }
    [[nodiscard]] std::size_t nodes() const { return fate_.size(); }
    [[nodiscard]] std::size_t bytes() const {
        return detail::bytes_of(mesh_.tri) + detail::bytes_of(slot_id_) + fate_.bytes() +
               three_.bytes() + two_.bytes();
    }

    /// The triangles without a corner of the super-triangle, linked, compacted in place (the
    /// mesh is the output); the history is released first.
    [[nodiscard]] std::vector<Triangle> take_real_triangles(std::size_t& peak) {
        peak = std::max(peak, bytes());
        fate_.clear();
        two_.clear();
        three_.clear();
        std::vector<std::uint32_t>& renumber = slot_id_;  // reused: same size, no longer needed
        TriangleIndex count = 0;
        for (TriangleIndex t = 0; t < mesh_.tri.size(); ++t) {
            const auto& v = mesh_[t].v;
            const bool real = !st_.is_corner(v[0]) && !st_.is_corner(v[1]) && !st_.is_corner(v[2]);
            renumber[t] = real ? count++ : no_triangle;
        }
        for (TriangleIndex t = 0; t < mesh_.tri.size(); ++t) {
            if (renumber[t] == no_triangle) continue;
            Triangle x = mesh_[t];
            for (TriangleIndex& n : x.n) n = n == no_triangle ? no_triangle : renumber[n];
            mesh_.tri[renumber[t]] = x;
        }
        mesh_.tri.resize(count);
        detail::free_storage(slot_id_);
        return std::move(mesh_.tri);
    }

private:
    /// Descends the history from the first triangle to the current one containing q.
    TriangleIndex locate(VertexIndex q) {
        std::uint32_t id = 0;
        for (;;) {
            ++steps_;
            const std::uint32_t f = fate_[id];
            const std::uint32_t k = f & index_mask;
            if ((f & tag_mask) == tag_live) return k;
            if ((f & tag_mask) == tag_two) {
                const TwoWay& r = two_[k];
                id = r.first + (st_.orient(r.x, r.y, q) < 0 ? 0u : 1u);
            } else {
                const ThreeWay& r = three_[k];
                if (st_.orient(r.p, r.b, q) <= 0) {
                    id = r.first + (st_.orient(r.p, r.a, q) >= 0 ? 0u : 2u);
                } else {
                    id = r.first + (st_.orient(r.p, r.c, q) <= 0 ? 1u : 2u);
                }
            }
        }
    }

    /// A new triangle id for slot t (fate: live).
    std::uint32_t make_live(TriangleIndex t) {
        if (fate_.size() >= index_mask) throw Error("randomized-dag: history too large");
        fate_.push_back(tag_live | t);
        slot_id_[t] = static_cast<std::uint32_t>(fate_.size() - 1);
        return slot_id_[t];
    }
    TriangleIndex new_slot() {
        mesh_.tri.emplace_back();
        slot_id_.push_back(0);
        return static_cast<TriangleIndex>(mesh_.tri.size() - 1);
    }

    void split_triangle(TriangleIndex t, VertexIndex p) {
        const Triangle old = mesh_[t];
        const auto [a, b, c] = old.v;
        const auto [na, nb, nc] = old.n;  // across (b,c), (c,a), (a,b)
        const TriangleIndex t1 = new_slot();
        const TriangleIndex t2 = new_slot();
        // t0 = (a, b, p), t1 = (b, c, p), t2 = (c, a, p).
        mesh_[t].v = {a, b, p};
        mesh_[t].n = {t1, t2, nc};
        mesh_[t1].v = {b, c, p};
        mesh_[t1].n = {t2, t, na};
        mesh_[t2].v = {c, a, p};
        mesh_[t2].n = {t, t1, nb};
        mesh_.relink(na, t, t1);
        mesh_.relink(nb, t, t2);
        const std::uint32_t dead = slot_id_[t];
        three_.push_back({p, a, b, c, static_cast<std::uint32_t>(fate_.size())});
        fate_[dead] = tag_three | static_cast<std::uint32_t>(three_.size() - 1);
        make_live(t);
        make_live(t1);
        make_live(t2);
        legalize(t, 2);
        legalize(t1, 2);
        legalize(t2, 2);
    }

    /// p on the edge opposite corner i of t: t = (a, b, c) with p on b-c, u = (c, b, d).
    void split_edge(TriangleIndex t, int i, VertexIndex p) {
        const TriangleIndex u = mesh_[t].n[static_cast<std::size_t>(i)];
        const int j = mesh_.link_back(u, t);
        const Triangle x = mesh_[t];
        const Triangle y = mesh_[u];
        const VertexIndex a = x.v[static_cast<std::size_t>(i)];
        const VertexIndex b = x.v[static_cast<std::size_t>(detail::next3(i))];
        const VertexIndex c = x.v[static_cast<std::size_t>(detail::prev3(i))];
        const VertexIndex d = y.v[static_cast<std::size_t>(j)];
        const TriangleIndex n_ca = x.n[static_cast<std::size_t>(detail::next3(i))];
        const TriangleIndex n_ab = x.n[static_cast<std::size_t>(detail::prev3(i))];
        const TriangleIndex n_bd = y.n[static_cast<std::size_t>(detail::next3(j))];
        const TriangleIndex n_dc = y.n[static_cast<std::size_t>(detail::prev3(j))];
        const TriangleIndex t2 = new_slot();
        const TriangleIndex u2 = new_slot();
        // t = (a, b, p), t2 = (a, p, c); u = (d, c, p), u2 = (d, p, b).
        mesh_[t].v = {a, b, p};
        mesh_[t].n = {u2, t2, n_ab};
        mesh_[t2].v = {a, p, c};
        mesh_[t2].n = {u, n_ca, t};
        mesh_[u].v = {d, c, p};
        mesh_[u].n = {t2, u2, n_dc};
        mesh_[u2].v = {d, p, b};
        mesh_[u2].n = {t, n_bd, u};
        mesh_.relink(n_ca, t, t2);
        mesh_.relink(n_bd, u, u2);
        const auto first = static_cast<std::uint32_t>(fate_.size());
        // Children of the old t: (a,b,p) right of a->p, then (a,p,c); of u: (d,c,p) right of
        // d->p, then (d,p,b).
        fate_[slot_id_[t]] = tag_two | static_cast<std::uint32_t>(two_.size());
        two_.push_back({a, p, first});
        fate_[slot_id_[u]] = tag_two | static_cast<std::uint32_t>(two_.size());
        two_.push_back({d, p, first + 2});
        make_live(t);
        make_live(t2);
        make_live(u);
        make_live(u2);
        legalize(t, 2);
        legalize(t2, 1);
        legalize(u, 2);
        legalize(u2, 1);
    }

    /// LEGALIZEEDGE: the edge of t opposite its corner at the new point (corner @p i).
    void legalize(TriangleIndex t, int i) {
        stack_.push_back({t, i});
        while (!stack_.empty()) {
            const StackEdge e = stack_.back();
            stack_.pop_back();
            const Triangle& x = mesh_[e.t];
            const TriangleIndex u = x.n[static_cast<std::size_t>(e.i)];
            if (u == no_triangle) continue;  // an edge of the super-triangle
            const VertexIndex d = mesh_[u].v[static_cast<std::size_t>(mesh_.link_back(u, e.t))];
            if (st_.incircle(x.v[0], x.v[1], x.v[2], d) <= 0) continue;
            // Rotate so the new point is corner 0, flip: t = (p, b, d), u = (p, d, c).
            const VertexIndex p = x.v[static_cast<std::size_t>(e.i)];
            const std::uint32_t dead_t = slot_id_[e.t];
            const std::uint32_t dead_u = slot_id_[u];
            (void)mesh_.flip(e.t, e.i);
            ++flips_;
            const auto first = static_cast<std::uint32_t>(fate_.size());
            fate_[dead_t] = fate_[dead_u] = tag_two | static_cast<std::uint32_t>(two_.size());
            two_.push_back({p, d, first});  // (p, b, d) is right of p->d
            make_live(e.t);
            make_live(u);
            stack_.push_back({e.t, 0});
            stack_.push_back({u, 0});
        }
    }

    const std::vector<Point3>& pts_;
    SuperTriangle st_;
    TriMesh mesh_;
    std::vector<std::uint32_t> slot_id_;      ///< per mesh slot, the id of its live triangle
    detail::PagedArray<std::uint32_t> fate_;  ///< per triangle id, live slot or its record
    detail::PagedArray<ThreeWay> three_;
    detail::PagedArray<TwoWay> two_;
    struct StackEdge {
        TriangleIndex t;
        int i;
    };
    std::vector<StackEdge> stack_;
    std::uint64_t flips_ = 0;
    std::uint64_t steps_ = 0;
};

}  // namespace

MethodResult run_randomized_dag(const MethodInput& input,
                                const MethodOptions& options,
                                const Progress& progress) {
    detail::ParamReader params("randomized-dag", options);
    const bool finite =
        params.choice("super-triangle", {"symbolic", "finite"}, "symbolic") == "finite";
    const bool brio = params.choice("order", {"brio", "random"}, "brio") == "brio";
    params.finish();
    detail::CountingPredicates pred;
    detail::PreparedPoints prepared = detail::prepare_points("randomized-dag", input, pred);
    const std::vector<VertexIndex> order =
        brio ? detail::brio_order(prepared.vertices, options.seed)
             : detail::random_order(prepared.vertices.size(), options.seed);
    // Vertex k = the k-th inserted (detail::to_insertion_order): same coordinates, same
    // decisions; the history's records and the mesh then read nearby coordinates.
    detail::to_insertion_order(prepared.vertices, order);
    std::vector<Point3>& pts = prepared.vertices;
    MethodResult result;
    std::size_t peak = 0;
    {
        RandomizedDag dag(pts, pred,
                          finite ? SuperTriangle::Mode::finite : SuperTriangle::Mode::symbolic);
        for (std::size_t k = 0; k < pts.size(); ++k) {
            if ((k & 4095) == 0) {
                progress.report(static_cast<double>(k) / static_cast<double>(pts.size()),
                                "inserting");
            }
            dag.insert(static_cast<VertexIndex>(k));
        }
        result.counters.flips = dag.flips();
        result.counters.walk_steps = dag.steps();
        result.counters.extra["dag_nodes"] = dag.nodes();
        peak = detail::bytes_of(pts) + detail::bytes_of(order);
        std::size_t own = 0;
        result.tin.triangles = dag.take_real_triangles(own);
        peak += own;
    }
    detail::to_input_numbering(result.tin.triangles, pts, order);
    result.tin.vertices = std::move(pts);
    detail::finish_counters(result, pred, prepared.duplicates, peak);
    progress.report(1.0, "triangulated");
    return result;
}

}  // namespace dtm::methods
