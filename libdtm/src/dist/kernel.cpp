// SPDX-License-Identifier: MIT
//
// The Delaunay kernel over ranks (kernel.hpp).
//
// Every rank owns the positions of its leaves, a contiguous run [lo, hi) of the serial kernel
// order, and the triangle slots [2 lo, 2 hi). A node of the tree whose leaves all belong to one
// rank is built there by the serial kernel's own steps (order_kernel_subtree and
// build_kernel_subtree), merges included. The other nodes ("cross" nodes) are merged level by
// level, deepest first; all merges of one level run at once:
//   1. seeds: each rank sends the rank merging node X = A | B (the owner of A's last leaf) its
//      triangles of A and B that band_seeds selects (every ghost, every circumdisk that may
//      reach across X's cut, tested against X's median), and A's spare slots, with the
//      coordinates of their vertices;
//   2. rings: the merging rank asks the owners for the slots next to its band, `rings` times;
//   3. each merging rank runs ghost_merge on its band (merge_on_band); a merge that touches a
//      slot outside the band asks for that slot and all merges that failed run again, until an
//      integer reduction says none is missing;
//   4. the changed slots go back to their owners with their vertices' coordinates, and the
//      merged hulls to every rank.
// A slot's content is changed only by the merge of the node whose range holds it, on one rank,
// with the serial code on the serial data, so the final slots are the serial ones.
#include "dist/kernel.hpp"

#include <algorithm>
#include <map>

#include "algo/detail/delaunay_dc.hpp"
#include "dist/band_merge.hpp"
#include "dist/drop_pages.hpp"
#include "dist/tree.hpp"
#include "dtm/core/error.hpp"

namespace dtm::dist {
namespace {

/// A slot and its triangle with its vertices' coordinates, for merge `node` of the level.
struct BandEntry {
    std::uint64_t node;
    std::uint64_t slot;
    GlobalTriangle t;
    XY p[3];
};

struct SlotRequest {
    std::uint64_t node;
    std::uint64_t slot;
};

struct HullNote {
    std::uint64_t lo;
    std::uint64_t hi;
    std::uint64_t last_out;
    std::uint64_t first_in;
};

using NodeKey = std::pair<std::uint64_t, std::uint64_t>;

/// Who owns which position (leaves in tree order, contiguous runs per rank).
class Owners {
public:
    explicit Owners(const std::vector<Leaf>& leaves) : leaves_(leaves) {}
    [[nodiscard]] int of_position(std::uint64_t p) const {
        auto it = std::upper_bound(leaves_.begin(), leaves_.end(), p,
                                   [](std::uint64_t v, const Leaf& l) { return v < l.lo; });
        return std::prev(it)->owner;
    }
    [[nodiscard]] int of_slot(std::uint64_t s) const { return of_position(s / 2); }

private:
    const std::vector<Leaf>& leaves_;
};

BandEntry entry_of(const LocalMesh& mesh, std::uint64_t node, std::uint64_t slot) {
    BandEntry e{node, slot, mesh.at(slot), {}};
    for (unsigned i = 0; i < 3; ++i) {
        if (e.t.v[i] != global_ghost) e.p[i] = mesh.point(e.t.v[i]);
    }
    return e;
}

void add_entry(BandMesh& band, const BandEntry& e) {
    band.add(e.slot, e.t);
    for (unsigned i = 0; i < 3; ++i) {
        if (e.t.v[i] != global_ghost) band.add_point(e.t.v[i], e.p[i]);
    }
}

/// One merge across ranks of the current level.
struct CrossMerge {
    Node node;
    Node left;
    Node right;
    int merger = 0;
    int axis = 0;
    double cut = 0.0;
    BandMesh band;  ///< on the merging rank
    bool done = false;
    std::uint64_t missing = 0;
    BandMergeOutcome outcome;
};

class Kernel {
public:
    Kernel(Comm& comm, Share& share, const KernelOptions& options)
        : comm_(comm), share_(share), options_(options), owners_(share.leaves) {}

    DistributedMesh run(const Progress& progress) {
        DistributedMesh out;
        if (share_.total < 2) return out;
        std::vector<std::vector<Node>> cross_by_depth;
        build_local(Node{0, share_.total, 0, 0, 0}, cross_by_depth, out);
        publish_local_hulls();
        for (auto level = cross_by_depth.rbegin(); level != cross_by_depth.rend(); ++level) {
            if (level->empty()) continue;
            check_stop_everywhere(comm_, progress);
            merge_level(*level, out);
            ++out.stats.levels;
        }
        return out;
    }

private:
    /// Builds this rank's maximal local subtrees; lists the cross nodes by depth.
    void build_local(const Node& root,
                     std::vector<std::vector<Node>>& cross,
                     DistributedMesh& out) {
        std::uint64_t lo = 0;
        std::uint64_t hi = 0;
        if (share_.first_leaf < share_.last_leaf) {
            lo = share_.leaves[share_.first_leaf].lo;
            hi = share_.leaves[share_.last_leaf - 1].hi;
        }
        const std::size_t n = hi - lo;
        detail::BigArray<detail::KernelPoint> pts(n);
        for (std::size_t k = 0; k < n; ++k) {
            pts[k] = {{share_.points[k].x, share_.points[k].y}, static_cast<std::uint32_t>(k)};
        }
        for (std::size_t i = share_.first_leaf; i < share_.last_leaf; ++i) {
            const Leaf& leaf = share_.leaves[i];
            detail::order_kernel_subtree(pts, leaf.lo - lo, leaf.hi - lo, leaf.cut);
        }
        // The input numbers in kernel order; then the share's points are no longer needed.
        out.input_ids.resize(n);
        for (std::size_t k = 0; k < n; ++k) out.input_ids[k] = share_.points[pts[k].id].id;
        std::vector<Point>().swap(share_.points);
        detail::GhostMesh local;
        local.tris.assign(2 * n, Triangle{});
        walk(root, lo, pts, local, cross);
        // The kernel's own numbering is the local one: the triangles move as they are.
        LocalMesh& mesh = out.mesh;
        mesh.first_slot = 2 * lo;
        mesh.first_vertex = lo;
        mesh.tris = std::move(local.tris);
        // The points' pages go back as they are copied: the 24-byte kernel points and the
        // 16-byte positions are never both whole beside the triangles (R-M1).
        mesh.own_points.reserve(n);
        constexpr std::size_t chunk = std::size_t{1} << 16;
        for (std::size_t k = 0; k < n; k += chunk) {
            const std::size_t end = std::min(n, k + chunk);
            for (std::size_t j = k; j < end; ++j) mesh.own_points.push_back({pts[j].x, pts[j].y});
            drop_pages(pts.data(), pts.data() + end);  // the pages dropped before cost little
        }
    }

    void walk(const Node& node,
              std::uint64_t lo,
              detail::BigArray<detail::KernelPoint>& pts,
              detail::GhostMesh& local,
              std::vector<std::vector<Node>>& cross) {
        const int first = owners_.of_position(node.lo);
        if (first == owners_.of_position(node.hi - 1)) {
            if (first == comm_.rank()) {
                const detail::KernelSubtree sub = detail::build_kernel_subtree(
                    pts, local, node.lo - lo, node.hi - lo, node.cut, node.frame);
                const std::uint64_t shift = (2 * lo) << 2;
                local_hulls_.push_back(
                    {node.lo, node.hi, sub.hull.last_out + shift, sub.hull.first_in + shift});
            }
            return;
        }
        if (cross.size() <= node.depth) cross.resize(node.depth + 1);
        cross[node.depth].push_back(node);
        for (const Node& child : children(node)) walk(child, lo, pts, local, cross);
    }

    /// Every rank learns the hulls of the subtrees built whole.
    void publish_local_hulls() {
        comm_.set_phase("kernel hulls");
        learn_hulls(local_hulls_);
    }

    void learn_hulls(const std::vector<HullNote>& mine) {
        const auto all =
            concatenated<HullNote>(comm_.allgatherv(to_bytes(std::span<const HullNote>(mine))));
        for (const HullNote& h : all) hulls_[{h.lo, h.hi}] = {h.last_out, h.first_in};
    }

    [[nodiscard]] const Cut& cut_of(const Node& node) const {
        for (const Cut& c : share_.cuts) {
            if (c.lo == node.lo && c.hi == node.hi) return c;
        }
        throw std::logic_error("no cut recorded for a node of the tree");
    }

    void merge_level(const std::vector<Node>& nodes, DistributedMesh& out) {
        const auto ranks = static_cast<std::size_t>(comm_.size());
        const int me = comm_.rank();
        LocalMesh& mesh = out.mesh;
        std::vector<CrossMerge> merges;
        for (const Node& node : nodes) {
            CrossMerge m;
            m.node = node;
            const auto halves = children(node);
            m.left = halves[0];
            m.right = halves[1];
            m.merger = owners_.of_position(m.left.hi - 1);
            m.axis = effective_cut(node);
            const Cut& c = cut_of(node);
            m.cut = m.axis == 0 ? c.x : c.y;
            merges.push_back(std::move(m));
        }

        // 1. Seeds and spare slots to the merging ranks.
        comm_.set_phase("kernel bands");
        std::vector<Bytes> send(ranks);
        for (std::size_t k = 0; k < merges.size(); ++k) {
            const CrossMerge& m = merges[k];
            Bytes& to = send[static_cast<std::size_t>(m.merger)];
            for (const bool left : {true, false}) {
                const Node& side = left ? m.left : m.right;
                for (const std::uint64_t s :
                     band_seeds(mesh, 2 * side.lo, 2 * side.hi, m.axis, m.cut, left)) {
                    append_value(to, entry_of(mesh, k, s));
                }
            }
            for (const std::uint64_t s : {2 * m.left.hi - 2, 2 * m.left.hi - 1}) {
                if (mesh.owns(s)) append_value(to, entry_of(mesh, k, s));
            }
        }
        receive_entries(comm_.alltoallv(std::move(send)), merges, out.stats);

        // 2. Rings around the bands.
        for (unsigned r = 0; r < options_.rings; ++r) {
            std::vector<SlotRequest> wanted;
            for (std::size_t k = 0; k < merges.size(); ++k) {
                if (merges[k].merger != me) continue;
                for (const std::uint64_t s : band_ring(merges[k].band)) wanted.push_back({k, s});
            }
            fetch(wanted, merges, mesh, out.stats);
        }

        // 3. Merges, widened by the slots they lacked until none lacks any.
        for (;;) {
            std::vector<SlotRequest> wanted;
            for (std::size_t k = 0; k < merges.size(); ++k) {
                CrossMerge& m = merges[k];
                if (m.merger != me || m.done) continue;
                try {
                    m.outcome = merge_on_band(m.band, hulls_.at({m.left.lo, m.left.hi}),
                                              hulls_.at({m.right.lo, m.right.hi}),
                                              {2 * m.left.hi - 2, 2 * m.left.hi - 1}, m.node.frame);
                    m.done = true;
                    ++out.stats.merges;
                } catch (const BandTooNarrow& e) {
                    wanted.push_back({k, e.slot});
                }
            }
            if (comm_.allreduce(static_cast<std::int64_t>(wanted.size()), Reduce::sum) == 0) break;
            ++out.stats.widenings;
            fetch(wanted, merges, mesh, out.stats);
        }

        // 4. Changed slots to their owners, merged hulls to everyone.
        comm_.set_phase("kernel results");
        send.assign(ranks, {});
        std::vector<HullNote> merged;
        for (std::size_t k = 0; k < merges.size(); ++k) {
            const CrossMerge& m = merges[k];
            if (m.merger != me) continue;
            for (const auto& [slot, t] : m.outcome.changed) {
                BandEntry e{k, slot, t, {}};
                for (unsigned i = 0; i < 3; ++i) {
                    if (t.v[i] != global_ghost) e.p[i] = m.band.points().at(t.v[i]);
                }
                append_value(send[static_cast<std::size_t>(owners_.of_slot(slot))], e);
            }
            out.stats.changed_triangles += m.outcome.changed.size();
            merged.push_back(
                {m.node.lo, m.node.hi, m.outcome.hull.last_out, m.outcome.hull.first_in});
        }
        for (const BandEntry& e : concatenated<BandEntry>(comm_.alltoallv(std::move(send)))) {
            for (unsigned i = 0; i < 3; ++i) {
                if (e.t.v[i] != global_ghost) mesh.learn_point(e.t.v[i], e.p[i]);
            }
            mesh.set(e.slot, e.t);
        }
        learn_hulls(merged);
    }

    void receive_entries(const std::vector<Bytes>& in,
                         std::vector<CrossMerge>& merges,
                         KernelStats& stats) {
        for (const BandEntry& e : concatenated<BandEntry>(in)) {
            add_entry(merges[e.node].band, e);
            ++stats.band_triangles;
        }
    }

    /// The merging ranks ask the owners for @p wanted slots; the answers join the bands.
    void fetch(const std::vector<SlotRequest>& wanted,
               std::vector<CrossMerge>& merges,
               const LocalMesh& mesh,
               KernelStats& stats) {
        const auto ranks = static_cast<std::size_t>(comm_.size());
        std::vector<Bytes> ask(ranks);
        for (const SlotRequest& w : wanted)
            append_value(ask[static_cast<std::size_t>(owners_.of_slot(w.slot))], w);
        const std::vector<Bytes> asked = comm_.alltoallv(std::move(ask));
        std::vector<Bytes> answer(ranks);
        for (std::size_t s = 0; s < ranks; ++s) {
            for (const SlotRequest& w : from_bytes<SlotRequest>(asked[s])) {
                append_value(answer[s], entry_of(mesh, w.node, w.slot));
            }
        }
        receive_entries(comm_.alltoallv(std::move(answer)), merges, stats);
    }

    Comm& comm_;
    Share& share_;
    const KernelOptions& options_;
    Owners owners_;
    std::vector<HullNote> local_hulls_;
    std::map<NodeKey, GlobalHull> hulls_;
};

}  // namespace

void check_stop_everywhere(Comm& comm, const Progress& progress) {
    std::int64_t stop = 0;
    try {
        progress.check();
    } catch (const Cancelled&) {
        stop = 1;
    }
    if (comm.allreduce(stop, Reduce::max) != 0) throw Cancelled();
}

DistributedMesh triangulate_share(Comm& comm,
                                  Share share,
                                  const KernelOptions& options,
                                  const Progress& progress) {
    return Kernel(comm, share, options).run(progress);
}

}  // namespace dtm::dist
