// SPDX-License-Identifier: MIT
/// @file
/// @brief The Delaunay third point of an oriented edge among offered candidates, with one
/// consistent choice on cocircular ties: what the advancing-front methods (delaunay-distance,
/// uniform-grid, dewall) share.
///
/// For the edge a->b the chosen c is left of it and no candidate lies strictly inside the
/// circle through a, b, c: the minimum "Delaunay distance" (lecture 004), the smallest cosine
/// of the angle a-c-b (thesis 000 §3.10.3), decided by incircle alone. Each candidate strictly
/// inside the current circle replaces the best (the circles' parts left of a-b are nested, so
/// no earlier rejection is undone); candidates on it are kept as ties. The circle then holds
/// the Delaunay face on the left of a-b: a, b and the ties. Choosing any tie would let two
/// fronts triangulate one cocircular face in two crossing ways, so the face is always
/// triangulated as a fan from its lexicographically smallest vertex m: c = m if m is not a or
/// b; if m = a, c is the face's vertex after b (every other tie left of b->c); if m = b, the
/// vertex before a (every other tie left of c->a). Each triangle is then the fan triangle of
/// the unique face on that side, whichever front reaches it first.
#pragma once

#include <vector>

#include "dtm/core/tin.hpp"
#include "methods/detail/counting_predicates.hpp"

namespace dtm::methods::detail {

class ThirdPoint {
public:
    ThirdPoint(const std::vector<Point3>& points, CountingPredicates& predicates)
        : p_(points), pred_(predicates) {}

    /// Starts the search for the edge a->b.
    void reset(VertexIndex a, VertexIndex b) {
        a_ = a;
        b_ = b;
        best_ = no_vertex;
        ties_.clear();
    }

    /// Offers candidate c (any point; those not strictly left of a->b are ignored).
    void offer(VertexIndex c) {
        if (c == a_ || c == b_ || pred_.orient(p_[a_], p_[b_], p_[c]) <= 0) return;
        if (best_ == no_vertex) {
            best_ = c;
            return;
        }
        if (c == best_) return;
        const int s = pred_.incircle(p_[a_], p_[b_], p_[best_], p_[c]);
        if (s > 0) {
            best_ = c;
            ties_.clear();
        } else if (s == 0) {
            for (const VertexIndex t : ties_) {
                if (t == c) return;
            }
            ties_.push_back(c);
        }
    }

    [[nodiscard]] bool found() const noexcept { return best_ != no_vertex; }
    /// The best candidate so far (its circle is the current search bound).
    [[nodiscard]] VertexIndex best() const noexcept { return best_; }

    /// The chosen third point (no_vertex when no candidate was left of the edge: a hull
    /// edge), with the cocircular tie rule applied.
    [[nodiscard]] VertexIndex choose() {
        if (best_ == no_vertex || ties_.empty()) return best_;
        VertexIndex m = best_;
        for (const VertexIndex t : ties_) {
            if (smaller(t, m)) m = t;
        }
        if (smaller(a_, m) && smaller(a_, b_)) {
            VertexIndex c = best_;  // the face's vertex after b
            for (const VertexIndex t : ties_) {
                if (pred_.orient(p_[b_], p_[c], p_[t]) < 0) c = t;
            }
            return c;
        }
        if (smaller(b_, m)) {
            VertexIndex c = best_;  // the face's vertex before a
            for (const VertexIndex t : ties_) {
                if (pred_.orient(p_[c], p_[a_], p_[t]) < 0) c = t;
            }
            return c;
        }
        return m;
    }

private:
    [[nodiscard]] bool smaller(VertexIndex u, VertexIndex w) const noexcept {
        return p_[u].x < p_[w].x || (p_[u].x == p_[w].x && p_[u].y < p_[w].y);
    }

    const std::vector<Point3>& p_;
    CountingPredicates& pred_;
    VertexIndex a_ = no_vertex;
    VertexIndex b_ = no_vertex;
    VertexIndex best_ = no_vertex;
    std::vector<VertexIndex> ties_;
};

}  // namespace dtm::methods::detail
