// SPDX-License-Identifier: MIT
//
// The serial kernel's recursion tree over ranks (R-D1 of docs/distributed.md).
//
// Level by level, every node that still splits needs the element of rank n / 2 of its points
// under the order of its cut (Before<axis> of kd_order.hpp: (x, y) for x cuts, (y, -x) for y
// cuts; strips of at most strip_size points are cut by x). All nodes of a level are selected
// together, in rounds of two collectives:
//   1. every rank sends a regular sample of each node's candidate window (one allgatherv);
//      every rank sorts the union and takes two pivots around the wanted rank;
//   2. every rank splits its window three ways by the pivots and an integer allreduce of the
//      counts tells, exactly, which part holds the wanted rank; the window shrinks to it.
// Once a window holds at most gather_below candidates, they are gathered and ordered exactly.
// Pivots depend on the spread of the points (and so on the rank count), the median does not.
// Then one alltoallv sends every point to the owner of its leaf.
//
// References: R. W. Floyd, R. L. Rivest, "Expected time bounds for selection", CACM 18(3), 1975
// (sample pivots around the wanted rank); P. Sanders et al., "Sequential and Parallel
// Algorithms and Data Structures", Springer 2019, ch. 5.7 (distributed multiselection by
// sampling and counting).
#include "dtm/dist/partition.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "dist/tree.hpp"
#include "dtm/core/error.hpp"

namespace dtm::dist {
namespace {

bool before(int axis, const Point& a, const Point& b) noexcept {
    if (axis == 0) return a.x < b.x || (a.x == b.x && a.y < b.y);
    return a.y < b.y || (a.y == b.y && a.x > b.x);
}

Leaf to_leaf(const Node& n, std::uint64_t total, int ranks) noexcept {
    Leaf leaf{n.lo, n.hi, n.depth, n.cut, n.frame, 0};
    if (total > 0) {
        // The rank whose equal share of the positions holds the leaf's middle.
        leaf.owner =
            static_cast<int>(((n.lo + n.hi) * static_cast<std::uint64_t>(ranks)) / (2 * total));
        leaf.owner = std::min(leaf.owner, ranks - 1);
    }
    return leaf;
}

void collect_leaves(const Node& n,
                    std::uint32_t depth_limit,
                    std::uint64_t total,
                    int ranks,
                    std::vector<Leaf>& out) {
    if (!splits(n, depth_limit)) {
        out.push_back(to_leaf(n, total, ranks));
        return;
    }
    for (const Node& c : children(n)) collect_leaves(c, depth_limit, total, ranks, out);
}

/// Cancellation agreed by all ranks: true everywhere when any rank's progress asks to stop.
std::int64_t cancel_flag(const Progress& progress) {
    try {
        progress.check();
        return 0;
    } catch (const Cancelled&) {
        return 1;
    }
}

/// Progress without the throw: a stop request is seen by cancel_flag at the next agreement.
void report_quietly(const Progress& progress, double fraction) {
    try {
        progress.report(fraction, "partitioning");
    } catch (const Cancelled&) {
    }
}

void append(Bytes& out, const void* data, std::size_t size) {
    const auto* p = static_cast<const std::byte*>(data);
    out.insert(out.end(), p, p + size);
}

/// Reads the payloads of every source in turn: a count, then that many points.
class Cursor {
public:
    explicit Cursor(const Bytes& bytes) : bytes_(bytes) {}
    std::uint64_t count() {
        std::uint64_t n = 0;
        std::memcpy(&n, bytes_.data() + at_, sizeof n);
        at_ += sizeof n;
        return n;
    }
    void points(std::uint64_t n, std::vector<Point>& out) {
        const std::size_t first = out.size();
        out.resize(first + n);
        if (n > 0) std::memcpy(out.data() + first, bytes_.data() + at_, n * sizeof(Point));
        at_ += n * sizeof(Point);
    }

private:
    const Bytes& bytes_;
    std::size_t at_ = 0;
};

/// The selection of one node's median: the candidate window [wa, wb) of this rank's segment,
/// the wanted rank k among the W candidates of all ranks.
struct Selection {
    std::size_t node = 0;
    int axis = 0;
    std::size_t wa = 0;
    std::size_t wb = 0;
    std::uint64_t k = 0;
    std::uint64_t candidates = 0;
    bool done = false;
    std::size_t split_at = 0;  ///< after done: this rank's points before the median end here
    Point median{};            ///< after done: the first point of the right half
    // This rank's window ends below the current round's pivots.
    std::size_t below_low = 0;
    std::size_t below_high = 0;
};

class Selector {
public:
    Selector(Comm& comm,
             std::vector<Point>& points,
             const PartitionOptions& options,
             const Progress& progress,
             PartitionStats& stats)
        : comm_(comm), pts_(points), options_(options), progress_(progress), stats_(stats) {}

    /// Runs the rounds until every selection is done.
    void run(std::vector<Selection>& sel) {
        const auto ranks = static_cast<std::size_t>(comm_.size());
        for (;;) {
            std::vector<Selection*> open;
            for (auto& s : sel) {
                if (!s.done) open.push_back(&s);
            }
            if (open.empty()) return;
            // 1. Offers to each selection's deciding rank (open selections take turns).
            std::vector<Bytes> offers(ranks);
            for (std::size_t i = 0; i < open.size(); ++i) offer(*open[i], offers[i % ranks]);
            const std::vector<Bytes> received = comm_.alltoallv(std::move(offers));
            // 2. The deciding ranks pick the medians or the pivots and tell every rank.
            std::vector<Cursor> cursors(received.begin(), received.end());
            Bytes decided;
            bool sampled = false;
            for (std::size_t i = 0; i < open.size(); ++i) {
                sampled = sampled || !gathers(*open[i]);
                if (i % ranks != static_cast<std::size_t>(comm_.rank())) continue;
                std::vector<Point> items;
                for (auto& c : cursors) c.points(c.count(), items);
                const Decision d = decide(*open[i], items, i);
                append(decided, &d, sizeof d);
            }
            for (const Decision& d : received_decisions(comm_.allgatherv(std::move(decided)))) {
                Selection& s = *open[d.index];
                if (d.median) {
                    apply_median(s, d.low);
                } else {
                    apply_pivots(s, d);
                }
            }
            // 3. Counts of the sampled selections and the cancel flag in one reduction.
            std::vector<std::int64_t> counts;
            for (Selection* s : open) {
                if (s->done) continue;
                counts.push_back(static_cast<std::int64_t>(s->below_low - s->wa));
                counts.push_back(static_cast<std::int64_t>(s->below_high - s->wa));
            }
            counts.push_back(cancel_flag(progress_));
            comm_.allreduce(counts, Reduce::sum);
            if (counts.back() > 0) throw Cancelled();
            std::size_t at = 0;
            for (Selection* s : open) {
                if (s->done) continue;
                narrow(*s, static_cast<std::uint64_t>(counts[at]),
                       static_cast<std::uint64_t>(counts[at + 1]));
                at += 2;
            }
            if (sampled) ++stats_.sample_rounds;
        }
    }

private:
    /// What a deciding rank tells every rank about open selection `index`: its median, or the
    /// pivots to split the windows by.
    struct Decision {
        std::uint64_t index;
        std::uint32_t median;
        std::uint16_t has_low;
        std::uint16_t has_high;
        Point low;  ///< the median when `median`
        Point high;
    };

    static std::vector<Decision> received_decisions(const std::vector<Bytes>& in) {
        std::vector<Decision> out;
        for (const Bytes& b : in) {
            const auto part = from_bytes<Decision>(b);
            out.insert(out.end(), part.begin(), part.end());
        }
        return out;
    }

    [[nodiscard]] bool gathers(const Selection& s) const noexcept {
        return s.candidates <= options_.gather_below;
    }

    /// This rank's contribution to the round: the whole window, or a regular sample of it.
    void offer(const Selection& s, Bytes& payload) {
        const std::size_t step =
            gathers(s) ? 1
                       : static_cast<std::size_t>(std::max<std::uint64_t>(
                             1, s.candidates / std::max<std::size_t>(options_.sample, 1)));
        const std::uint64_t n = s.wb > s.wa ? (s.wb - s.wa + step - 1) / step : 0;
        append(payload, &n, sizeof n);
        for (std::size_t i = s.wa; i < s.wb; i += step) append(payload, &pts_[i], sizeof(Point));
        if (gathers(s)) stats_.gathered += n;
    }

    /// On the deciding rank: all candidates at hand give the median (the one of rank k); a
    /// sample gives pivots about 2 sqrt(m) sample ranks either side of the wanted rank.
    [[nodiscard]] Decision decide(const Selection& s,
                                  std::vector<Point>& items,
                                  std::size_t index) const {
        const int axis = s.axis;
        const auto less = [axis](const Point& a, const Point& b) { return before(axis, a, b); };
        Decision d{index, 0, 0, 0, {}, {}};
        if (gathers(s)) {
            std::nth_element(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(s.k),
                             items.end(), less);
            d.median = 1;
            d.low = items[s.k];
            return d;
        }
        std::sort(items.begin(), items.end(), less);
        const std::uint64_t m = items.size();
        const std::uint64_t pos = s.k * m / s.candidates;
        const auto delta = static_cast<std::uint64_t>(2.0 * std::sqrt(static_cast<double>(m))) + 1;
        d.has_low = pos > delta ? 1 : 0;
        d.has_high = pos + delta < m ? 1 : 0;
        if (d.has_low) d.low = items[pos - delta];
        if (d.has_high) d.high = items[pos + delta];
        if (!d.has_low && !d.has_high) {  // a tiny sample: one pivot in its middle
            d.has_low = 1;
            d.low = items[m / 2];
        }
        return d;
    }

    /// Every rank: the points of its window before the median go first.
    void apply_median(Selection& s, const Point& median) {
        const int axis = s.axis;
        s.median = median;
        s.split_at = static_cast<std::size_t>(
            std::partition(pts_.begin() + static_cast<std::ptrdiff_t>(s.wa),
                           pts_.begin() + static_cast<std::ptrdiff_t>(s.wb),
                           [&](const Point& p) { return before(axis, p, median); }) -
            pts_.begin());
        s.done = true;
    }

    /// Every rank: its window split three ways by the pivots.
    void apply_pivots(Selection& s, const Decision& d) {
        const int axis = s.axis;
        auto first = pts_.begin() + static_cast<std::ptrdiff_t>(s.wa);
        auto last = pts_.begin() + static_cast<std::ptrdiff_t>(s.wb);
        if (d.has_low) {
            first =
                std::partition(first, last, [&](const Point& p) { return before(axis, p, d.low); });
        }
        s.below_low = static_cast<std::size_t>(first - pts_.begin());
        if (d.has_high) {
            first = std::partition(first, last,
                                   [&](const Point& p) { return before(axis, p, d.high); });
        } else {
            first = last;
        }
        s.below_high = static_cast<std::size_t>(first - pts_.begin());
    }

    /// Keeps the part that holds the wanted rank (global counts below each pivot).
    static void narrow(Selection& s, std::uint64_t below_low, std::uint64_t below_high) {
        if (s.k < below_low) {
            s.wb = s.below_low;
            s.candidates = below_low;
        } else if (s.k < below_high) {
            s.wa = s.below_low;
            s.wb = s.below_high;
            s.k -= below_low;
            s.candidates = below_high - below_low;
        } else {
            s.wa = s.below_high;
            s.k -= below_high;
            s.candidates -= below_high;
        }
    }

    Comm& comm_;
    std::vector<Point>& pts_;
    const PartitionOptions& options_;
    const Progress& progress_;
    PartitionStats& stats_;
};

/// Sends every point to its leaf's owner; returns the owned leaves' points in leaf order.
void shuffle(Comm& comm,
             const std::vector<Point>& pts,
             const std::vector<std::size_t>& seg,
             Share& share) {
    const auto p = static_cast<std::size_t>(comm.size());
    std::vector<Bytes> out(p);
    for (std::size_t i = 0; i < share.leaves.size(); ++i) {
        Bytes& o = out[static_cast<std::size_t>(share.leaves[i].owner)];
        const std::uint64_t n = seg[i + 1] - seg[i];
        append(o, &n, sizeof n);
        if (n > 0) append(o, &pts[seg[i]], n * sizeof(Point));
    }
    const std::vector<Bytes> in = comm.alltoallv(std::move(out));
    const auto me = comm.rank();
    share.first_leaf = share.leaves.size();
    share.last_leaf = share.leaves.size();
    for (std::size_t i = 0; i < share.leaves.size(); ++i) {
        if (share.leaves[i].owner == me && share.first_leaf == share.leaves.size()) {
            share.first_leaf = i;
        }
        if (share.leaves[i].owner > me) {
            share.last_leaf = i;
            break;
        }
    }
    share.first_leaf = std::min(share.first_leaf, share.last_leaf);
    // Two passes over what arrived: the leaves' sizes, then the points straight into place.
    const std::size_t owned = share.last_leaf - share.first_leaf;
    std::vector<std::size_t> size(owned, 0);
    for (const Bytes& bytes : in) {
        std::size_t at = 0;
        for (std::size_t i = 0; i < owned; ++i) {
            std::uint64_t n = 0;
            std::memcpy(&n, bytes.data() + at, sizeof n);
            size[i] += n;
            at += sizeof n + n * sizeof(Point);
        }
    }
    share.offsets.assign(owned + 1, 0);
    for (std::size_t i = 0; i < owned; ++i) share.offsets[i + 1] = share.offsets[i] + size[i];
    share.points.resize(share.offsets[owned]);
    std::vector<std::size_t> fill(share.offsets.begin(), share.offsets.end() - 1);
    for (const Bytes& bytes : in) {
        std::size_t at = 0;
        for (std::size_t i = 0; i < owned; ++i) {
            std::uint64_t n = 0;
            std::memcpy(&n, bytes.data() + at, sizeof n);
            at += sizeof n;
            if (n > 0)
                std::memcpy(share.points.data() + fill[i], bytes.data() + at, n * sizeof(Point));
            fill[i] += n;
            at += n * sizeof(Point);
        }
    }
    share.stats.received_points = share.points.size();
}

/// Sorts every owned leaf by (x, y) and fails on every rank when two points coincide.
void sort_and_check(Comm& comm, Share& share, const Progress& progress) {
    std::int64_t pair[2] = {INT64_MAX, INT64_MAX};
    for (std::size_t i = 0; i + 1 < share.offsets.size(); ++i) {
        auto first = share.points.begin() + static_cast<std::ptrdiff_t>(share.offsets[i]);
        auto last = share.points.begin() + static_cast<std::ptrdiff_t>(share.offsets[i + 1]);
        std::sort(first, last, [](const Point& a, const Point& b) { return before(0, a, b); });
        for (auto it = first; it != last && it + 1 != last; ++it) {
            if (it->x == (it + 1)->x && it->y == (it + 1)->y) {
                const auto a = static_cast<std::int64_t>(std::min(it->id, (it + 1)->id));
                const auto b = static_cast<std::int64_t>(std::max(it->id, (it + 1)->id));
                if (a < pair[0] || (a == pair[0] && b < pair[1])) {
                    pair[0] = a;
                    pair[1] = b;
                }
            }
        }
    }
    // The smallest pair by (a, b): the first members agreed on, then the second for that one.
    std::int64_t first[2] = {pair[0], -cancel_flag(progress)};
    comm.allreduce(first, Reduce::min);
    if (first[1] < 0) throw Cancelled();
    pair[1] = comm.allreduce(pair[0] == first[0] ? pair[1] : INT64_MAX, Reduce::min);
    pair[0] = first[0];
    if (pair[0] != INT64_MAX) {
        throw InputError("points " + std::to_string(pair[0]) + " and " + std::to_string(pair[1]) +
                         " coincide: the distributed partition needs pairwise distinct points");
    }
}

}  // namespace

std::vector<Leaf> tree_leaves(std::uint64_t total, int ranks, unsigned extra_levels) {
    std::vector<Leaf> leaves;
    collect_leaves(Node{0, total, 0, 0, 0}, max_depth(ranks, extra_levels), total, ranks, leaves);
    return leaves;
}

Share partition_points(Comm& comm,
                       std::vector<Point> local,
                       const PartitionOptions& options,
                       const Progress& progress) {
    Share share;
    comm.set_phase("partition");
    share.total = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(local.size()), Reduce::sum));
    const std::uint32_t depth_limit = max_depth(comm.size(), options.extra_levels);

    std::vector<Node> nodes{Node{0, share.total, 0, 0, 0}};
    std::vector<std::size_t> seg{0, local.size()};  // node i is local[seg[i], seg[i + 1])
    Selector selector(comm, local, options, progress, share.stats);
    for (;;) {
        std::vector<Selection> sel;
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            if (!splits(nodes[i], depth_limit)) continue;
            const std::uint64_t n = nodes[i].hi - nodes[i].lo;
            sel.push_back(Selection{i, effective_cut(nodes[i]), seg[i], seg[i + 1], n / 2, n});
        }
        if (sel.empty()) break;
        selector.run(sel);
        for (const Selection& s : sel) {
            const Node& n = nodes[s.node];
            share.cuts.push_back(
                {n.lo, n.hi, static_cast<std::uint8_t>(s.axis), s.median.x, s.median.y});
        }
        std::vector<Node> next;
        std::vector<std::size_t> next_seg{0};
        std::size_t s = 0;
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            if (s < sel.size() && sel[s].node == i) {
                const auto halves = children(nodes[i]);
                next.push_back(halves[0]);
                next_seg.push_back(sel[s].split_at);
                next.push_back(halves[1]);
                ++s;
            } else {
                next.push_back(nodes[i]);
            }
            next_seg.push_back(seg[i + 1]);
        }
        nodes = std::move(next);
        seg = std::move(next_seg);
        ++share.stats.levels;
        report_quietly(progress,
                       0.8 * share.stats.levels / std::max<std::uint32_t>(depth_limit, 1));
    }
    for (const Node& n : nodes) share.leaves.push_back(to_leaf(n, share.total, comm.size()));
    comm.set_phase("shuffle");
    shuffle(comm, local, seg, share);
    std::vector<Point>().swap(local);
    sort_and_check(comm, share, progress);
    report_quietly(progress, 1.0);
    return share;
}

}  // namespace dtm::dist
