// SPDX-License-Identifier: MIT
//
// The domain as a distributed fixpoint (R-B3). Serially (algo/detail/tin_build_domain.cpp) a
// 0-1 breadth-first search from the hull gives every triangle the least number of boundary or
// hole edges to cross from the outside; odd depths are kept. Least depths are the unique
// fixpoint of d(t) = min(seed(t), min over neighbours n of d(n) + w(t, n)), whatever the order
// of relaxations: each rank relaxes its own triangles with a bucket queue, sends the labels that
// cross to other ranks' triangles, and the rounds stop when an allreduce counts no improvement.
#include "dist/domain.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "algo/detail/ghost_mesh.hpp"
#include "dist/mesh_vertices.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::dist {
namespace {

constexpr std::uint8_t ring_bits = detail::constraint_boundary | detail::constraint_hole;
constexpr std::uint32_t unreached = 0xffffffffu;

struct Label {
    std::uint64_t slot;
    std::uint32_t depth;
    std::uint32_t pad = 0;
};

/// Which rank holds a slot: ranks hold ascending contiguous ranges.
class SlotOwners {
public:
    SlotOwners(Comm& comm, const LocalMesh& mesh) {
        const std::uint64_t end = mesh.first_slot + mesh.tris.size();
        std::uint64_t running = 0;
        for (const std::uint64_t e : concatenated<std::uint64_t>(
                 comm.allgatherv(to_bytes(std::span<const std::uint64_t>(&end, 1))))) {
            running = std::max(running, e);
            ends_.push_back(running);
        }
    }
    [[nodiscard]] std::size_t of(std::uint64_t slot) const {
        return static_cast<std::size_t>(std::upper_bound(ends_.begin(), ends_.end(), slot) -
                                        ends_.begin());
    }

private:
    std::vector<std::uint64_t> ends_;
};

/// Removes, from @p stack outwards, every triangle @p removable accepts, going on across the
/// edges @p spreads allows: to own neighbours at once, to other ranks' ones by notices (the
/// neighbour's slot and the removed slot, which @p told hears of), until no rank sends any.
/// Returns the triangles removed here.
template <class Removable, class Spreads, class Told>
std::int64_t remove_spreading(Comm& comm,
                              LocalMesh& mesh,
                              const std::vector<std::uint64_t>& ghosts,
                              const SlotOwners& owners,
                              std::vector<std::uint64_t> stack,
                              const Removable& removable,
                              const Spreads& spreads,
                              const Told& told,
                              const Progress& progress) {
    std::int64_t removed = 0;
    for (;;) {
        std::vector<Bytes> out(static_cast<std::size_t>(comm.size()));
        while (!stack.empty()) {
            const std::uint64_t s = stack.back();
            stack.pop_back();
            if (!removable(s)) continue;
            mesh.removed[s] = 1;
            ++removed;
            const GlobalTriangle g = mesh.at(mesh.first_slot + s);
            for (unsigned i = 0; i < 3; ++i) {
                const std::uint64_t twin = g.n[i] >> 2;
                if (!spreads(s, i) || std::binary_search(ghosts.begin(), ghosts.end(), twin)) {
                    continue;
                }
                if (mesh.owns(twin)) {
                    stack.push_back(twin - mesh.first_slot);
                } else {
                    append_value(out[owners.of(twin)], Label{twin, 0});
                    append_value(out[owners.of(twin)], Label{mesh.first_slot + s, 0});
                }
            }
        }
        const auto notices = concatenated<Label>(comm.alltoallv(std::move(out)));
        for (std::size_t k = 0; k + 1 < notices.size(); k += 2) {  // (my slot, removed neighbour)
            told(notices[k + 1].slot);
            stack.push_back(notices[k].slot - mesh.first_slot);
        }
        check_stop_everywhere(comm, progress);
        if (comm.allreduce(static_cast<std::int64_t>(notices.size()), Reduce::sum) == 0) break;
    }
    return removed;
}

}  // namespace

DomainStats apply_distributed_domain(Comm& comm,
                                     DistributedMesh& distributed,
                                     bool has_boundary,
                                     const Progress& progress) {
    LocalMesh& mesh = distributed.mesh;
    DomainStats stats;
    std::int64_t rings = 0;
    for (const auto& b : mesh.bits) rings |= ((b[0] | b[1] | b[2]) & ring_bits) != 0 ? 1 : 0;
    if (!has_boundary && comm.allreduce(rings, Reduce::max) == 0) return stats;
    comm.set_phase("domain");
    const auto ghosts = all_ghost_slots(comm, mesh);
    const SlotOwners owners(comm, mesh);
    const std::size_t n = mesh.tris.size();
    std::vector<std::uint32_t> depth(n, unreached);
    std::vector<std::vector<std::uint32_t>> buckets;
    const auto push = [&](std::uint64_t s, std::uint32_t d) {
        if (d >= depth[s]) return false;
        depth[s] = d;
        if (buckets.size() <= d) buckets.resize(d + 1);
        buckets[d].push_back(static_cast<std::uint32_t>(s));
        return true;
    };
    const auto weight = [&](std::uint64_t s, unsigned i) -> std::uint32_t {
        return !mesh.bits.empty() && (mesh.bits[s][i] & ring_bits) != 0 ? 1 : 0;
    };
    const std::uint32_t outside = has_boundary ? 0 : 1;
    for (std::uint64_t s = 0; s < n; ++s) {
        if (detail::is_ghost_triangle(mesh.tris[s])) continue;
        const GlobalTriangle g = mesh.at(mesh.first_slot + s);
        for (unsigned i = 0; i < 3; ++i) {
            if (std::binary_search(ghosts.begin(), ghosts.end(), g.n[i] >> 2))
                push(s, outside + weight(s, i));
        }
    }
    for (;;) {
        ++stats.rounds;
        std::vector<Bytes> out(static_cast<std::size_t>(comm.size()));
        for (std::uint32_t d = 0; d < buckets.size(); ++d) {
            for (std::size_t k = 0; k < buckets[d].size(); ++k) {  // the bucket may grow
                const std::uint32_t s = buckets[d][k];
                if (depth[s] != d) continue;
                const GlobalTriangle g = mesh.at(mesh.first_slot + s);
                for (unsigned i = 0; i < 3; ++i) {
                    const std::uint64_t twin = g.n[i] >> 2;
                    if (std::binary_search(ghosts.begin(), ghosts.end(), twin)) continue;
                    const std::uint32_t next = d + weight(s, i);
                    if (mesh.owns(twin)) {
                        push(twin - mesh.first_slot, next);
                    } else {
                        append_value(out[owners.of(twin)], Label{twin, next});
                    }
                }
            }
            buckets[d].clear();
        }
        std::int64_t improved = 0;
        for (const Label& l : concatenated<Label>(comm.alltoallv(std::move(out)))) {
            improved += push(l.slot - mesh.first_slot, l.depth) ? 1 : 0;
        }
        check_stop_everywhere(comm, progress);
        if (comm.allreduce(improved, Reduce::sum) == 0) break;
    }
    mesh.removed.assign(n, 0);
    std::int64_t removed = 0;
    for (std::uint64_t s = 0; s < n; ++s) {
        if (detail::is_ghost_triangle(mesh.tris[s]) || depth[s] % 2 == 1) continue;
        mesh.removed[s] = 1;
        ++removed;
    }
    stats.removed = static_cast<std::uint64_t>(comm.allreduce(removed, Reduce::sum));
    return stats;
}

std::unordered_set<std::uint64_t> foreign_removed(Comm& comm, const LocalMesh& mesh) {
    const SlotOwners owners(comm, mesh);
    std::vector<Bytes> out(static_cast<std::size_t>(comm.size()));
    for (std::uint64_t s = 0; s < mesh.removed.size(); ++s) {
        if (mesh.removed[s] == 0) continue;
        const GlobalTriangle g = mesh.at(mesh.first_slot + s);
        for (const std::uint64_t h : g.n) {
            if (h != global_ghost && !mesh.owns(h >> 2)) {
                append_value(out[owners.of(h >> 2)], mesh.first_slot + s);
            }
        }
    }
    std::unordered_set<std::uint64_t> set;
    for (const std::uint64_t s : concatenated<std::uint64_t>(comm.alltoallv(std::move(out)))) {
        set.insert(s);
    }
    return set;
}

std::uint64_t remove_hole_seeds(Comm& comm,
                                DistributedMesh& distributed,
                                const std::vector<Point2>& seeds,
                                const Progress& progress) {
    LocalMesh& mesh = distributed.mesh;
    if (seeds.empty()) return 0;
    comm.set_phase("domain");
    const std::size_t n = mesh.tris.size();
    if (mesh.removed.empty()) mesh.removed.assign(n, 0);
    const auto ghosts = all_ghost_slots(comm, mesh);
    const SlotOwners owners(comm, mesh);
    const auto slots =
        static_cast<std::uint64_t>(comm.allreduce(static_cast<std::int64_t>(n), Reduce::sum));
    const std::uint64_t real = slots - ghosts.size();
    // Per seed, the smallest serial index of an own triangle holding it.
    constexpr auto nowhere = std::numeric_limits<std::int64_t>::max();
    std::vector<std::int64_t> first(seeds.size(), nowhere);
    std::vector<std::uint64_t> mine(seeds.size(), 0);
    for (std::uint64_t s = 0; s < n; ++s) {
        if (detail::is_ghost_triangle(mesh.tris[s])) continue;
        const GlobalTriangle g = mesh.at(mesh.first_slot + s);
        const XY a = mesh.point(g.v[0]), b = mesh.point(g.v[1]), c = mesh.point(g.v[2]);
        const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
        const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
        for (std::size_t k = 0; k < seeds.size(); ++k) {
            const Point2 p = seeds[k];
            if (p.x < x0 || p.x > x1 || p.y < y0 || p.y > y1) continue;
            if (geom::orient2d(a.x, a.y, b.x, b.y, p.x, p.y) < 0 ||
                geom::orient2d(b.x, b.y, c.x, c.y, p.x, p.y) < 0 ||
                geom::orient2d(c.x, c.y, a.x, a.y, p.x, p.y) < 0) {
                continue;
            }
            const auto face =
                static_cast<std::int64_t>(serial_face(mesh.first_slot + s, ghosts, real));
            if (face < first[k]) {
                first[k] = face;
                mine[k] = s;
            }
        }
    }
    std::vector<std::int64_t> least = first;
    comm.allreduce(least, Reduce::min);
    std::vector<std::uint64_t> stack;
    for (std::size_t k = 0; k < seeds.size(); ++k) {
        if (first[k] != nowhere && first[k] == least[k] && mesh.removed[mine[k]] == 0) {
            stack.push_back(mine[k]);
        }
    }
    const std::int64_t removed = remove_spreading(
        comm, mesh, ghosts, owners, std::move(stack), [&](std::uint64_t t) { return mesh.kept(t); },
        [&](std::uint64_t t, unsigned i) { return mesh.bits.empty() || mesh.bits[t][i] == 0; },
        [](std::uint64_t) {}, progress);
    return static_cast<std::uint64_t>(comm.allreduce(removed, Reduce::sum));
}

std::uint64_t trim_distributed_long_edges(Comm& comm,
                                          DistributedMesh& distributed,
                                          double max_edge,
                                          const Progress& progress) {
    LocalMesh& mesh = distributed.mesh;
    comm.set_phase("domain");
    const std::size_t n = mesh.tris.size();
    if (mesh.removed.empty()) mesh.removed.assign(n, 0);
    const auto ghosts = all_ghost_slots(comm, mesh);
    const SlotOwners owners(comm, mesh);
    std::unordered_set<std::uint64_t> gone = foreign_removed(comm, mesh);
    const auto outside = [&](std::uint64_t slot) {
        if (std::binary_search(ghosts.begin(), ghosts.end(), slot)) return true;
        return mesh.owns(slot) ? mesh.removed[slot - mesh.first_slot] != 0 : gone.contains(slot);
    };
    const double limit2 = max_edge * max_edge;
    const auto removable = [&](std::uint64_t s) {
        const GlobalTriangle g = mesh.at(mesh.first_slot + s);
        for (unsigned i = 0; i < 3; ++i) {
            if (!outside(g.n[i] >> 2) || (!mesh.bits.empty() && mesh.bits[s][i] != 0)) continue;
            const XY a = mesh.point(g.v[i]);
            const XY b = mesh.point(g.v[(i + 1) % 3]);
            const double dx = a.x - b.x;
            const double dy = a.y - b.y;
            if (dx * dx + dy * dy > limit2) return true;
        }
        return false;
    };
    std::vector<std::uint64_t> stack;
    for (std::uint64_t s = 0; s < n; ++s) {
        if (!mesh.kept(s)) continue;
        const GlobalTriangle g = mesh.at(mesh.first_slot + s);
        if (outside(g.n[0] >> 2) || outside(g.n[1] >> 2) || outside(g.n[2] >> 2))
            stack.push_back(s);
    }
    const std::int64_t removed = remove_spreading(
        comm, mesh, ghosts, owners, std::move(stack),
        [&](std::uint64_t t) { return mesh.kept(t) && removable(t); },
        [](std::uint64_t, unsigned) { return true; },
        [&](std::uint64_t from) { gone.insert(from); }, progress);
    return static_cast<std::uint64_t>(comm.allreduce(removed, Reduce::sum));
}

FaceNumbers kept_face_numbers(Comm& comm,
                              const LocalMesh& mesh,
                              const std::vector<std::uint64_t>& ghosts) {
    const SlotOwners owners(comm, mesh);
    const auto slots = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(mesh.tris.size()), Reduce::sum));
    const std::uint64_t real = slots - ghosts.size();
    const std::size_t n = mesh.tris.size();
    FaceNumbers out;
    out.face.assign(n, FaceNumbers::none);
    // Removal flags by serial index, at the rank whose slot range holds the index.
    std::vector<std::uint8_t> removed_at(n, 0);
    std::vector<Bytes> movers(static_cast<std::size_t>(comm.size()));
    std::vector<std::uint64_t> mover_slots;
    for (std::uint64_t s = 0; s < n; ++s) {
        if (detail::is_ghost_triangle(mesh.tris[s])) continue;
        const std::uint64_t slot = mesh.first_slot + s;
        const std::uint64_t k = serial_face(slot, ghosts, real);
        const std::uint8_t removed = mesh.removed.empty() ? 0 : mesh.removed[s];
        if (slot < real) {
            removed_at[s] = removed;
            out.face[s] = k;
        } else {
            append_value(movers[owners.of(k)], Label{k, removed});
            mover_slots.push_back(s);
        }
    }
    const std::vector<Bytes> arrived = comm.alltoallv(std::move(movers));
    for (const Bytes& b : arrived) {
        for (const Label& l : from_bytes<Label>(b))
            removed_at[l.slot - mesh.first_slot] = l.depth != 0;
    }
    std::vector<std::uint64_t> before(n + 1, 0);  // removed indices of this range before each
    for (std::size_t j = 0; j < n; ++j) before[j + 1] = before[j] + removed_at[j];
    const auto base =
        static_cast<std::uint64_t>(comm.exscan_sum(static_cast<std::int64_t>(before[n])));
    const auto removed_total = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(before[n]), Reduce::sum));
    out.count = real - removed_total;
    const auto final_of = [&](std::uint64_t k) { return k - base - before[k - mesh.first_slot]; };
    for (std::uint64_t s = 0; s < n; ++s) {
        if (out.face[s] == FaceNumbers::none) continue;
        out.face[s] = removed_at[s] != 0 ? FaceNumbers::none : final_of(out.face[s]);
    }
    std::vector<Bytes> answers(arrived.size());
    for (std::size_t r = 0; r < arrived.size(); ++r) {
        for (const Label& l : from_bytes<Label>(arrived[r])) {
            append_value(answers[r], l.depth != 0 ? FaceNumbers::none : final_of(l.slot));
        }
    }
    // Answers come back in source order, each in the order asked: mover_slots' order, since
    // the movers were asked in slot order and owners hold ascending ranges.
    const auto finals = concatenated<std::uint64_t>(comm.alltoallv(std::move(answers)));
    for (std::size_t m = 0; m < mover_slots.size(); ++m) out.face[mover_slots[m]] = finals[m];
    return out;
}

}  // namespace dtm::dist
