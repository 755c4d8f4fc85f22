// SPDX-License-Identifier: MIT
/// @file
/// @brief Topology-oriented divide and conquer after Oishi and Sugihara ([OIS93]; thesis 000
/// §3.7): Guibas-Stolfi's divide and conquer whose merge keeps the combinatorial skeleton
/// valid whatever the numerical answers, templated on the predicates so that tests can feed
/// it corrupted in-circle signs.
///
/// The merge region (between the two halves, above the base edge) is always one polygon whose
/// boundary is the base, the left and right chains: every other face is a triangle. The
/// numbers only choose among topologically allowed actions:
///  - step 3/4 (conditions 2-4): the left (right) neighbour of the base is deleted only when
///    the circle test says so AND the face beyond it is a triangle (it then joins the merge
///    region, which stays one polygon: no edge between two vertices already joined by cross
///    edges, never the edge closing the region) AND its far vertex has another edge (no
///    disconnection; it lies on the region's boundary then, and every boundary vertex between
///    the tangents gets a cross edge, so C3 holds at the end);
///  - step 6 (conditions 5, 6): the cross edge is the one the circle test prefers among the
///    valid candidates (above the base: an orientation test), the other one if it would
///    duplicate an existing edge. Both candidates lie above the base by an exact orientation,
///    so a cross edge never crosses the region's boundary (condition 6) and the thesis' 5/6
///    conflict cannot arise; it is counted (and the merge stopped) should it ever.
/// With exact predicates no guard ever refuses: the result is the Delaunay triangulation.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "methods/detail/edge_algebra.hpp"
#include "methods/detail/free_storage.hpp"

namespace dtm::methods::detail {

struct MergeCounts {
    std::uint64_t deletions = 0;
    std::uint64_t refused_deletions = 0;  ///< circle test said delete, topology said no
    std::uint64_t swapped_choices = 0;    ///< preferred cross edge duplicated an edge
    std::uint64_t conflicts = 0;          ///< both cross edges forbidden (anti-conflict)
    std::uint64_t repaired_faces = 0;     ///< faces closed by the anti-conflict triangulation
};

/// Pred: int orient(VertexIndex, VertexIndex, VertexIndex); int incircle(4 x VertexIndex).
template <class Pred>
class TopologicalDc {
public:
    TopologicalDc(std::vector<VertexIndex> sorted, Pred& pred)
        : order_(std::move(sorted)), pred_(pred) {
        q_.reserve(3 * order_.size() + 8);
    }

    /// Triangulates the points in order_ (sorted lexicographically, distinct, >= 2).
    void run() { (void)build(0, order_.size()); }

    [[nodiscard]] const EdgeAlgebra& edges() const noexcept { return q_; }
    [[nodiscard]] const MergeCounts& counts() const noexcept { return counts_; }
    /// Frees the quad-edges and the working lists (the counts stay).
    void release() {
        free_storage(q_);
        free_storage(order_);
        free_storage(cross_);
        free_storage(hanging_);
        free_storage(scratch_);
    }

private:
    using Hull = std::pair<HalfEdge, HalfEdge>;  ///< ccw out of leftmost, cw out of rightmost

    [[nodiscard]] bool right_of(VertexIndex x, HalfEdge e) {
        return pred_.orient(x, q_.dest(e), q_.org(e)) > 0;
    }
    [[nodiscard]] bool left_of(VertexIndex x, HalfEdge e) {
        return pred_.orient(x, q_.org(e), q_.dest(e)) > 0;
    }

    [[nodiscard]] std::size_t degree(HalfEdge e) const noexcept {
        std::size_t d = 1;
        for (HalfEdge f = q_.onext(e); f != e; f = q_.onext(f)) ++d;
        return d;
    }
    [[nodiscard]] bool adjacent(VertexIndex a, HalfEdge around_b) const noexcept {
        HalfEdge f = around_b;
        do {
            if (q_.dest(f) == a) return true;
            f = q_.onext(f);
        } while (f != around_b);
        return false;
    }
    /// The face left of e is a triangle.
    [[nodiscard]] bool left_triangle(HalfEdge e) const noexcept {
        return q_.lnext(q_.lnext(q_.lnext(e))) == e;
    }

    Hull build(std::size_t lo, std::size_t hi) {
        const std::size_t n = hi - lo;
        if (n == 2) {
            const HalfEdge a = q_.make_edge(order_[lo], order_[lo + 1]);
            return {a, EdgeAlgebra::sym(a)};
        }
        if (n == 3) {
            const VertexIndex s1 = order_[lo], s2 = order_[lo + 1], s3 = order_[lo + 2];
            const HalfEdge a = q_.make_edge(s1, s2);
            const HalfEdge b = q_.make_edge(s2, s3);
            q_.splice(EdgeAlgebra::sym(a), b);
            const int c = pred_.orient(s1, s2, s3);
            if (c > 0) {
                (void)q_.connect(b, a);
                return {a, EdgeAlgebra::sym(b)};
            }
            if (c < 0) {
                const HalfEdge e = q_.connect(b, a);
                return {EdgeAlgebra::sym(e), e};
            }
            return {a, EdgeAlgebra::sym(b)};
        }
        const std::size_t mid = lo + n / 2;
        auto [ldo, ldi] = build(lo, mid);
        auto [rdi, rdo] = build(mid, hi);
        merge(ldo, ldi, rdi, rdo, n);
        return {ldo, rdo};
    }

    /// Step 1: the lower common tangent; steps 2-7: the merge (see the file comment).
    void merge(HalfEdge& ldo, HalfEdge ldi, HalfEdge rdi, HalfEdge& rdo, std::size_t n) {
        const HalfEdge ldi0 = ldi;  // out of the left half's rightmost vertex
        const HalfEdge rdi0 = rdi;  // out of the right half's leftmost vertex
        const VertexIndex leftmost = q_.org(ldo);
        const VertexIndex rightmost = q_.org(rdo);
        const std::uint64_t before = counts_.refused_deletions + counts_.swapped_choices +
                                     counts_.conflicts + counts_.repaired_faces;
        // The walks along the hulls end within a few rounds of them; the caps only matter
        // when wrong circle answers made an earlier merge's hull non-convex.
        std::size_t cap = 4 * n + 8;
        for (; cap > 0; --cap) {
            if (left_of(q_.org(rdi), ldi)) {
                ldi = q_.lnext(ldi);
            } else if (right_of(q_.org(ldi), rdi)) {
                rdi = q_.rprev(rdi);
            } else {
                break;
            }
        }
        // The upper common tangent (condition 1: it differs from the lower one unless all
        // points are collinear): along the hulls' upper sides, the outer face on the right
        // of ul (left hull, counter-clockwise) and on the left of ur (right hull, clockwise).
        HalfEdge ul = q_.onext(ldi0);
        HalfEdge ur = q_.oprev(rdi0);
        for (cap = 4 * n + 8; cap > 0; --cap) {
            if (right_of(q_.org(ur), ul)) {
                ul = q_.rprev(ul);
            } else if (left_of(q_.org(ul), ur)) {
                ur = q_.lnext(ur);
            } else {
                break;
            }
        }
        HalfEdge basel = q_.connect(EdgeAlgebra::sym(rdi), ldi);  // right -> left
        cross_.clear();
        hanging_.clear();
        hull_hit_ = false;
        cross_.push_back(basel);
        if (q_.org(ldi) == q_.org(ldo)) ldo = EdgeAlgebra::sym(basel);
        if (q_.org(rdi) == q_.org(rdo)) rdo = basel;
        const VertexIndex upper_left = q_.org(ul);
        const VertexIndex upper_right = q_.org(ur);
        // A candidate lies above the base (exactly: so no end passes the upper tangent).
        const auto valid_left = [&](HalfEdge e) { return right_of(q_.dest(e), basel); };
        const auto valid_right = [&](HalfEdge e) { return right_of(q_.dest(e), basel); };
        for (;;) {
            HalfEdge lcand = q_.onext(EdgeAlgebra::sym(basel));
            if (valid_left(lcand)) {
                while (pred_.incircle(q_.dest(basel), q_.org(basel), q_.dest(lcand),
                                      q_.dest(q_.onext(lcand))) > 0) {
                    // The region is right of lcand: the face left of it must be a triangle.
                    if (!left_triangle(lcand) || degree(EdgeAlgebra::sym(lcand)) < 2) {
                        ++counts_.refused_deletions;
                        break;
                    }
                    const HalfEdge t = q_.onext(lcand);
                    const HalfEdge far = q_.onext(EdgeAlgebra::sym(lcand));
                    if ((lcand | 1u) == (ldo | 1u) || (lcand | 1u) == (rdo | 1u)) hull_hit_ = true;
                    q_.delete_edge(lcand);
                    ++counts_.deletions;
                    if (q_.onext(far) == far) hanging_.push_back(far);
                    lcand = t;
                }
            }
            HalfEdge rcand = q_.oprev(basel);
            if (valid_right(rcand)) {
                while (pred_.incircle(q_.dest(basel), q_.org(basel), q_.dest(rcand),
                                      q_.dest(q_.oprev(rcand))) > 0) {
                    // The region is left of rcand: the face right of it must be a triangle.
                    if (!left_triangle(EdgeAlgebra::sym(rcand)) ||
                        degree(EdgeAlgebra::sym(rcand)) < 2) {
                        ++counts_.refused_deletions;
                        break;
                    }
                    const HalfEdge t = q_.oprev(rcand);
                    const HalfEdge far = q_.onext(EdgeAlgebra::sym(rcand));
                    if ((rcand | 1u) == (ldo | 1u) || (rcand | 1u) == (rdo | 1u)) hull_hit_ = true;
                    q_.delete_edge(rcand);
                    ++counts_.deletions;
                    if (q_.onext(far) == far) hanging_.push_back(far);
                    rcand = t;
                }
            }
            const bool lv = valid_left(lcand);
            const bool rv = valid_right(rcand);
            if (!lv && !rv) break;
            // Condition 5: a cross edge must not duplicate an edge (the preferred one is
            // checked first, the other only when needed).
            bool take_right = !lv || (rv && pred_.incircle(q_.dest(lcand), q_.org(lcand),
                                                           q_.org(rcand), q_.dest(rcand)) > 0);
            const auto allowed = [&](bool right) {
                return right ? !adjacent(q_.dest(basel), EdgeAlgebra::sym(rcand))
                             : !adjacent(q_.org(basel), EdgeAlgebra::sym(lcand));
            };
            if (!allowed(take_right)) {
                if ((take_right ? lv : rv) && allowed(!take_right)) {
                    take_right = !take_right;
                    ++counts_.swapped_choices;
                } else {
                    ++counts_.conflicts;
                    break;
                }
            }
            basel = take_right ? q_.connect(rcand, EdgeAlgebra::sym(basel))
                               : q_.connect(EdgeAlgebra::sym(basel), EdgeAlgebra::sym(lcand));
            cross_.push_back(basel);
        }
        // The last base should be the upper tangent, with the outer face above it. Wrong
        // circle answers can end the walk below it (a chain vertex skipped): then the tangent
        // is added across the face above the last base, closing the region (condition 6).
        if (q_.org(basel) != upper_right || q_.dest(basel) != upper_left) {
            ++counts_.conflicts;
            basel = close_with_tangent(basel, upper_right, upper_left);
        }
        // Any face at a cross edge that is no triangle (a vertex skipped or hanging) gets the
        // anti-conflict triangulation; above the tangent lies the outer face.
        const HalfEdge outer = EdgeAlgebra::sym(basel);
        // A vertex left with one edge by a deletion (never with exact answers) hangs in a
        // face: joined to the next vertex of the outer face, or fanned in an inner one.
        for (const HalfEdge d : hanging_) {
            if (q_.onext(d) != d) continue;  // it got a cross edge
            if (in_face(d, outer)) {
                const HalfEdge into = EdgeAlgebra::sym(d);    // a -> d
                const HalfEdge from = q_.lnext(q_.lnext(d));  // starts at the vertex after a
                cross_.push_back(q_.connect(into, from));
                ++counts_.repaired_faces;
            } else {
                close_face(d, outer);
            }
        }
        for (const HalfEdge c : cross_) {
            for (const HalfEdge side : {c, EdgeAlgebra::sym(c)}) close_face(side, outer);
        }
        const std::uint64_t after = counts_.refused_deletions + counts_.swapped_choices +
                                    counts_.conflicts + counts_.repaired_faces;
        if (after != before || hull_hit_) {
            // Something was irregular: find the hull edges at the extreme vertices again on
            // the outer face (outer face on their right for ldo, on their left for rdo).
            HalfEdge f = outer;
            std::size_t steps = 0;
            do {
                if (q_.dest(f) == leftmost) ldo = EdgeAlgebra::sym(f);
                if (q_.org(f) == rightmost) rdo = f;
                f = q_.lnext(f);
            } while (f != outer && ++steps <= 2 * order_.size() + 8);
        }
    }

    /// The face left of e is the face left of @p outer.
    [[nodiscard]] bool in_face(HalfEdge e, HalfEdge outer) const noexcept {
        HalfEdge f = e;
        std::size_t steps = 0;
        do {
            if (f == outer) return true;
            f = q_.lnext(f);
        } while (f != e && ++steps <= 2 * order_.size() + 8);
        return false;
    }

    /// The edge right -> left across the face above @p basel (its left side), from the
    /// face's first visit of @p right to its last visit of @p left; returns it.
    HalfEdge close_with_tangent(HalfEdge basel, VertexIndex right, VertexIndex left) {
        std::vector<HalfEdge> cycle;
        const HalfEdge start = EdgeAlgebra::sym(basel);  // left -> right, face on its left
        HalfEdge f = start;
        do {
            cycle.push_back(f);
            f = q_.lnext(f);
        } while (f != start && cycle.size() <= 2 * order_.size() + 8);
        std::size_t into_right = cycle.size();
        for (std::size_t k = 0; k < cycle.size(); ++k) {
            if (q_.dest(cycle[k]) == right) {
                into_right = k;
                break;
            }
        }
        std::size_t out_of_left = cycle.size();
        for (std::size_t k = cycle.size(); k-- > into_right + 1;) {
            if (q_.org(cycle[k]) == left) {
                out_of_left = k;
                break;
            }
        }
        if (into_right == cycle.size() || out_of_left == cycle.size() ||
            adjacent(left, cycle[into_right + 1 < cycle.size() ? into_right + 1 : 0])) {
            return basel;
        }
        const HalfEdge t = q_.connect(cycle[into_right], cycle[out_of_left]);  // right -> left
        cross_.push_back(t);
        return t;
    }

    /// Triangulates the face left of @p e unless it is a triangle or the outer face (the face
    /// left of @p outer), combinatorially: ears are cut off, an ear being two face edges
    /// a -> b -> c with a != c not yet joined (a chord a-c never duplicates an edge).
    void close_face(HalfEdge e, HalfEdge outer) {
        if (left_triangle(e) && e != outer && q_.lnext(e) != outer &&
            q_.lnext(q_.lnext(e)) != outer) {
            return;  // the usual case: no allocation
        }
        std::vector<HalfEdge>& cycle = scratch_;
        for (bool cut = true; cut;) {
            cycle.clear();
            HalfEdge f = e;
            do {
                if (f == outer || cycle.size() > order_.size() * 2) return;
                cycle.push_back(f);
                f = q_.lnext(f);
            } while (f != e);
            if (cycle.size() <= 3) return;
            cut = false;
            const std::size_t m = cycle.size();
            for (std::size_t k = 0; k < m && !cut; ++k) {
                const HalfEdge ab = cycle[k];
                const HalfEdge bc = cycle[(k + 1) % m];
                const VertexIndex a = q_.org(ab);
                if (a == q_.dest(bc) || adjacent(q_.dest(bc), ab)) continue;
                // The chord c -> a closes the triangle (a, b, c); e stays on the rest.
                const HalfEdge chord = q_.connect(bc, ab);
                ++counts_.repaired_faces;
                e = EdgeAlgebra::sym(chord);
                cut = true;
            }
            if (!cut) ++counts_.conflicts;
        }
    }

    std::vector<VertexIndex> order_;
    Pred& pred_;
    EdgeAlgebra q_;
    MergeCounts counts_;
    std::vector<HalfEdge> cross_;    ///< the cross edges of the current merge
    std::vector<HalfEdge> hanging_;  ///< edges out of vertices a deletion left with one edge
    bool hull_hit_ = false;          ///< a deletion took one of the halves' extreme hull edges
    std::vector<HalfEdge> scratch_;
};

}  // namespace dtm::methods::detail
