// SPDX-License-Identifier: MIT
// [lifting] Delaunay triangulation by lifting to the paraboloid (thesis 000 §2.4.4: map the
// points to one dimension higher, take the convex hull, project back; Brown 1979, Edelsbrunner
// and Seidel 1986 for the paraboloid z = x^2 + y^2).
//
// Idea: the lift of p is (x, y, x^2 + y^2); d lies inside the circle through a, b, c exactly
// when its lift lies below the plane of theirs, so the facets of the convex hull of the lifts
// seen from below project to the Delaunay triangles. The hull is built by randomized
// incremental construction with conflict lists (Clarkson and Shor 1989; de Berg et al.
// ch. 11): a tetrahedron of four lifts, then each point in random order (BRIO rounds); the facets
// it sees (strictly beyond their plane: geom::orient3d_lifted, exact) are replaced by a cone from
// it over their horizon. Every other point keeps one facet it sees; when that facet goes, it finds
// one among the cone's facets (it always sees one: the segment to a point just under its old facet
// enters the new hull through the cone). Every lift is a vertex of the hull (the paraboloid is
// strictly convex), so no point is ever inside. Degeneracies: coplanar lifts (cocircular points)
// are not seen, so faces of several cocircular points come out triangulated somehow (any
// triangulation is Delaunay); if all points lie on one circle, the hull is flat and the polygon is
// fanned from its lowest point. Vertical facets (collinear hull points) project to nothing and are
// left out. Data structure: facets (3 corners counter-clockwise from outside, 3 neighbours, the
// head of their conflict list), per point the next point of its list. Expected O(n log n).
#include "lifting.hpp"

#include <algorithm>
#include <stdexcept>

#include "methods/detail/method_support.hpp"
#include "methods/detail/spatial_order.hpp"
#include "methods/detail/tri_mesh.hpp"

namespace dtm::methods {
namespace {

using detail::CountingPredicates;

constexpr std::uint32_t none = 0xffffffffu;

struct Facet {
    std::array<VertexIndex, 3> v{};    ///< counter-clockwise seen from outside
    std::array<std::uint32_t, 3> n{};  ///< across the edge opposite v[i]
    std::uint32_t conflicts = none;    ///< first point that sees it
    std::uint32_t mark = 0;            ///< visibility stamp of an insertion
    bool alive = false;
};

class LiftedHull {
public:
    LiftedHull(const std::vector<Point3>& p, CountingPredicates& pred)
        : p_(p),
          pred_(pred),
          next_(p.size(), none),
          seen_by_(p.size(), none),
          horizon_at_(p.size(), none) {}

    /// false when all lifts are coplanar (every point on one circle).
    bool build(const std::vector<VertexIndex>& order, const Progress& progress);

    /// The lower facets as Tin triangles, linked (their hull neighbours if lower too).
    [[nodiscard]] std::vector<Triangle> lower_triangles();
    [[nodiscard]] std::size_t bytes() const {
        return detail::bytes_of(f_) + detail::bytes_of(next_) + detail::bytes_of(seen_by_) +
               detail::bytes_of(horizon_at_) + detail::bytes_of(free_);
    }
    std::uint64_t reassigned = 0;
    std::uint64_t created = 0;

private:
    [[nodiscard]] bool sees(VertexIndex q, std::uint32_t f) {
        const auto& v = f_[f].v;
        return pred_.orient3d_lifted(p_[v[0]], p_[v[1]], p_[v[2]], p_[q]) < 0;
    }
    std::uint32_t new_facet(VertexIndex a, VertexIndex b, VertexIndex c) {
        std::uint32_t k;
        if (!free_.empty()) {
            k = free_.back();
            free_.pop_back();
        } else {
            k = static_cast<std::uint32_t>(f_.size());
            f_.emplace_back();
        }
        f_[k] = Facet{};
        f_[k].v = {a, b, c};
        f_[k].alive = true;
        ++created;
        return k;
    }
    void add_conflict(VertexIndex q, std::uint32_t f) {
        seen_by_[q] = f;
        next_[q] = f_[f].conflicts;
        f_[f].conflicts = q;
    }
    void insert(VertexIndex p);

    const std::vector<Point3>& p_;
    CountingPredicates& pred_;
    std::vector<Facet> f_;
    std::vector<std::uint32_t> free_;
    std::vector<std::uint32_t> next_;     ///< per point: next in its facet's conflict list
    std::vector<std::uint32_t> seen_by_;  ///< per point: the facet it is listed with
    std::vector<std::uint32_t>
        horizon_at_;  ///< per vertex: new facet whose horizon edge starts there
    std::uint32_t stamp_ = 0;
    std::vector<std::uint32_t> visible_;
    std::vector<std::uint32_t> cone_;
};

bool LiftedHull::build(const std::vector<VertexIndex>& order, const Progress& progress) {
    // A tetrahedron: three non-collinear points and a fourth off their circle.
    const VertexIndex a = order[0], b = order[1];
    std::size_t kc = 2;
    while (pred_.orient(p_[a], p_[b], p_[order[kc]]) == 0) ++kc;
    const VertexIndex c0 = order[kc];
    std::size_t kd = 2;
    while (kd < order.size() &&
           (kd == kc || pred_.orient3d_lifted(p_[a], p_[b], p_[c0], p_[order[kd]]) == 0)) {
        ++kd;
    }
    if (kd == order.size()) return false;
    const VertexIndex d = order[kd];
    VertexIndex b1 = b, c1 = c0;
    if (pred_.orient3d_lifted(p_[a], p_[b], p_[c0], p_[d]) < 0) std::swap(b1, c1);
    // orient(a, b1, c1, d) > 0: d is inside (a, b1, c1); the other faces as even permutations.
    const std::uint32_t t[4] = {new_facet(a, b1, c1), new_facet(a, d, b1), new_facet(b1, d, c1),
                                new_facet(c1, d, a)};
    for (const std::uint32_t x : t) {
        for (int i = 0; i < 3; ++i) {
            const VertexIndex u = f_[x].v[static_cast<std::size_t>((i + 1) % 3)];
            const VertexIndex w = f_[x].v[static_cast<std::size_t>((i + 2) % 3)];
            for (const std::uint32_t y : t) {
                for (int j = 0; j < 3; ++j) {
                    if (f_[y].v[static_cast<std::size_t>((j + 1) % 3)] == w &&
                        f_[y].v[static_cast<std::size_t>((j + 2) % 3)] == u) {
                        f_[x].n[static_cast<std::size_t>(i)] = y;
                    }
                }
            }
        }
    }
    for (std::size_t k = 2; k < order.size(); ++k) {
        const VertexIndex q = order[k];
        if (k == kc || k == kd) continue;
        std::uint32_t f = none;
        for (const std::uint32_t x : t) {
            if (f == none && sees(q, x)) f = x;
        }
        if (f == none) throw std::logic_error("lifting: a lift inside the tetrahedron");
        add_conflict(q, f);
    }
    for (std::size_t k = 2; k < order.size(); ++k) {
        if ((k & 4095) == 0) {
            progress.report(static_cast<double>(k) / static_cast<double>(order.size()), "hull");
        }
        if (k != kc && k != kd) insert(order[k]);
    }
    return true;
}

void LiftedHull::insert(VertexIndex p) {
    // The facets p sees: a connected cap around the one it is listed with.
    ++stamp_;
    visible_.clear();
    visible_.push_back(seen_by_[p]);
    f_[seen_by_[p]].mark = stamp_;
    for (std::size_t i = 0; i < visible_.size(); ++i) {
        for (const std::uint32_t g : f_[visible_[i]].n) {
            if (f_[g].mark != stamp_ && sees(p, g)) {
                f_[g].mark = stamp_;
                visible_.push_back(g);
            }
        }
    }
    // The cone over the horizon (edges from a seen facet to an unseen one).
    cone_.clear();
    for (const std::uint32_t x : visible_) {
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t g = f_[x].n[static_cast<std::size_t>(i)];
            if (f_[g].mark == stamp_) continue;
            const VertexIndex u = f_[x].v[static_cast<std::size_t>((i + 1) % 3)];
            const VertexIndex w = f_[x].v[static_cast<std::size_t>((i + 2) % 3)];
            const std::uint32_t k = new_facet(u, w, p);
            f_[k].n[2] = g;  // across (u, w)
            for (int j = 0; j < 3; ++j) {
                if (f_[g].n[static_cast<std::size_t>(j)] == x)
                    f_[g].n[static_cast<std::size_t>(j)] = k;
            }
            horizon_at_[u] = k;
            cone_.push_back(k);
        }
    }
    for (const std::uint32_t k : cone_) {
        const VertexIndex u = f_[k].v[0];
        const VertexIndex w = f_[k].v[1];
        f_[k].n[0] = horizon_at_[w];  // across (w, p): the facet of the edge starting at w
        f_[horizon_at_[w]].n[1] = k;  // across (p, u') of that facet, u' = w
        (void)u;
    }
    // The points the seen facets held find a facet of the cone they see.
    for (const std::uint32_t x : visible_) {
        for (std::uint32_t q = f_[x].conflicts; q != none;) {
            const std::uint32_t next = next_[q];
            if (q != p) {
                ++reassigned;
                std::uint32_t found = none;
                for (const std::uint32_t k : cone_) {
                    if (sees(q, k)) {
                        found = k;
                        break;
                    }
                }
                if (found == none) throw std::logic_error("lifting: a point sees no new facet");
                add_conflict(q, found);
            }
            q = next;
        }
        f_[x].alive = false;
        free_.push_back(x);
    }
}

std::vector<Triangle> LiftedHull::lower_triangles() {
    // Lower facets run clockwise seen from above: reversed, they are the triangles.
    std::vector<TriangleIndex> index(f_.size(), no_triangle);
    std::vector<Triangle> out;
    out.reserve(2 * p_.size());
    for (std::uint32_t k = 0; k < f_.size(); ++k) {
        const Facet& x = f_[k];
        if (!x.alive || pred_.orient(p_[x.v[0]], p_[x.v[1]], p_[x.v[2]]) >= 0) continue;
        index[k] = static_cast<TriangleIndex>(out.size());
        Triangle t;
        t.v = {x.v[0], x.v[2], x.v[1]};
        out.push_back(t);
    }
    for (std::uint32_t k = 0; k < f_.size(); ++k) {
        if (index[k] == no_triangle) continue;
        const Facet& x = f_[k];
        // Reversed corners (v0, v2, v1): opposite v0, v2, v1 lie n[0], n[2], n[1].
        out[index[k]].n = {index[x.n[0]], index[x.n[2]], index[x.n[1]]};
    }
    return out;
}

/// All points on one circle: the convex polygon fanned from its lexicographically smallest
/// point (counter-clockwise around it by orientation).
std::vector<detail::TriangleCorners> fan_of_circle(const std::vector<Point3>& p,
                                                   CountingPredicates& pred) {
    std::vector<VertexIndex> s(p.size());
    for (VertexIndex i = 0; i < s.size(); ++i) s[i] = i;
    const auto low = *std::min_element(s.begin(), s.end(), [&](VertexIndex a, VertexIndex b) {
        return p[a].x < p[b].x || (p[a].x == p[b].x && p[a].y < p[b].y);
    });
    std::erase(s, low);
    std::sort(s.begin(), s.end(),
              [&](VertexIndex a, VertexIndex b) { return pred.orient(p[low], p[a], p[b]) > 0; });
    std::vector<detail::TriangleCorners> out;
    for (std::size_t i = 0; i + 1 < s.size(); ++i) out.push_back({low, s[i], s[i + 1]});
    return out;
}

}  // namespace

MethodResult run_lifting(const MethodInput& input,
                         const MethodOptions& options,
                         const Progress& progress) {
    detail::ParamReader params("lifting", options);
    params.finish();
    CountingPredicates pred;
    detail::PreparedPoints prepared = detail::prepare_points("lifting", input, pred);
    // BRIO (Amenta, Choi, Rote 2003): random rounds of doubling size, each in Hilbert order;
    // every round is a random sample, so the expected bounds of the randomized construction
    // hold. The points are renumbered in that order (vertex k = the k-th inserted), so the
    // conflict lists and facets of nearby points lie near each other in memory.
    std::vector<VertexIndex> order = detail::brio_order(prepared.vertices, options.seed);
    detail::to_insertion_order(prepared.vertices, order);
    std::vector<Point3>& p = prepared.vertices;
    MethodResult result;
    std::size_t peak = 0;
    {
        std::vector<VertexIndex> sequence(p.size());
        for (std::size_t k = 0; k < sequence.size(); ++k) sequence[k] = static_cast<VertexIndex>(k);
        LiftedHull hull(p, pred);
        if (hull.build(sequence, progress.sub(0.0, 0.95))) {
            result.counters.extra["reassigned"] = hull.reassigned;
            result.counters.extra["facets_made"] = hull.created;
            const std::size_t building = hull.bytes() + detail::bytes_of(p) +
                                         detail::bytes_of(sequence) + detail::bytes_of(order);
            detail::free_storage(sequence);
            result.tin.triangles = hull.lower_triangles();
            peak = std::max(building, hull.bytes() + detail::bytes_of(p) + detail::bytes_of(order) +
                                          detail::bytes_of(result.tin.triangles));
        } else {
            result.counters.extra["cocircular"] = 1;
            const auto fan = fan_of_circle(p, pred);
            result.tin.triangles = detail::link_triangles(fan, p.size());
            peak = detail::bytes_of(p) + detail::bytes_of(order) + detail::bytes_of(fan) +
                   detail::bytes_of(result.tin.triangles);
        }
    }
    detail::to_input_numbering(result.tin.triangles, p, order);
    result.tin.vertices = std::move(p);
    detail::finish_counters(result, pred, prepared.duplicates, peak);
    progress.report(1.0, "triangulated");
    return result;
}

}  // namespace dtm::methods
