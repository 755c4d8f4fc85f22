// SPDX-License-Identifier: MIT
//
// The planar straight-line graph pre-pass: before triangulation, every constraint segment is
// split at its crossings with other segments, at the endpoints of other segments that lie inside
// it (T-junctions, which also cover collinear overlaps), and equal segments become one. Each
// round finds the touching pairs on a uniform grid (segment_grid.hpp, exact predicates), then
// handles them in ascending pair order (i < j, segment indices):
//   - equal: j goes, its ConstraintBits or-ed into the first of its equals;
//   - an endpoint of one strictly inside the other: the other is split there;
//   - a proper crossing: the intersection point, computed as the insertion did before (relative to
//     j's first endpoint, parameters clamped to [0, 1]) and rounded to doubles, becomes a vertex,
//     unless it falls on an existing vertex; both segments are split there.
// A crossing vertex takes the mean of the two lines' heights, or the hard line's when the other is
// soft; between two soft lines it is a soft vertex (height from the surface without soft lines).
// A conflict is recorded when two non-soft heights differ by more than the tolerance. Rounding
// may leave new pieces crossing or touching near a crossing, so the rounds repeat until none touch
// (one round in practice; after max_rounds the insertion takes the rest one by one).
// New vertices are numbered after the merged ones in pair order, so the result is a function of
// the input alone, whatever the tiles, threads or (later) ranks; the insertion that follows only
// gets segments that touch at shared endpoints, all by deterministic reservations.
// References: de Berg et al., Computational Geometry, ch. 2 (segment intersection, the PSLG);
// Shewchuk, "Triangle" (segments split at crossings before CDT insertion).
#include "algo/detail/segment_split.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "algo/detail/segment_grid.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::detail {
namespace {

constexpr int max_rounds = 8;
using Pair = std::pair<std::uint32_t, std::uint32_t>;

/// Every pair i < j of segments that touch (segments_touch), ascending.
std::vector<Pair> touching_pairs(const MergedInput& in) {
    const auto point = [&in](VertexIndex v) -> const Point3& { return in.vertices[v]; };
    const SegmentGrid grid = segment_grid(in.segments, point);
    tbb::enumerable_thread_specific<std::vector<Pair>> found;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, grid.cells(), 1024), [&](const auto& r) {
        std::vector<Pair>& mine = found.local();
        for (std::size_t c = r.begin(); c < r.end(); ++c) {
            for (std::uint32_t i = grid.start[c]; i < grid.start[c + 1]; ++i) {
                for (std::uint32_t j = i + 1; j < grid.start[c + 1]; ++j) {
                    const std::uint32_t a = grid.listed[i];
                    const std::uint32_t b = grid.listed[j];
                    if (segments_touch(point, in.segments[a], in.segments[b])) {
                        mine.emplace_back(std::min(a, b), std::max(a, b));
                    }
                }
            }
        }
    });
    std::vector<Pair> pairs;
    for (const std::vector<Pair>& part : found) pairs.insert(pairs.end(), part.begin(), part.end());
    tbb::parallel_sort(pairs.begin(), pairs.end());  // a pair may share several cells
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

/// The dominant axis of a -> b and its direction: positions along the segment compare by it first.
struct Along {
    bool by_x;
    bool ascending_x;
    bool ascending_y;
    Along(const Point3& a, const Point3& b)
        : by_x(std::abs(b.x - a.x) >= std::abs(b.y - a.y)),
          ascending_x(b.x >= a.x),
          ascending_y(b.y >= a.y) {}
    [[nodiscard]] bool before(const Point3& p, const Point3& q) const {
        const auto x_less = [&] { return ascending_x ? p.x < q.x : p.x > q.x; };
        const auto y_less = [&] { return ascending_y ? p.y < q.y : p.y > q.y; };
        if (by_x) return p.x != q.x ? x_less() : y_less();
        return p.y != q.y ? y_less() : x_less();
    }
};

/// Height of segment a-b at a point q on (or next to) it, linear along its dominant axis.
double height_along(const Point3& a, const Point3& b, const Point3& q) {
    const double t = Along(a, b).by_x ? (q.x - a.x) / (b.x - a.x) : (q.y - a.y) / (b.y - a.y);
    return a.z + std::clamp(t, 0.0, 1.0) * (b.z - a.z);
}

/// A vertex a crossing would add, before duplicates of it are found.
struct Candidate {
    Point3 at;
    bool z_known;
};

/// One round's work: the splits per segment, the crossings and the new vertices.
struct Round {
    std::vector<std::pair<std::uint32_t, VertexIndex>> splits;  ///< (segment, vertex), in order
    std::vector<Candidate> candidates;    ///< split vertices >= first_candidate refer to these
    std::vector<std::uint32_t> equal_to;  ///< per segment: itself, or the first segment equal to it
    VertexIndex first_candidate = 0;
};

void add_crossing(const MergedInput& in,
                  std::uint32_t i,
                  std::uint32_t j,
                  double z_tolerance,
                  Round& round,
                  SegmentSplit& out) {
    const InputSegment& s = in.segments[i];  // the earlier line
    const InputSegment& t = in.segments[j];  // the later line
    const Point3 &pu = in.vertices[t.a], &pw = in.vertices[t.b];
    const Point3 &pp = in.vertices[s.a], &pr = in.vertices[s.b];
    const double wx = pw.x - pu.x, wy = pw.y - pu.y;
    const double px = pp.x - pu.x, py = pp.y - pu.y;
    const double rx = pr.x - pp.x, ry = pr.y - pp.y;
    const double denom = wx * ry - wy * rx;
    double along_t = (px * ry - py * rx) / denom;
    double along_s = (px * wy - py * wx) / denom;
    if (!std::isfinite(along_t) || !std::isfinite(along_s)) {
        // Parallel in floating point, crossing by the exact predicates (a sliver of an angle):
        // where the side distances of each one's ends from the other's line change sign.
        const auto side = [](const Point3& a, const Point3& b, const Point3& q) {
            return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
        };
        const double du = side(pp, pr, pu), dw = side(pp, pr, pw);
        const double dp = side(pu, pw, pp), dr = side(pu, pw, pr);
        along_t = du != dw ? du / (du - dw) : 0.5;
        along_s = dp != dr ? dp / (dp - dr) : 0.5;
    }
    along_t = std::clamp(along_t, 0.0, 1.0);
    along_s = std::clamp(along_s, 0.0, 1.0);
    const Point2 at{pu.x + along_t * wx, pu.y + along_t * wy};
    const double z_later = pu.z + along_t * (pw.z - pu.z);
    const double z_earlier = pp.z + along_s * (pr.z - pp.z);
    const bool soft_earlier = s.bits == constraint_soft;
    const bool soft_later = t.bits == constraint_soft;
    const bool compared = !soft_earlier && !soft_later;
    out.crossings.push_back(
        {at, z_earlier, z_later, compared && std::abs(z_earlier - z_later) > z_tolerance});
    // On an endpoint of either segment: the other is split at that vertex.
    for (const VertexIndex e : {s.a, s.b, t.a, t.b}) {
        if (in.vertices[e].x == at.x && in.vertices[e].y == at.y) {
            round.splits.emplace_back(e == s.a || e == s.b ? j : i, e);
            return;
        }
    }
    const double z = soft_later ? z_earlier : soft_earlier ? z_later : 0.5 * (z_earlier + z_later);
    const auto v = round.first_candidate + static_cast<VertexIndex>(round.candidates.size());
    round.candidates.push_back({{at.x, at.y, z}, !(soft_earlier && soft_later)});
    round.splits.emplace_back(i, v);
    round.splits.emplace_back(j, v);
}

/// The handling of one touching pair (see the file comment).
void handle_pair(
    const MergedInput& in, Pair pair, double z_tolerance, Round& round, SegmentSplit& out) {
    const auto [i, j] = pair;
    const InputSegment& s = in.segments[i];
    const InputSegment& t = in.segments[j];
    bool junction = false;
    const auto inside = [&](const InputSegment& seg, VertexIndex e) {
        return e != seg.a && e != seg.b &&
               geom::orient2d(in.vertices[seg.a], in.vertices[seg.b], in.vertices[e]) == 0 &&
               in_box(in.vertices[seg.a], in.vertices[seg.b], in.vertices[e]);
    };
    for (const VertexIndex e : {t.a, t.b}) {
        if (inside(s, e)) {
            round.splits.emplace_back(i, e);
            junction = true;
        }
    }
    for (const VertexIndex e : {s.a, s.b}) {
        if (inside(t, e)) {
            round.splits.emplace_back(j, e);
            junction = true;
        }
    }
    if (junction || s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b) return;
    add_crossing(in, i, j, z_tolerance, round, out);  // touching, no junction: a proper crossing
}

/// Candidates at one position become one (the first); candidates on an existing vertex become
/// it. Returns, per candidate, the vertex it is.
std::vector<VertexIndex> place_candidates(MergedInput& in, const Round& round) {
    const std::size_t count = round.candidates.size();
    std::vector<std::uint32_t> order(count);
    for (std::uint32_t k = 0; k < count; ++k) order[k] = k;
    const auto xy_less = [&](std::uint32_t a, std::uint32_t b) {
        const Point3 &p = round.candidates[a].at, &q = round.candidates[b].at;
        return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : a < b);
    };
    std::sort(order.begin(), order.end(), xy_less);
    constexpr VertexIndex none = ~VertexIndex{0};
    std::vector<VertexIndex> is(count, none);
    std::vector<std::uint32_t> first_at(count);  // per candidate: the first at its position
    for (std::size_t k = 0; k < count; ++k) {
        const Point3& p = round.candidates[order[k]].at;
        const bool same = k > 0 && round.candidates[order[k - 1]].at.x == p.x &&
                          round.candidates[order[k - 1]].at.y == p.y;
        first_at[order[k]] = same ? first_at[order[k - 1]] : order[k];
    }
    // Existing vertices at a candidate's position (vertices are distinct: one at most each).
    Box2 box;
    for (const Candidate& c : round.candidates) box.add(c.at.x, c.at.y);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, in.vertices.size(), 1 << 14), [&](const auto& r) {
            for (std::size_t v = r.begin(); v < r.end(); ++v) {
                const Point3& p = in.vertices[v];
                if (p.x < box.xmin || p.x > box.xmax || p.y < box.ymin || p.y > box.ymax) {
                    continue;
                }
                const auto it = std::lower_bound(order.begin(), order.end(), p,
                                                 [&](std::uint32_t c, const Point3& q) {
                                                     const Point3& a = round.candidates[c].at;
                                                     return a.x != q.x ? a.x < q.x : a.y < q.y;
                                                 });
                if (it != order.end() && round.candidates[*it].at.x == p.x &&
                    round.candidates[*it].at.y == p.y) {
                    is[first_at[*it]] = static_cast<VertexIndex>(v);
                }
            }
        });
    for (std::uint32_t k = 0; k < count; ++k) {  // in pair order: new vertices numbered so
        if (first_at[k] != k) continue;
        if (is[k] != none) continue;
        is[k] = static_cast<VertexIndex>(in.vertices.size());
        in.vertices.push_back(round.candidates[k].at);
        in.z_known.push_back(round.candidates[k].z_known);
    }
    for (std::uint32_t k = 0; k < count; ++k) is[k] = is[first_at[k]];
    return is;
}

/// Replaces every split segment by its pieces (in order along it) and drops the segments equal to
/// earlier ones.
void apply_splits(MergedInput& in, Round& round) {
    auto& splits = round.splits;
    std::stable_sort(splits.begin(), splits.end(),
                     [](const auto& p, const auto& q) { return p.first < q.first; });
    std::vector<InputSegment> out;
    out.reserve(in.segments.size() + splits.size());
    std::vector<VertexIndex> cuts;
    std::size_t next = 0;  // splits[next..] belong to segments >= i
    for (std::uint32_t i = 0; i < in.segments.size(); ++i) {
        cuts.clear();
        for (; next < splits.size() && splits[next].first == i; ++next) {
            cuts.push_back(splits[next].second);
        }
        if (round.equal_to[i] != i) continue;
        const InputSegment s = in.segments[i];
        if (cuts.empty()) {
            out.push_back(s);
            continue;
        }
        const Along along(in.vertices[s.a], in.vertices[s.b]);
        std::sort(cuts.begin(), cuts.end(), [&](VertexIndex p, VertexIndex q) {
            return along.before(in.vertices[p], in.vertices[q]);
        });
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        VertexIndex from = s.a;
        for (const VertexIndex v : cuts) {
            if (v == from || v == s.b) continue;
            out.push_back({from, v, s.bits});
            from = v;
        }
        out.push_back({from, s.b, s.bits});
    }
    in.segments = std::move(out);
}

}  // namespace

SegmentSplit split_segments(MergedInput& in, double z_tolerance) {
    SegmentSplit out;
    for (int r = 0; r < max_rounds; ++r) {
        const std::vector<Pair> pairs = touching_pairs(in);
        if (pairs.empty()) return out;
        Round round;
        round.first_candidate = static_cast<VertexIndex>(in.vertices.size());
        round.equal_to.resize(in.segments.size());
        for (std::uint32_t i = 0; i < in.segments.size(); ++i) round.equal_to[i] = i;
        // Equal segments first: a pair with a segment equal to an earlier one is that one's.
        for (const auto& [i, j] : pairs) {
            if (same_segment(in.segments[i], in.segments[j])) {
                round.equal_to[j] = std::min(round.equal_to[j], round.equal_to[i]);
            }
        }
        for (std::uint32_t i = 0; i < in.segments.size(); ++i) {
            if (round.equal_to[i] != i) in.segments[round.equal_to[i]].bits |= in.segments[i].bits;
        }
        for (const auto& [i, j] : pairs) {
            if (round.equal_to[i] == i && round.equal_to[j] == j) {
                handle_pair(in, {i, j}, z_tolerance, round, out);
            }
        }
        const std::vector<VertexIndex> placed = place_candidates(in, round);
        for (auto& [seg, v] : round.splits) {
            if (v >= round.first_candidate) v = placed[v - round.first_candidate];
            // A vertex of unknown height (a soft line's) on a non-soft segment takes its height.
            const InputSegment& s = in.segments[seg];
            if (!in.z_known[v] && s.bits != constraint_soft) {
                in.vertices[v].z = height_along(in.vertices[s.a], in.vertices[s.b], in.vertices[v]);
                in.z_known[v] = true;
            }
        }
        apply_splits(in, round);
    }
    out.all_free = touching_pairs(in).empty();
    return out;
}

}  // namespace dtm::detail
