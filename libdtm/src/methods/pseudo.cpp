// SPDX-License-Identifier: MIT
// [pseudo] Pseudo-triangulation by incremental insertion with the generalized flip.
//
// L. Hobza, "Konstrukce pseudotriangulace inkrementálním vkládáním", bachelor thesis, University
// of West Bohemia, Pilsen 2010 (digest: ../shared/docs/sources/thesis-pseudo-triangulation.md),
// extending J. Trčka, "Pseudo-triangulace a jejich využití v aplikované výpočetní geometrii",
// Charles University, Prague 2007.
//
// Insertion (001 §2): a point inside a pseudo-triangle splits it by the geodesics to two of its
// corners (which two: the criterion); a point on an edge splits the edge and each face at it by
// the geodesic to the corner opposite that side (on a hull edge one face, and the hull grows by a
// vertex); a point outside the hull closes the visible hull chain with two edges into one new
// face (split at hull vertices with a straight angle, which would otherwise stay flat in it).
// The generalized flip (001 §3): the two faces of an edge are merged (getPolygon: with one common
// edge a polygon, with two an interior point remains) and split anew, by the best of all splits
// into two pseudo-triangles (brute force, getDiagonals, O(k^3)) or by the geodesic between the
// corners opposite the edge (fast findDiagonal, iterated tangents; valid on minimal
// pseudo-triangulations; when it fails - the two ends meet, or the diagonal is not a valid split
// - brute force takes over). swap=post flips over the finished structure, swap=incremental after
// each insertion from the edges the insertion touched (recursiveSwap, as Delaunay legalisation).
//
// Termination (the thesis gives none): a flip is taken only when its split is strictly better
// than the current one, and each criterion is a strict improvement of a global measure over the
// finitely many pseudo-triangulations: the exact sum of the computed edge lengths (min-length
// smaller, max-length larger) or the sorted vector of per-face values (lexicographic, as in 000
// §2.3). random chooses splits at random on insertion and never flips. A flip budget guards the
// rest.
#include "pseudo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>

#include "dtm/core/error.hpp"
#include "methods/detail/method_support.hpp"
#include "methods/detail/planar.hpp"
#include "methods/detail/point_set.hpp"
#include "methods/detail/pseudo_split.hpp"

namespace dtm::methods {
namespace {

using detail::Cycle;
using detail::FaceId;
using detail::kOuterFace;
using detail::PseudoCriterion;
using detail::Split;
using Edge = std::pair<VertexIndex, VertexIndex>;

enum class SwapMode : std::uint8_t { none, post, incremental };

struct Counts {
    std::uint64_t inside = 0, on_edge = 0, outside = 0, flips = 0, fast = 0, fallbacks = 0,
                  flip_tests = 0;
    bool budget_hit = false;
};

std::size_t position(const Cycle& c, VertexIndex v) {
    return static_cast<std::size_t>(std::find(c.begin(), c.end(), v) - c.begin());
}

/// The corner of @p c opposite the side that holds position @p at (a vertex or an edge start).
std::size_t opposite_corner(std::span<const Point3> p,
                            const Cycle& c,
                            std::size_t at,
                            detail::CountingPredicates& pred) {
    const std::vector<std::size_t> cs = detail::corners(p, c, pred);
    if (cs.size() != 3) throw std::logic_error("pseudo: a face without three corners");
    const std::size_t k = c.size();
    for (int s = 0; s < 3; ++s) {
        const std::size_t from = cs[s];
        const std::size_t to = cs[(s + 1) % 3];
        // Side from..to (cyclic) holds `at` when walking from `from` reaches it before `to`.
        if ((at + k - from) % k < (to + k - from) % k) return cs[(s + 2) % 3];
    }
    return cs[0];
}

class Builder {
public:
    Builder(std::span<const Point3> points,
            detail::CountingPredicates& pred,
            SwapMode swap,
            bool fast,
            PseudoCriterion criterion,
            std::uint64_t seed)
        : p_(points),
          pred_(pred),
          mesh_(points, pred),
          swap_(swap),
          fast_(fast),
          criterion_(criterion),
          rng_(seed),
          budget_(200 * points.size() + 100000) {}

    void build(const Progress& progress) {
        const auto n = static_cast<VertexIndex>(p_.size());
        VertexIndex c = 2;
        while (pred_.orient(p_[0], p_[1], p_[c]) == 0) ++c;  // not all collinear: checked
        if (pred_.orient(p_[0], p_[1], p_[c]) > 0) {
            mesh_.start(0, 1, c);
        } else {
            mesh_.start(0, c, 1);
        }
        for (VertexIndex v = 2; v < n; ++v) {
            if (v == c) continue;
            if ((v & 1023) == 0) progress.report(0.9 * double(v) / double(n), "pseudo");
            insert(v);
        }
        if (swap_ == SwapMode::post) {
            std::vector<Edge> all;
            for (const Cycle& f : mesh_.faces()) {
                for (std::size_t i = 0; i < f.size(); ++i)
                    all.emplace_back(f[i], f[(i + 1) % f.size()]);
            }
            swap_from(all);
        }
    }

    [[nodiscard]] PolygonFaces faces() const { return mesh_.faces(); }
    [[nodiscard]] const Counts& counts() const { return counts_; }

private:
    const Split& choose(const std::vector<Split>& options) {
        if (criterion_ == PseudoCriterion::random) {
            return options[std::uniform_int_distribution<std::size_t>(0, options.size() - 1)(rng_)];
        }
        std::size_t best = 0;
        for (std::size_t i = 1; i < options.size(); ++i) {
            if (better(options[i], options[best])) best = i;
        }
        return options[best];
    }

    /// @p a beats @p b: strictly better under the criterion, or equal with the smaller border
    /// (so the choice never depends on the order in which the candidates were found).
    bool better(const Split& a, const Split& b) {
        const int c = detail::compare_splits(p_, a, b, criterion_, pred_);
        if (c != 0) return c > 0;
        std::vector<Edge> x = a.border;
        std::vector<Edge> y = b.border;
        std::sort(x.begin(), x.end());
        std::sort(y.begin(), y.end());
        return x < y;
    }

    void insert(VertexIndex v) {
        const detail::Location loc = mesh_.locate(v);
        std::vector<Edge> touched;
        switch (loc.kind) {
            case detail::Location::inside:
                insert_inside(loc.face, v, touched);
                break;
            case detail::Location::on_edge:
                insert_on_edge(loc.a, loc.b, v, touched);
                break;
            case detail::Location::outside:
                insert_outside(loc.a, loc.b, v, touched);
                break;
            case detail::Location::on_vertex:
                throw std::logic_error("pseudo: a repeated point reached the insertion");
        }
        mesh_.mark_inserted(v);
        if (swap_ == SwapMode::incremental) swap_from(touched);
    }

    void insert_inside(FaceId f, VertexIndex v, std::vector<Edge>& touched) {
        ++counts_.inside;
        const Cycle old = mesh_.cycle(f);
        const std::vector<Split> options = detail::point_splits(p_, old, v, pred_);
        if (options.empty()) throw std::logic_error("pseudo: no geodesic split of a face");
        const Split& s = choose(options);
        const FaceId ids[] = {f};
        mesh_.replace(ids, s.faces);
        for (std::size_t i = 0; i < old.size(); ++i)
            touched.emplace_back(old[i], old[(i + 1) % old.size()]);
    }

    /// The split of face cycle @p c (with v on its boundary at position i) by the geodesic from
    /// v to the corner opposite its side.
    Split split_at_boundary_point(const Cycle& c, std::size_t i) {
        const std::size_t corner = opposite_corner(p_, c, i, pred_);
        const std::size_t w = detail::geodesic_tangent(p_, c, corner, p_[c[i]], pred_);
        if (auto s = detail::try_diagonal(p_, c, i, w, pred_)) return *s;
        // Degenerate positions (collinear points): the best valid diagonal from v instead, one
        // leaving no straight angle if there is one.
        std::vector<Split> options;
        for (const bool allow_straight : {false, true}) {
            for (std::size_t j = 0; j < c.size(); ++j) {
                if (auto s = detail::try_diagonal(p_, c, i, j, pred_, allow_straight)) {
                    options.push_back(std::move(*s));
                }
            }
            if (!options.empty()) break;
        }
        if (options.empty()) throw std::logic_error("pseudo: no split at a point on an edge");
        return choose(options);
    }

    void insert_on_edge(VertexIndex a, VertexIndex b, VertexIndex v, std::vector<Edge>& touched) {
        ++counts_.on_edge;
        if (mesh_.left_face(a, b) == kOuterFace) std::swap(a, b);
        const FaceId fa = mesh_.left_face(a, b);
        const FaceId fb = mesh_.left_face(b, a);
        for (const FaceId f : {fa, fb}) {
            if (f == kOuterFace) continue;
            const Cycle old = mesh_.cycle(f);
            for (std::size_t i = 0; i < old.size(); ++i) {
                const Edge e{old[i], old[(i + 1) % old.size()]};
                if (!((e.first == a && e.second == b) || (e.first == b && e.second == a)))
                    touched.push_back(e);
            }
            Cycle c = old;
            const std::size_t at = (f == fa ? position(c, a) : position(c, b)) + 1;
            c.insert(c.begin() + static_cast<std::ptrdiff_t>(at), v);
            const Split s = split_at_boundary_point(c, at);
            const FaceId ids[] = {f};
            mesh_.replace(ids, s.faces);
        }
        if (fb == kOuterFace) {
            mesh_.hull_link(a, v);
            mesh_.hull_link(v, b);
        }
    }

    void insert_outside(VertexIndex a, VertexIndex b, VertexIndex v, std::vector<Edge>& touched) {
        ++counts_.outside;
        const Point3& q = p_[v];
        VertexIndex u = a;
        VertexIndex w = b;
        while (pred_.orient(p_[mesh_.hull_prev(u)], p_[u], q) < 0) u = mesh_.hull_prev(u);
        while (pred_.orient(p_[w], p_[mesh_.hull_next(w)], q) < 0) w = mesh_.hull_next(w);
        std::vector<VertexIndex> chain{u};
        for (VertexIndex x = u; x != w;) {
            x = mesh_.hull_next(x);
            chain.push_back(x);
        }
        for (std::size_t i = 0; i + 1 < chain.size(); ++i)
            touched.emplace_back(chain[i], chain[i + 1]);
        // New faces q, chain reversed; split where a hull vertex of the chain is straight.
        std::size_t end = chain.size() - 1;
        for (std::size_t i = chain.size() - 1; i-- > 0;) {
            const bool straight =
                i > 0 && pred_.orient(p_[chain[i - 1]], p_[chain[i]], p_[chain[i + 1]]) == 0;
            if (i == 0 || straight) {
                Cycle face{v};
                for (std::size_t k = end + 1; k-- > i;) face.push_back(chain[k]);
                mesh_.add_face(std::move(face));
                if (straight) touched.emplace_back(v, chain[i]);
                end = i;
            }
        }
        for (std::size_t i = 1; i + 1 < chain.size(); ++i) mesh_.hull_unlink(chain[i]);
        mesh_.hull_link(u, v);
        mesh_.hull_link(v, w);
    }

    /// The union of the two faces of edge a-b: its boundary cycle, the interior point left when
    /// they share two edges, and the shared edges. False when it is no simple polygon.
    bool merge(FaceId f1, FaceId f2, Cycle& q, VertexIndex& in, std::vector<Edge>& shared) {
        std::map<VertexIndex, VertexIndex> next;
        std::set<Edge> directed;
        for (const FaceId f : {f1, f2}) {
            const Cycle& c = mesh_.cycle(f);
            for (std::size_t i = 0; i < c.size(); ++i)
                directed.emplace(c[i], c[(i + 1) % c.size()]);
        }
        shared.clear();
        for (const auto& [x, y] : directed) {
            if (directed.count({y, x})) {
                if (x < y) shared.emplace_back(x, y);
                continue;
            }
            if (!next.emplace(x, y).second) return false;  // pinched
        }
        if (shared.empty() || shared.size() > 2 || next.empty()) return false;
        q.clear();
        VertexIndex x = next.begin()->first;
        do {
            q.push_back(x);
            x = next[x];
            if (q.size() > next.size()) return false;
        } while (x != q.front());
        if (q.size() != next.size()) return false;
        in = no_vertex;
        if (shared.size() == 2) {
            std::set<VertexIndex> ends{shared[0].first, shared[0].second, shared[1].first,
                                       shared[1].second};
            if (ends.size() != 3) return false;
            for (const VertexIndex e : ends) {
                if (!next.count(e)) in = e;
            }
            if (in == no_vertex) return false;
        }
        return true;
    }

    /// Candidate splits of the merged polygon by findDiagonal (fast) or getDiagonals.
    std::vector<Split> candidates(
        FaceId f1, FaceId f2, const Cycle& q, VertexIndex in, const std::vector<Edge>& shared) {
        if (!fast_) return detail::brute_splits(p_, q, in, pred_);
        if (in != no_vertex) {
            // Two common edges: the merged polygon is a pseudo-triangle with an interior point;
            // its splits are the geodesics from that point to two of its corners.
            if (detail::is_pseudo_triangle(p_, q, pred_)) {
                ++counts_.fast;
                return detail::point_splits(p_, q, in, pred_);
            }
            ++counts_.fallbacks;
            return detail::brute_splits(p_, q, in, pred_);
        }
        // One common edge a-b: the geodesic between the corners c1, c2 opposite it, by tangents
        // from either side in turn until they settle (v3 in f1, v4 in f2).
        const Cycle& c1 = mesh_.cycle(f1);
        const Cycle& c2 = mesh_.cycle(f2);
        const auto [a, b] = shared[0];
        const bool a_first = c1[(position(c1, a) + 1) % c1.size()] == b;
        const std::size_t k1 = opposite_corner(p_, c1, position(c1, a_first ? a : b), pred_);
        const std::size_t k2 = opposite_corner(p_, c2, position(c2, a_first ? b : a), pred_);
        // Two starts: the corners themselves, then (the thesis' "a posteriori" choice) the
        // vertices next to them on the sides that hide the other corner.
        auto beside = [&](const Cycle& c, std::size_t corner, VertexIndex other) {
            const std::size_t k = c.size();
            const Point3& x = p_[other];
            if (pred_.orient(p_[c[corner]], p_[c[(corner + 1) % k]], x) <= 0) {
                return c[(corner + 1) % k];
            }
            if (pred_.orient(p_[c[(corner + k - 1) % k]], p_[c[corner]], x) <= 0) {
                return c[(corner + k - 1) % k];
            }
            return c[corner];
        };
        const std::pair<VertexIndex, VertexIndex> starts[] = {
            {c1[k1], c2[k2]}, {beside(c1, k1, c2[k2]), beside(c2, k2, c1[k1])}};
        for (const auto& [s3, s4] : starts) {
            VertexIndex v3 = s3;
            VertexIndex v4 = s4;
            for (std::size_t round = 0; round < q.size() + 2; ++round) {
                const VertexIndex n3 = c1[detail::geodesic_tangent(p_, c1, k1, p_[v4], pred_)];
                const VertexIndex n4 = c2[detail::geodesic_tangent(p_, c2, k2, p_[n3], pred_)];
                if (n3 == v3 && n4 == v4) break;
                v3 = n3;
                v4 = n4;
            }
            if (v3 == v4) continue;  // the ends met: try the other start
            const std::size_t i = position(q, v3);
            const std::size_t j = position(q, v4);
            if (i == q.size() || j == q.size()) continue;
            if (auto s = detail::try_diagonal(p_, q, std::min(i, j), std::max(i, j), pred_)) {
                ++counts_.fast;
                return {std::move(*s)};
            }
        }
        ++counts_.fallbacks;  // not minimal here: the ends meet or the diagonal is no split
        return detail::brute_splits(p_, q, in, pred_);
    }

    bool flip(VertexIndex a, VertexIndex b, std::vector<Edge>& boundary) {
        const FaceId f1 = mesh_.left_face(a, b);
        const FaceId f2 = mesh_.left_face(b, a);
        if (f1 >= kOuterFace - 1 || f2 >= kOuterFace - 1) return false;  // hull edge or none
        Cycle q;
        VertexIndex in = no_vertex;
        std::vector<Edge> shared;
        if (!merge(f1, f2, q, in, shared)) return false;
        ++counts_.flip_tests;
        Split now;
        now.faces = {mesh_.cycle(f1), mesh_.cycle(f2)};
        now.border = shared;
        const std::vector<Split> options = candidates(f1, f2, q, in, shared);
        const Split* best = nullptr;
        for (const Split& s : options) {
            std::vector<Edge> border = s.border;
            std::sort(border.begin(), border.end());
            if (border == shared) continue;  // the current split
            if (best == nullptr || better(s, *best)) best = &s;
        }
        if (best == nullptr || detail::compare_splits(p_, *best, now, criterion_, pred_) <= 0)
            return false;
        boundary.clear();
        for (std::size_t i = 0; i < q.size(); ++i)
            boundary.emplace_back(q[i], q[(i + 1) % q.size()]);
        const FaceId ids[] = {f1, f2};
        mesh_.replace(ids, best->faces);
        ++counts_.flips;
        return true;
    }

    /// recursiveSwap from each edge, with an explicit stack.
    void swap_from(const std::vector<Edge>& start) {
        if (criterion_ == PseudoCriterion::random) return;
        std::vector<Edge> stack(start.rbegin(), start.rend());
        std::vector<Edge> boundary;
        while (!stack.empty()) {
            const auto [a, b] = stack.back();
            stack.pop_back();
            if (!mesh_.has_edge(a, b)) continue;
            if (counts_.flips >= budget_) {
                counts_.budget_hit = true;
                return;
            }
            if (flip(a, b, boundary)) stack.insert(stack.end(), boundary.rbegin(), boundary.rend());
        }
    }

    std::span<const Point3> p_;
    detail::CountingPredicates& pred_;
    detail::PseudoMesh mesh_;
    SwapMode swap_;
    bool fast_;
    PseudoCriterion criterion_;
    std::mt19937_64 rng_;
    std::uint64_t budget_;
    Counts counts_;
};

std::string histogram_json(const std::vector<std::size_t>& h) {
    std::string s = "[";
    for (std::size_t i = 0; i < h.size(); ++i) s += (i ? ", " : "") + std::to_string(h[i]);
    return s + "]";
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    return buf;
}

}  // namespace

MethodResult run_pseudo(const MethodInput& input,
                        const MethodOptions& options,
                        const Progress& progress) {
    detail::ParamReader params("pseudo", options);
    const std::string swap = params.choice("swap", {"none", "post", "incremental"}, "incremental");
    const std::string flip = params.choice("flip", {"brute", "fast"}, "fast");
    const std::string crit = params.choice(
        "criterion",
        {"random", "min-length", "max-length", "maxmin-angle", "minmax-angle", "maxmin-sum-angle",
         "minmax-sum-angle", "maxmin-angle-hull", "minmax-angle-hull"},
        "min-length");
    params.finish();
    if (!input.segments.empty()) throw UsageError("method pseudo takes no segments");
    detail::CountingPredicates pred;
    detail::PreparedInput prepared = detail::prepare_input(input, "pseudo", pred);
    if (detail::all_collinear(prepared.points, pred)) {
        throw InputError("method pseudo: fewer than 3 distinct points or all points collinear");
    }
    const SwapMode mode = swap == "none"   ? SwapMode::none
                          : swap == "post" ? SwapMode::post
                                           : SwapMode::incremental;
    Builder builder(prepared.points, pred, mode, flip == "fast",
                    *detail::parse_pseudo_criterion(crit), options.seed);
    builder.build(progress);
    MethodResult result;
    result.faces = builder.faces();
    result.tin.vertices = prepared.points;
    const Counts& c = builder.counts();
    const std::size_t n = prepared.points.size();
    std::size_t edge_sides = 0;
    for (const auto& f : result.faces) edge_sides += f.size();
    const std::size_t hull = detail::hull_boundary(prepared.points, pred).size();
    const std::size_t edges = (edge_sides + hull) / 2;
    pred.add_to(result.counters);
    result.counters.flips = c.flips;
    result.counters.extra["duplicates"] = prepared.duplicates;
    result.counters.extra["inserted_inside"] = c.inside;
    result.counters.extra["inserted_on_edge"] = c.on_edge;
    result.counters.extra["inserted_outside"] = c.outside;
    result.counters.extra["flip_tests"] = c.flip_tests;
    result.counters.extra["fast_flips"] = c.fast;
    result.counters.extra["fast_fallbacks"] = c.fallbacks;
    const PseudoAngleStats angles = pseudo_angle_stats(prepared.points, result.faces);
    result.stats_json = "\"faces\": " + std::to_string(result.faces.size()) +
                        ", \"edges\": " + std::to_string(edges) +
                        ", \"pointed\": " + (edges == 2 * n - 3 ? "true" : "false") +
                        ", \"swap\": \"" + swap + "\", \"flip\": \"" + flip +
                        "\", \"criterion\": \"" + crit +
                        "\", \"flip_budget_reached\": " + (c.budget_hit ? "true" : "false") +
                        ", \"mean_min_angle\": " + number(angles.mean_min) +
                        ", \"mean_max_angle\": " + number(angles.mean_max) +
                        ", \"min_angle_histogram\": " + histogram_json(angles.min_histogram) +
                        ", \"max_angle_histogram\": " + histogram_json(angles.max_histogram);
    progress.report(1.0, "pseudo");
    return result;
}

PseudoAngleStats pseudo_angle_stats(std::span<const Point3> points, const PolygonFaces& faces) {
    PseudoAngleStats s;
    s.min_histogram.assign(36, 0);
    s.max_histogram.assign(36, 0);
    detail::CountingPredicates pred;
    constexpr double deg = 180.0 / 3.14159265358979323846;
    for (const auto& f : faces) {
        const detail::FaceAngles a = detail::face_angles(points, f, pred);
        s.min_angle.push_back(a.min * deg);
        s.max_angle.push_back(a.max * deg);
        s.mean_min += a.min * deg;
        s.mean_max += a.max * deg;
        ++s.min_histogram[std::min<std::size_t>(35, static_cast<std::size_t>(a.min * deg / 5.0))];
        ++s.max_histogram[std::min<std::size_t>(35, static_cast<std::size_t>(a.max * deg / 5.0))];
    }
    if (!faces.empty()) {
        s.mean_min /= static_cast<double>(faces.size());
        s.mean_max /= static_cast<double>(faces.size());
    }
    return s;
}

}  // namespace dtm::methods
