// SPDX-License-Identifier: MIT
// [enumerate] Exhaustive enumeration of the triangulations of a small point set.
//
// Thesis 000 §2.3 ([HOSCH]): a global optimum is the triangulation whose sorted quality vector
// is lexicographically best; the 6-point example has 10 triangulations. We find them all by a
// recursion over "open" edges: the hull edges start open on their inner side; at each step the
// smallest open directed edge u->v gets its triangle (u, v, w) for every point w left of it such
// that the triangle is empty, its new edges cross no present edge and its present edges are
// still open on the triangle's side. In a triangulation the triangle on that side of u->v is
// unique, so every triangulation is produced exactly once, each as a leaf of the recursion.
// (An empty triangle whose edges cross no present edge cannot overlap a present triangle: an
// overlap would put a vertex of one strictly inside the other or make two edges cross.)
//
// Then every criterion of criteria.hpp picks its optimum by comparing quality vectors
// (R12-R14), plus the minimum-weight triangulation (least total edge length, slides 004).
#include "enumerate.hpp"

#include <algorithm>
#include <bitset>
#include <cstdio>
#include <string>

#include "algo/detail/exact_sum.hpp"
#include "dtm/algo/criteria.hpp"
#include "dtm/core/error.hpp"
#include "methods/detail/counting_predicates.hpp"
#include "methods/detail/method_support.hpp"
#include "methods/detail/planar.hpp"
#include "methods/detail/point_set.hpp"

namespace dtm::methods {
namespace {

constexpr std::size_t kMaxPoints = 12;
constexpr std::size_t kMaxPairs = kMaxPoints * (kMaxPoints - 1) / 2;
using EdgeBits = std::bitset<kMaxPairs>;

class Enumerator {
public:
    Enumerator(const std::vector<Point3>& points,
               detail::CountingPredicates& pred,
               const Progress& progress)
        : p_(points), n_(points.size()), pred_(pred), progress_(progress) {
        pair_.assign(n_ * n_, -1);
        for (std::size_t a = 0; a < n_; ++a) {
            for (std::size_t b = a + 1; b < n_; ++b) {
                pair_[a * n_ + b] = pair_[b * n_ + a] = static_cast<int>(ends_.size());
                ends_.emplace_back(a, b);
            }
        }
        const std::size_t m = ends_.size();
        valid_.assign(m, true);
        crossing_.assign(m, EdgeBits{});
        for (std::size_t e = 0; e < m; ++e) {
            for (std::size_t k = 0; k < n_; ++k) {
                if (detail::strictly_inside_segment(pred_, p_[ends_[e].first], p_[ends_[e].second],
                                                    p_[k])) {
                    valid_[e] = false;
                }
            }
            for (std::size_t f = 0; f < m; ++f) {
                if (f != e && detail::properly_cross(pred_, p_[ends_[e].first], p_[ends_[e].second],
                                                     p_[ends_[f].first], p_[ends_[f].second])) {
                    crossing_[e].set(f);
                }
            }
        }
        open_.assign(n_ * n_, false);
        const std::vector<VertexIndex> hull = detail::hull_boundary(p_, pred_);
        for (std::size_t i = 0; i < hull.size(); ++i) {
            const VertexIndex u = hull[i];
            const VertexIndex v = hull[(i + 1) % hull.size()];
            present_.set(static_cast<std::size_t>(edge(u, v)));
            open_[u * n_ + v] = true;
            ++open_count_;
        }
    }

    std::vector<std::vector<Triangle>> run() {
        recurse();
        return std::move(found_);
    }

private:
    [[nodiscard]] int edge(std::size_t a, std::size_t b) const { return pair_[a * n_ + b]; }

    /// Triangle (u, v, w) counter-clockwise with no point inside or on its boundary.
    [[nodiscard]] bool empty_triangle(std::size_t u, std::size_t v, std::size_t w) {
        for (std::size_t k = 0; k < n_; ++k) {
            if (k == u || k == v || k == w) continue;
            if (pred_.orient(p_[u], p_[v], p_[k]) >= 0 && pred_.orient(p_[v], p_[w], p_[k]) >= 0 &&
                pred_.orient(p_[w], p_[u], p_[k]) >= 0) {
                return false;
            }
        }
        return true;
    }

    /// The side v->w of the new triangle: usable if new and crossing nothing, or present and open.
    [[nodiscard]] bool side_usable(std::size_t v, std::size_t w) const {
        const auto e = static_cast<std::size_t>(edge(v, w));
        if (present_.test(e)) return open_[v * n_ + w];
        return valid_[e] && (crossing_[e] & present_).none();
    }

    struct Undo {
        std::size_t from, to;
        bool added;  // the edge was new (else it was present and open)
    };

    void use_side(std::size_t v, std::size_t w, std::vector<Undo>& undo) {
        const auto e = static_cast<std::size_t>(edge(v, w));
        if (present_.test(e)) {
            open_[v * n_ + w] = false;
            --open_count_;
            undo.push_back({v, w, false});
        } else {
            present_.set(e);
            open_[w * n_ + v] = true;  // the other side still needs its triangle
            ++open_count_;
            undo.push_back({v, w, true});
        }
    }

    void revert(const std::vector<Undo>& undo) {
        for (auto it = undo.rbegin(); it != undo.rend(); ++it) {
            if (it->added) {
                present_.reset(static_cast<std::size_t>(edge(it->from, it->to)));
                open_[it->to * n_ + it->from] = false;
                --open_count_;
            } else {
                open_[it->from * n_ + it->to] = true;
                ++open_count_;
            }
        }
    }

    void recurse() {
        if ((++nodes_ & 1023) == 0) progress_.check();
        if (open_count_ == 0) {
            found_.push_back(triangles_);
            return;
        }
        std::size_t u = 0;
        std::size_t v = 0;
        for (std::size_t k = 0; k < n_ * n_; ++k) {
            if (open_[k]) {
                u = k / n_;
                v = k % n_;
                break;
            }
        }
        for (std::size_t w = 0; w < n_; ++w) {
            if (w == u || w == v || pred_.orient(p_[u], p_[v], p_[w]) <= 0) continue;
            if (!empty_triangle(u, v, w) || !side_usable(v, w) || !side_usable(w, u)) continue;
            // The two new sides must not cross each other's edges either: they share w only.
            std::vector<Undo> undo;
            open_[u * n_ + v] = false;
            --open_count_;
            use_side(v, w, undo);
            use_side(w, u, undo);
            Triangle t;
            t.v = {static_cast<VertexIndex>(u), static_cast<VertexIndex>(v),
                   static_cast<VertexIndex>(w)};
            triangles_.push_back(t);
            recurse();
            triangles_.pop_back();
            revert(undo);
            open_[u * n_ + v] = true;
            ++open_count_;
        }
    }

    const std::vector<Point3>& p_;
    std::size_t n_;
    detail::CountingPredicates& pred_;
    const Progress& progress_;
    std::vector<int> pair_;
    std::vector<std::pair<std::size_t, std::size_t>> ends_;
    std::vector<bool> valid_;
    std::vector<EdgeBits> crossing_;
    EdgeBits present_;
    std::vector<bool> open_;
    std::size_t open_count_ = 0;
    std::vector<Triangle> triangles_;
    std::vector<std::vector<Triangle>> found_;
    std::uint64_t nodes_ = 0;
};

double total_length(const Tin& tin, std::vector<double>& lengths) {
    lengths = quality_vector(tin, Criterion::shortest_diagonal);
    return summarize_quality(lengths).sum;
}

std::string json_double(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6f", v);
    return buf;
}

std::string triangles_json(const Tin& tin) {
    std::string s = "[";
    for (std::size_t i = 0; i < tin.triangles.size(); ++i) {
        const auto& v = tin.triangles[i].v;
        s += (i ? ", [" : "[") + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " +
             std::to_string(v[2]) + "]";
    }
    return s + "]";
}

std::string optimum_json(const std::vector<Tin>& all,
                         std::size_t best,
                         std::size_t ties,
                         const std::vector<double>& vector) {
    std::string s = "{\"index\": " + std::to_string(best + 1) +
                    ", \"ties\": " + std::to_string(ties) + ", \"vector\": [";
    for (std::size_t i = 0; i < vector.size(); ++i) s += (i ? ", " : "") + json_double(vector[i]);
    return s + "], \"triangles\": " + triangles_json(all[best]) + "}";
}

}  // namespace

MethodResult run_enumerate(const MethodInput& input,
                           const MethodOptions& options,
                           const Progress& progress) {
    detail::ParamReader("enumerate", options).finish();
    if (!input.segments.empty()) throw UsageError("method enumerate takes no segments");
    detail::CountingPredicates pred;
    detail::PreparedInput prepared = detail::prepare_input(input, "enumerate", pred);
    const std::vector<Point3>& points = prepared.points;
    if (points.size() > kMaxPoints) {
        throw InputError("method enumerate: " + std::to_string(points.size()) +
                         " distinct points; it enumerates at most 12");
    }
    if (detail::all_collinear(points, pred)) {
        throw InputError("method enumerate: fewer than 3 points or all points collinear");
    }
    MethodResult result;
    result.counters.extra["duplicates"] = prepared.duplicates;
    for (const std::vector<Triangle>& found : Enumerator(points, pred, progress).run()) {
        std::vector<detail::TriangleCorners> corners;
        for (const Triangle& t : found) corners.push_back(t.v);
        result.all.push_back(detail::tin_from_triangles(points, corners));
    }
    std::string json =
        "\"triangulations\": " + std::to_string(result.all.size()) + ", \"optima\": {";
    bool first = true;
    for (const Criterion c : all_criteria()) {
        if (c == Criterion::delaunay) continue;
        std::size_t best = 0;
        std::size_t ties = 1;
        std::vector<double> best_vector = quality_vector(result.all[0], c);
        for (std::size_t i = 1; i < result.all.size(); ++i) {
            std::vector<double> v = quality_vector(result.all[i], c);
            const int cmp = compare_quality(v, best_vector, c);
            if (cmp > 0) {
                best = i;
                ties = 1;
                best_vector = std::move(v);
            } else if (cmp == 0) {
                ++ties;
            }
        }
        json += std::string(first ? "" : ", ") + "\"" + std::string(criterion_name(c)) +
                "\": " + optimum_json(result.all, best, ties, best_vector);
        first = false;
    }
    // Minimum weight: least total edge length (exact sum of the computed lengths).
    std::vector<double> lengths;
    std::vector<double> best_lengths;
    (void)total_length(result.all[0], best_lengths);
    std::size_t lightest = 0;
    std::size_t light_ties = 1;
    for (std::size_t i = 1; i < result.all.size(); ++i) {
        (void)total_length(result.all[i], lengths);
        const int cmp = -dtm::detail::exact_sum_difference_sign(lengths, best_lengths);
        if (cmp > 0) {
            lightest = i;
            light_ties = 1;
            best_lengths = lengths;
        } else if (cmp == 0) {
            ++light_ties;
        }
    }
    json += ", \"min-weight\": {\"index\": " + std::to_string(lightest + 1) +
            ", \"ties\": " + std::to_string(light_ties) +
            ", \"total_length\": " + json_double(summarize_quality(best_lengths).sum) +
            ", \"triangles\": " + triangles_json(result.all[lightest]) + "}}";
    // The Delaunay triangulations: locally max-min-angle optimal (several when cocircular).
    json += ", \"delaunay\": [";
    first = true;
    for (std::size_t i = 0; i < result.all.size(); ++i) {
        if (count_improvable_edges(result.all[i], Criterion::maxmin_angle) == 0) {
            json += (first ? "" : ", ") + std::to_string(i + 1);
            first = false;
        }
    }
    json += "]";
    result.stats_json = std::move(json);
    result.tin = result.all[0];
    pred.add_to(result.counters);
    return result;
}

}  // namespace dtm::methods
