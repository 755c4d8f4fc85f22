// SPDX-License-Identifier: MIT
// [greedy-gilbert] The greedy triangulation after P. D. Gilbert, "New results in planar
// triangulations", MSc thesis, University of Illinois, 1979, as described by Preparata and Shamos
// (1985) and the thesis 000 §3.1b.
//
// Every point p_i has its star of rays (HVEZDICE): the directions to all other points sorted
// counter-clockwise, equal directions grouped (the nearer point of a group hides the farther:
// such a candidate passes through a point and is never an edge). The rays cut the turn around
// p_i into sectors, the leaves of p_i's segment tree. An added edge p_k p_l not incident to p_i
// covers, seen from p_i, the run of sectors between the rays to p_k and p_l (the shorter way,
// less than pi); it is stored at the O(log n) canonical nodes of that run, each node keeping only
// the edge nearest to p_i (added edges never cross, so those over a common sector are ordered by
// distance from p_i, the same way in every sector of the run). A candidate p_i p_j crosses an
// added edge iff it crosses the nearest one over the sector starting at its ray: the candidate
// is tested against the edges on the root-to-leaf path of that sector in p_i's tree, O(log n)
// (R18). Accepting an edge updates the n - 2 other trees, O(n log n). Total O(n^2 log n) time
// (sorting the candidates and updating the trees), O(n^2) memory: refused above 5000 points.
#include "greedy_gilbert.hpp"

#include <algorithm>
#include <bit>
#include <map>
#include <memory>
#include <numeric>

#include "dtm/core/error.hpp"
#include "methods/detail/greedy_common.hpp"
#include "methods/detail/planar.hpp"

namespace dtm::methods {

SegmentTreeShape::SegmentTreeShape(std::uint32_t l, std::uint32_t r) {
    // Iterative construction in preorder: node, then its left and right subtrees.
    struct Todo {
        std::uint32_t node, l, r;
    };
    std::vector<Todo> stack{{0, l, r}};
    begin.push_back(l);
    end.push_back(r);
    left.push_back(none);
    right.push_back(none);
    while (!stack.empty()) {
        const Todo t = stack.back();
        stack.pop_back();
        if (t.r - t.l <= 1) continue;
        const std::uint32_t mid = (t.l + t.r) / 2;
        for (int side = 0; side < 2; ++side) {
            const auto child = static_cast<std::uint32_t>(begin.size());
            const std::uint32_t cl = side == 0 ? t.l : mid;
            const std::uint32_t cr = side == 0 ? mid : t.r;
            begin.push_back(cl);
            end.push_back(cr);
            left.push_back(none);
            right.push_back(none);
            (side == 0 ? left : right)[t.node] = child;
            stack.push_back({child, cl, cr});
        }
    }
}

int SegmentTreeShape::depth() const {
    int deepest = 0;
    std::vector<std::pair<std::uint32_t, int>> stack{{0, 0}};
    while (!stack.empty()) {
        const auto [v, d] = stack.back();
        stack.pop_back();
        deepest = std::max(deepest, d);
        if (left[v] != none) stack.emplace_back(left[v], d + 1);
        if (right[v] != none) stack.emplace_back(right[v], d + 1);
    }
    return deepest;
}

namespace {

constexpr std::size_t kMaxPoints = 5000;
constexpr std::uint32_t kNone = SegmentTreeShape::none;

class Gilbert {
public:
    explicit Gilbert(detail::GreedySetup& setup)
        : p_(setup.input.points), pred_(setup.pred), n_(p_.size()) {
        rank_.assign(n_ * n_, 0);
        nearest_.assign(n_ * n_, false);
        sectors_.resize(n_);
        trees_.resize(n_);
        std::vector<VertexIndex> order;
        for (VertexIndex i = 0; i < n_; ++i) {
            order.clear();
            for (VertexIndex j = 0; j < n_; ++j) {
                if (j != i) order.push_back(j);
            }
            std::sort(order.begin(), order.end(), [&](VertexIndex a, VertexIndex b) {
                if (detail::angle_before(pred_, p_[i], p_[a], p_[b])) return true;
                if (detail::angle_before(pred_, p_[i], p_[b], p_[a])) return false;
                return pred_.compare_distances(p_[i], p_[a], p_[i], p_[b]) <
                       0;  // same ray: nearer first
            });
            std::uint32_t group = 0;
            for (std::size_t k = 0; k < order.size(); ++k) {
                const bool same_ray =
                    k > 0 && !detail::angle_before(pred_, p_[i], p_[order[k - 1]], p_[order[k]]);
                if (k > 0 && !same_ray) ++group;
                rank_[i * n_ + order[k]] = group;
                nearest_[i * n_ + order[k]] = !same_ray;
            }
            sectors_[i] = group + 1;
            trees_[i].assign(shape(sectors_[i]).size(), kNone);
        }
    }

    /// The candidate ab contains no other point.
    [[nodiscard]] bool valid(VertexIndex a, VertexIndex b) const {
        return nearest_[a * n_ + b] && nearest_[b * n_ + a];
    }

    /// Walks a's tree to the sector that starts at the ray to b, testing each stored edge.
    [[nodiscard]] bool crosses(VertexIndex a, VertexIndex b) {
        const SegmentTreeShape& t = shape(sectors_[a]);
        const std::uint32_t leaf = rank_[a * n_ + b];
        std::uint32_t v = 0;
        while (v != kNone) {
            const std::uint32_t e = trees_[a][v];
            if (e != kNone && detail::properly_cross(pred_, p_[a], p_[b], p_[edges_[e].first],
                                                     p_[edges_[e].second])) {
                return true;
            }
            if (t.left[v] == kNone) break;
            v = leaf < t.end[t.left[v]] ? t.left[v] : t.right[v];
        }
        return false;
    }

    void add(VertexIndex a, VertexIndex b) {
        const auto id = static_cast<std::uint32_t>(edges_.size());
        edges_.emplace_back(a, b);
        for (VertexIndex i = 0; i < n_; ++i) {
            if (i == a || i == b) continue;
            const int o = pred_.orient(p_[i], p_[a], p_[b]);
            if (o == 0) continue;                    // seen edge-on: covers no sector of p_i
            const VertexIndex from = o > 0 ? a : b;  // the span runs ccw from `from` to `to`
            const VertexIndex to = o > 0 ? b : a;
            const std::uint32_t lo = rank_[i * n_ + from];
            const std::uint32_t hi = rank_[i * n_ + to];
            if (lo < hi) {
                insert(i, 0, lo, hi, id);
            } else {
                insert(i, 0, lo, sectors_[i], id);
                if (hi > 0) insert(i, 0, 0, hi, id);
            }
        }
    }

    [[nodiscard]] std::vector<detail::GreedyEdge> take_edges() { return std::move(edges_); }

private:
    const SegmentTreeShape& shape(std::uint32_t m) {
        auto& s = shapes_[m];
        if (!s) s = std::make_unique<SegmentTreeShape>(0, m);
        return *s;
    }

    /// P&S INSERT(b, e, v): stores the edge at the canonical nodes of the interval [b, e].
    void insert(
        VertexIndex i, std::uint32_t v, std::uint32_t b, std::uint32_t e, std::uint32_t id) {
        const SegmentTreeShape& t = shape(sectors_[i]);
        if (b <= t.begin[v] && t.end[v] <= e) {
            std::uint32_t& slot = trees_[i][v];
            if (slot == kNone || nearer(i, id, slot)) slot = id;
            return;
        }
        const std::uint32_t mid = (t.begin[v] + t.end[v]) / 2;
        if (b < mid) insert(i, t.left[v], b, e, id);
        if (mid < e) insert(i, t.right[v], b, e, id);
    }

    /// Edge e1 lies nearer to p_i than e2 over a run of sectors both cover. Non-crossing segments:
    /// one of them lies entirely (weakly) on one side of the other's line.
    [[nodiscard]] bool nearer(VertexIndex i, std::uint32_t e1, std::uint32_t e2) {
        const Point3& a1 = p_[edges_[e1].first];
        const Point3& b1 = p_[edges_[e1].second];
        const Point3& a2 = p_[edges_[e2].first];
        const Point3& b2 = p_[edges_[e2].second];
        const int si = pred_.orient(a2, b2, p_[i]);
        const int s1 = pred_.orient(a2, b2, a1);
        const int s2 = pred_.orient(a2, b2, b1);
        if (s1 * s2 >= 0 && (s1 != 0 || s2 != 0)) {
            return (s1 != 0 ? s1 : s2) == si;  // e1 on one side of e2's line: i's side is nearer
        }
        // e1 straddles e2's line, so e2 lies on one side of e1's line.
        const int ti = pred_.orient(a1, b1, p_[i]);
        const int t1 = pred_.orient(a1, b1, a2);
        const int t2 = pred_.orient(a1, b1, b2);
        return (t1 != 0 ? t1 : t2) != ti;
    }

    const std::vector<Point3>& p_;
    detail::CountingPredicates& pred_;
    std::size_t n_;
    std::vector<std::uint32_t> rank_;
    std::vector<bool> nearest_;
    std::vector<std::uint32_t> sectors_;
    std::vector<std::vector<std::uint32_t>> trees_;
    std::map<std::uint32_t, std::unique_ptr<SegmentTreeShape>> shapes_;
    std::vector<detail::GreedyEdge> edges_;
};

}  // namespace

MethodResult run_greedy_gilbert(const MethodInput& input,
                                const MethodOptions& options,
                                const Progress& progress) {
    detail::GreedySetup setup = detail::greedy_setup(input, options, "greedy-gilbert");
    const auto& p = setup.input.points;
    const auto n = static_cast<VertexIndex>(p.size());
    if (n > kMaxPoints) {
        throw InputError("method greedy-gilbert: " + std::to_string(n) +
                         " points; its n segment trees of n nodes are capped at 5000 points "
                         "(use greedy)");
    }
    std::vector<detail::GreedyEdge> candidates;
    candidates.reserve(static_cast<std::size_t>(n) * (n - 1) / 2);
    for (VertexIndex a = 0; a < n; ++a) {
        for (VertexIndex b = a + 1; b < n; ++b) candidates.emplace_back(a, b);
    }
    std::sort(candidates.begin(), candidates.end(), detail::GreedyOrder(p, setup.pred));
    progress.report(0.2, "greedy-gilbert");
    Gilbert gilbert(setup);
    std::size_t count = 0;
    for (const auto& s : setup.input.segments) {
        gilbert.add(s.first, s.second);
        ++count;
    }
    std::uint64_t tested = 0;
    for (std::size_t k = 0; k < candidates.size() && count < setup.target_edges; ++k) {
        if ((k & 4095) == 0) progress.report(0.2 + 0.8 * double(k) / double(candidates.size()));
        const auto [a, b] = candidates[k];
        if (std::binary_search(setup.input.segments.begin(), setup.input.segments.end(),
                               candidates[k])) {
            continue;
        }
        ++tested;
        if (!gilbert.valid(a, b) || gilbert.crosses(a, b)) continue;
        gilbert.add(a, b);
        ++count;
    }
    MethodResult result = detail::greedy_result(setup, gilbert.take_edges(), "");
    result.counters.extra["candidates_tested"] = tested;
    result.counters.peak_bytes = static_cast<std::size_t>(n) * n * 9;
    return result;
}

}  // namespace dtm::methods
