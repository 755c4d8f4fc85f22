// SPDX-License-Identifier: MIT
// [greedy] The greedy triangulation at 10^5 points and more.
//
// The greedy triangulation (thesis 000 §3.1; slides 004) is defined by the loop over all pairs
// in GreedyOrder. It is NOT a subgraph of the Delaunay triangulation, so candidates cannot be
// taken from it; instead this variant runs the very same loop but skips, without testing, pairs
// that the loop would certainly reject, and tests the rest against a bucket grid of the added
// edges. Exactness rests on three facts:
//
// 1. Length phases. The pairs are processed phase by phase: phase k holds the pairs with
//    r_k < length <= r_{k+1} (r_{k+1} = 2 r_k; compared exactly with geom::compare_distances),
//    sorted by GreedyOrder inside the phase. Phases partition the order, so the concatenation
//    is the full greedy order.
// 2. Closed points. A point p is closed when the added edges around it, taken in angular order,
//    bound empty triangles p a b (a b added, no point inside) in every angular gap, except the
//    gap outside the convex hull if p is a hull vertex. Any pair p q then either runs along an
//    added edge (q beyond a passes through a: not an edge) or leaves p inside such a triangle
//    and ends beyond a b: it crosses a b, an added edge, and would be rejected. Edges are never
//    removed, so a closed point stays closed: pairs with a closed end are skipped. Pairs of
//    phase k are generated only among points still open, through a grid of cell r_{k+1}.
// 3. The test itself is the naive one: a pair through a point is dropped; a pair crossing an
//    added edge is dropped (all edges it may meet are found through the grid cells it passes).
// The loop ends at 3n - 3 - h edges. The equality with greedy-naive and greedy-gilbert is
// tested edge for edge (tests/unit/methods/greedy_test.cpp), including grids with many equal
// lengths. Near-linear on uniform points: interior points close within a few phases; what stays
// open is near the hull, where the long greedy edges are (Dickerson, Drysdale, McElfresh and
// Welzl, "Fast greedy triangulation algorithms", Comput. Geom. 8 (1997): almost every edge is
// short or has both ends near the hull).
#include "greedy.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "dtm/core/error.hpp"
#include "methods/detail/greedy_common.hpp"
#include "methods/detail/planar.hpp"
#include "methods/detail/uniform_grid.hpp"

namespace dtm::methods {
namespace {

class FastGreedy {
public:
    FastGreedy(detail::GreedySetup& setup, const Progress& progress)
        : p_(setup.input.points),
          pred_(setup.pred),
          n_(p_.size()),
          target_(setup.target_edges),
          progress_(progress) {
        for (const Point3& q : p_) box_.add(q);
        points_.reset(box_, n_);
        edges_grid_.reset(box_, n_);
        for (VertexIndex i = 0; i < n_; ++i) points_.insert_point(p_[i], i);
        adj_.resize(n_);
        open_.assign(n_, true);
        dirty_.assign(n_, true);
        hull_prev_.assign(n_, no_vertex);
        hull_next_.assign(n_, no_vertex);
        const auto hull = detail::hull_boundary(p_, pred_);
        for (std::size_t k = 0; k < hull.size(); ++k) {
            hull_next_[hull[k]] = hull[(k + 1) % hull.size()];
            hull_prev_[hull[(k + 1) % hull.size()]] = hull[k];
        }
        stamp_.assign(1, 0);
        for (const auto& [a, b] : setup.input.segments) add(a, b);
    }

    std::vector<detail::GreedyEdge> run() {
        double r = first_radius();
        const double diagonal = std::hypot(box_.xmax - box_.xmin, box_.ymax - box_.ymin);
        double lower = 0.0;  // phase: lower < length <= r
        while (edges_.size() < target_) {
            progress_.report(std::min(0.99, double(edges_.size()) / double(target_)), "greedy");
            run_phase(lower, r);
            update_closure();
            ++phases_;
            if (r > 1.001 * diagonal) break;  // every pair has been processed
            lower = r;
            r *= 2.0;
        }
        return std::move(edges_);
    }

    [[nodiscard]] std::uint64_t tested() const noexcept { return tested_; }
    [[nodiscard]] std::uint64_t phases() const noexcept { return phases_; }
    [[nodiscard]] std::uint64_t generated() const noexcept { return generated_; }

private:
    /// The median nearest-neighbour distance (grid search), so that dense clusters start small.
    double first_radius() {
        std::vector<double> nn;
        nn.reserve(n_);
        const double cell = points_.cell_size();
        const auto step = static_cast<VertexIndex>(std::max<std::size_t>(1, n_ / 2000));
        for (VertexIndex i = 0; i < n_; i += step) {
            double best = INFINITY;
            for (int ring = 1; ring <= 4 && !std::isfinite(best); ++ring) {
                const double reach = ring * cell;
                points_.for_box_cells(
                    p_[i].x - reach, p_[i].y - reach, p_[i].x + reach, p_[i].y + reach,
                    [&](std::size_t c) {
                        for (const std::uint32_t j : points_.items(c)) {
                            if (j == i) continue;
                            best = std::min(best, std::hypot(p_[j].x - p_[i].x, p_[j].y - p_[i].y));
                        }
                    });
            }
            if (std::isfinite(best)) nn.push_back(best);
        }
        if (nn.empty()) return cell;
        std::nth_element(nn.begin(), nn.begin() + nn.size() / 2, nn.end());
        return std::max(nn[nn.size() / 2], 1e-300);
    }

    /// The length class of pair (a, b) against the phase radii, exactly: the radii are the
    /// lengths of the axis-parallel pairs (0, 0)-(r, 0).
    [[nodiscard]] bool in_phase(VertexIndex a, VertexIndex b, double lower, double upper) {
        const Point2 o{0.0, 0.0};
        const double dx = p_[b].x - p_[a].x;
        const double dy = p_[b].y - p_[a].y;
        const double d2 = dx * dx + dy * dy;
        // Clear cases by a generous margin, the rest exactly.
        if (d2 > upper * upper * 1.0001) return false;
        if (lower > 0.0 && d2 < lower * lower * 0.9999) return false;
        if (pred_.compare_distances(p_[a], p_[b], o, Point2{upper, 0.0}) > 0) return false;
        return lower == 0.0 || pred_.compare_distances(p_[a], p_[b], o, Point2{lower, 0.0}) > 0;
    }

    void run_phase(double lower, double upper) {
        std::vector<VertexIndex> active;
        for (VertexIndex i = 0; i < n_; ++i) {
            if (open_[i]) active.push_back(i);
        }
        const Box2& box = box_;
        const double span = std::max(box.xmax - box.xmin, box.ymax - box.ymin);
        const double most = std::sqrt(4.0 * static_cast<double>(active.size()) + 1.0);
        const auto per_side = static_cast<std::size_t>(std::clamp(span / upper, 1.0, most));
        detail::UniformGrid grid(box, per_side * per_side);
        for (const VertexIndex i : active) grid.insert_point(p_[i], i);
        std::vector<detail::GreedyEdge> pairs;
        for (const VertexIndex a : active) {
            grid.for_box_cells(p_[a].x - upper, p_[a].y - upper, p_[a].x + upper, p_[a].y + upper,
                               [&](std::size_t c) {
                                   for (const std::uint32_t b : grid.items(c)) {
                                       if (b > a && in_phase(a, b, lower, upper)) {
                                           pairs.emplace_back(a, b);
                                       }
                                   }
                               });
        }
        generated_ += pairs.size();
        std::sort(pairs.begin(), pairs.end(), detail::GreedyOrder(p_, pred_));
        std::size_t k = 0;
        for (const auto& [a, b] : pairs) {
            if (edges_.size() >= target_) return;
            if ((++k & 4095) == 0) progress_.check();
            if (is_edge(a, b)) continue;  // a fixed edge
            ++tested_;
            if (!crosses_edge(a, b) && !through_point(a, b)) add(a, b);
        }
    }

    [[nodiscard]] bool is_edge(VertexIndex a, VertexIndex b) const {
        return std::find(adj_[a].begin(), adj_[a].end(), b) != adj_[a].end();
    }

    [[nodiscard]] bool through_point(VertexIndex a, VertexIndex b) {
        bool hit = false;
        points_.for_segment_cells(p_[a], p_[b], [&](std::size_t c) {
            for (const std::uint32_t k : points_.items(c)) {
                hit = hit || detail::strictly_inside_segment(pred_, p_[a], p_[b], p_[k]);
            }
        });
        return hit;
    }

    [[nodiscard]] bool crosses_edge(VertexIndex a, VertexIndex b) {
        ++round_;
        bool hit = false;
        edges_grid_.for_segment_cells(p_[a], p_[b], [&](std::size_t c) {
            if (hit) return;
            for (const std::uint32_t e : edges_grid_.items(c)) {
                if (stamp_[e] == round_) continue;
                stamp_[e] = round_;
                const auto [u, v] = edges_[e];
                if (detail::properly_cross(pred_, p_[a], p_[b], p_[u], p_[v])) {
                    hit = true;
                    return;
                }
            }
        });
        return hit;
    }

    void add(VertexIndex a, VertexIndex b) {
        const auto id = static_cast<std::uint32_t>(edges_.size());
        edges_.emplace_back(std::min(a, b), std::max(a, b));
        stamp_.push_back(0);
        // Registered without margin: the queries walk with one (uniform_grid.hpp).
        edges_grid_.for_segment_cells(
            p_[a], p_[b],
            [&](std::size_t c) {
                auto& items = edges_grid_.items(c);
                if (items.empty() || items.back() != id) items.push_back(id);
            },
            0);
        adj_[a].push_back(b);
        adj_[b].push_back(a);
        // The gaps at a, at b, and at every common neighbour (edge ab may close its gap) change.
        dirty_[a] = dirty_[b] = true;
        for (const VertexIndex c : adj_[a]) {
            if (is_edge(b, c)) dirty_[c] = true;
        }
    }

    /// No point strictly inside triangle (p, a, b), counter-clockwise.
    [[nodiscard]] bool empty_triangle(VertexIndex p, VertexIndex a, VertexIndex b) {
        const double xmin = std::min({p_[p].x, p_[a].x, p_[b].x});
        const double xmax = std::max({p_[p].x, p_[a].x, p_[b].x});
        const double ymin = std::min({p_[p].y, p_[a].y, p_[b].y});
        const double ymax = std::max({p_[p].y, p_[a].y, p_[b].y});
        bool empty = true;
        points_.for_box_cells(xmin, ymin, xmax, ymax, [&](std::size_t c) {
            for (const std::uint32_t k : points_.items(c)) {
                if (!empty || k == p || k == a || k == b) continue;
                if (pred_.orient(p_[p], p_[a], p_[k]) > 0 &&
                    pred_.orient(p_[a], p_[b], p_[k]) > 0 &&
                    pred_.orient(p_[b], p_[p], p_[k]) > 0) {
                    empty = false;
                }
            }
        });
        return empty;
    }

    [[nodiscard]] bool closed(VertexIndex p) {
        auto& around = adj_[p];
        if (around.size() < 2) return false;
        std::sort(around.begin(), around.end(), [&](VertexIndex a, VertexIndex b) {
            return detail::angle_before(pred_, p_[p], p_[a], p_[b]);
        });
        for (std::size_t k = 0; k < around.size(); ++k) {
            const VertexIndex a = around[k];
            const VertexIndex b = around[(k + 1) % around.size()];
            if (a == hull_prev_[p] && b == hull_next_[p]) continue;  // outside the hull
            if (pred_.orient(p_[p], p_[a], p_[b]) <= 0 || !is_edge(a, b) ||
                !empty_triangle(p, a, b)) {
                return false;
            }
        }
        return true;
    }

    void update_closure() {
        for (VertexIndex i = 0; i < n_; ++i) {
            if (open_[i] && dirty_[i]) {
                dirty_[i] = false;
                open_[i] = !closed(i);
            }
        }
    }

    const std::vector<Point3>& p_;
    detail::CountingPredicates& pred_;
    std::size_t n_;
    std::size_t target_;
    const Progress& progress_;
    Box2 box_;
    detail::UniformGrid points_;
    detail::UniformGrid edges_grid_;
    std::vector<std::vector<VertexIndex>> adj_;
    std::vector<bool> open_;
    std::vector<bool> dirty_;
    std::vector<VertexIndex> hull_prev_, hull_next_;
    std::vector<detail::GreedyEdge> edges_;
    std::vector<std::uint64_t> stamp_;
    std::uint64_t round_ = 0;
    std::uint64_t tested_ = 0;
    std::uint64_t generated_ = 0;
    std::uint64_t phases_ = 0;
};

}  // namespace

MethodResult run_greedy(const MethodInput& input,
                        const MethodOptions& options,
                        const Progress& progress) {
    detail::GreedySetup setup = detail::greedy_setup(input, options, "greedy");
    FastGreedy greedy(setup, progress);
    std::vector<detail::GreedyEdge> edges = greedy.run();
    const std::uint64_t tested = greedy.tested();
    const std::uint64_t phases = greedy.phases();
    const std::uint64_t generated = greedy.generated();
    MethodResult result = detail::greedy_result(setup, std::move(edges), "");
    result.counters.extra["candidates_tested"] = tested;
    result.counters.extra["candidates_generated"] = generated;
    result.counters.extra["phases"] = phases;
    return result;
}

}  // namespace dtm::methods
