// SPDX-License-Identifier: MIT
//
// Breaklines into the distributed Delaunay mesh, with the serial result slot for slot.
//
// Inserting a segment by cavity retriangulation (Anglada 1997) rewrites exactly the triangles it
// crosses, and the new ones cover the same region; so by induction every triangle any insertion
// rewrites lies in the union of the original triangles the segments meet. Two segments whose
// met triangles are neither shared nor edge-adjacent therefore never read or write each other's
// triangles, and their insertions commute; linking the segments that do share or neighbour a
// triangle gives groups that can be inserted independently, each in the serial priority order
// (segment_priority; the serial rounds of deterministic reservations equal that order, Blelloch,
// Fineman, Gibbons and Shun, PPoPP 2012). The triangles a segment meets include the whole star of
// each endpoint, so every walk the editor makes stays inside the group's triangles; the ring of
// neighbours sent with them is only written (links and bits across the group's border).
//
// Steps: resolve the endpoints (input id -> kernel position, coordinates) by one allgather;
// test every own slot against the segments (SegmentGrid, exact); union-find over the segments
// from shared and adjacent triangles, its unions gathered and replayed on every rank (roots are
// group minima, so every rank gets the same groups); send each group's triangles and their ring
// to the rank of the group's first endpoint; insert there on a copy whose slot and vertex
// numbers are the global ones renumbered monotonically (the editor only compares them); send the
// changed slots and border links back.
#include "dist/constraints.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "algo/detail/constraint_batch.hpp"
#include "algo/detail/mesh_edit.hpp"
#include "dist/segment_touch.hpp"
#include "dtm/core/error.hpp"

namespace dtm::dist {
namespace {

constexpr std::uint32_t none = 0xffffffffu;

struct Endpoint {
    std::uint64_t id;
    std::uint64_t position;
    XY p;
};

/// A slot's content on the way to or from the rank that inserts its group.
struct SlotRecord {
    std::uint64_t slot = 0;
    GlobalTriangle t;
    std::array<XY, 3> p{};
    std::array<std::uint8_t, 3> bits{};
    std::uint8_t changed = 0;  ///< going back: bit i edge i (link, bits), bit 3 the corners
};

/// Which rank holds a slot or a vertex: the ranks' ranges are contiguous and in rank order.
class Owners {
public:
    Owners(Comm& comm, const LocalMesh& mesh) {
        std::array<std::uint64_t, 2> mine{mesh.first_slot + mesh.tris.size(),
                                          mesh.first_vertex + mesh.own_points.size()};
        const auto all = concatenated<std::uint64_t>(
            comm.allgatherv(to_bytes(std::span<const std::uint64_t>(mine))));
        std::uint64_t slot_end = 0, vertex_end = 0;
        for (std::size_t r = 0; r + 1 < all.size(); r += 2) {
            // An empty rank may report 0: the ends are made non-decreasing.
            slot_end = std::max(slot_end, all[r]);
            vertex_end = std::max(vertex_end, all[r + 1]);
            slot_ends_.push_back(slot_end);
            vertex_ends_.push_back(vertex_end);
        }
    }
    [[nodiscard]] int of_slot(std::uint64_t slot) const { return find(slot_ends_, slot); }
    [[nodiscard]] int of_vertex(std::uint64_t v) const { return find(vertex_ends_, v); }

private:
    static int find(const std::vector<std::uint64_t>& ends, std::uint64_t x) {
        const auto it = std::upper_bound(ends.begin(), ends.end(), x);
        if (it == ends.end()) throw std::logic_error("distributed constraints: no owner");
        return static_cast<int>(it - ends.begin());
    }
    std::vector<std::uint64_t> slot_ends_;
    std::vector<std::uint64_t> vertex_ends_;
};

class Groups {
public:
    explicit Groups(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
    std::uint32_t find(std::uint32_t a) {
        while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
        return a;
    }
    /// Joins the groups of @p a and @p b (the smaller root stays); true when they were apart.
    bool unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        parent_[std::max(a, b)] = std::min(a, b);
        return true;
    }

private:
    std::vector<std::uint32_t> parent_;
};

/// Every endpoint's kernel position and coordinates, from the ranks that hold them.
std::unordered_map<std::uint64_t, Endpoint> resolve_endpoints(
    Comm& comm, const DistributedMesh& mesh, const std::vector<GlobalSegment>& segments) {
    std::unordered_set<std::uint64_t> wanted;
    for (const GlobalSegment& s : segments) {
        wanted.insert(s.a);
        wanted.insert(s.b);
    }
    std::vector<Endpoint> mine;
    for (std::size_t i = 0; i < mesh.input_ids.size(); ++i) {
        if (wanted.contains(mesh.input_ids[i])) {
            mine.push_back(
                {mesh.input_ids[i], mesh.mesh.first_vertex + i, mesh.mesh.own_points[i]});
        }
    }
    std::unordered_map<std::uint64_t, Endpoint> out;
    for (const Endpoint& e :
         concatenated<Endpoint>(comm.allgatherv(to_bytes(std::span<const Endpoint>(mine))))) {
        out.emplace(e.id, e);
    }
    if (out.size() != wanted.size()) {
        throw std::logic_error("distributed constraints: a segment endpoint is in no rank's mesh");
    }
    return out;
}

std::array<XY, 3> corners(const LocalMesh& mesh, const GlobalTriangle& g, bool& hull_edge) {
    std::array<XY, 3> p{};
    unsigned k = 0;
    hull_edge = g.is_ghost();
    for (unsigned i = 0; i < 3; ++i) {
        if (g.v[i] != global_ghost) p[k++] = mesh.point(g.v[i]);
    }
    return p;
}

/// The own slots that some segment meets, each with the smallest such segment, ascending by
/// slot; the segments meeting one slot are united in @p groups (the unions kept in @p unions).
std::vector<std::pair<std::uint64_t, std::uint32_t>> touched_slots(
    const LocalMesh& mesh,
    const SegmentGrid& grid,
    const std::vector<std::uint32_t>& ids,
    Groups& groups,
    std::vector<std::uint32_t>& unions) {
    const std::size_t n = mesh.tris.size();
    constexpr std::size_t block = 4096;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found((n + block - 1) /
                                                                            block);
    tbb::parallel_for(std::size_t{0}, found.size(), [&](std::size_t b) {
        std::vector<std::uint32_t> hits;
        for (std::size_t s = b * block; s < std::min(n, (b + 1) * block); ++s) {
            const GlobalTriangle g = mesh.at(mesh.first_slot + s);
            if (g.unused()) continue;
            bool hull_edge = false;
            const std::array<XY, 3> p = corners(mesh, g, hull_edge);
            hits.clear();
            grid.touching(p, hull_edge, hits);
            for (const std::uint32_t h : hits)
                found[b].emplace_back(static_cast<std::uint32_t>(s), ids[h]);
        }
    });
    std::vector<std::pair<std::uint64_t, std::uint32_t>> out;
    for (const auto& part : found) {
        for (std::size_t k = 0; k < part.size(); ++k) {
            const auto [s, seg] = part[k];
            if (k > 0 && part[k - 1].first == s) {  // hits of one slot come ascending
                if (groups.unite(out.back().second, seg))
                    unions.insert(unions.end(), {out.back().second, seg});
                continue;
            }
            out.emplace_back(s, seg);
        }
    }
    return out;
}

struct PairHash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& k) const noexcept {
        return std::hash<std::uint64_t>{}(k.first * 0x9e3779b97f4a7c15ull ^ k.second);
    }
};

/// Sets the bits of every own half-edge that is a segment; per segment, 1 if it is an edge here.
std::vector<std::int64_t> mark_existing_edges(
    LocalMesh& mesh,
    const std::vector<GlobalSegment>& segments,
    const std::vector<std::array<std::uint64_t, 2>>& position) {
    std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, std::uint32_t, PairHash> index;
    for (std::uint32_t i = 0; i < segments.size(); ++i) {
        index.emplace(std::pair{std::min(position[i][0], position[i][1]),
                                std::max(position[i][0], position[i][1])},
                      i);
    }
    std::vector<std::int64_t> found(segments.size(), 0);
    for (std::uint64_t s = 0; s < mesh.tris.size(); ++s) {
        const GlobalTriangle g = mesh.at(mesh.first_slot + s);
        if (g.unused()) continue;
        for (unsigned i = 0; i < 3; ++i) {
            const std::uint64_t u = g.v[i];
            const std::uint64_t w = g.v[(i + 1) % 3];
            if (u == global_ghost || w == global_ghost) continue;
            const auto it = index.find({std::min(u, w), std::max(u, w)});
            if (it == index.end()) continue;
            mesh.bits[s][i] |= segments[it->second].bits;
            found[it->second] = 1;
        }
    }
    return found;
}

/// A met slot's note to the owner of its neighbour: join my group if you are met too.
struct NeighbourNote {
    std::uint64_t slot;
    std::uint32_t segment;
    std::uint32_t pad = 0;
};

/// Joins the groups of met slots that share an edge; returns the unions made here.
void join_adjacent(Comm& comm,
                   const LocalMesh& mesh,
                   const Owners& owners,
                   const std::vector<std::pair<std::uint64_t, std::uint32_t>>& touched,
                   Groups& groups,
                   std::vector<std::uint32_t>& unions) {
    const auto group_of = [&](std::uint64_t local) {
        const auto it = std::lower_bound(touched.begin(), touched.end(),
                                         std::pair<std::uint64_t, std::uint32_t>{local, 0});
        return it != touched.end() && it->first == local ? it->second : none;
    };
    const auto join = [&](std::uint32_t a, std::uint32_t b) {
        if (b != none && groups.unite(a, b)) unions.insert(unions.end(), {a, b});
    };
    std::vector<Bytes> out(static_cast<std::size_t>(comm.size()));
    for (const auto& [s, seg] : touched) {
        const GlobalTriangle g = mesh.at(mesh.first_slot + s);
        for (const std::uint64_t n : g.n) {
            if (n == global_ghost) continue;
            const std::uint64_t twin = n >> 2;
            if (mesh.owns(twin)) {
                join(seg, group_of(twin - mesh.first_slot));
            } else {
                append_value(out[static_cast<std::size_t>(owners.of_slot(twin))],
                             NeighbourNote{twin, seg});
            }
        }
    }
    for (const NeighbourNote& note : concatenated<NeighbourNote>(comm.alltoallv(std::move(out)))) {
        join(note.segment, group_of(note.slot - mesh.first_slot));
    }
}

SlotRecord record_of(const LocalMesh& mesh, std::uint64_t slot) {
    SlotRecord r;
    r.slot = slot;
    r.t = mesh.at(slot);
    r.bits = mesh.bits[slot - mesh.first_slot];
    for (unsigned i = 0; i < 3; ++i) {
        if (r.t.v[i] != global_ghost) r.p[i] = mesh.point(r.t.v[i]);
    }
    return r;
}

/// The slots gathered on this rank and their ring, as a serial mesh with monotone numbers.
struct Gathered {
    std::vector<SlotRecord> records;      ///< ascending by slot; local slot k is records[k]
    std::vector<std::uint64_t> vertices;  ///< local vertex v is global vertices[v]
    detail::GhostMesh mesh;

    [[nodiscard]] detail::VertexId local_vertex(std::uint64_t v) const {
        const auto it = std::lower_bound(vertices.begin(), vertices.end(), v);
        return static_cast<detail::VertexId>(it - vertices.begin());
    }

    explicit Gathered(std::vector<SlotRecord> all) : records(std::move(all)) {
        std::sort(records.begin(), records.end(),
                  [](const SlotRecord& a, const SlotRecord& b) { return a.slot < b.slot; });
        std::vector<std::pair<std::uint64_t, XY>> points;
        for (const SlotRecord& r : records) {
            for (unsigned i = 0; i < 3; ++i) {
                if (r.t.v[i] != global_ghost) points.emplace_back(r.t.v[i], r.p[i]);
            }
        }
        std::sort(points.begin(), points.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        points.erase(std::unique(points.begin(), points.end(),
                                 [](const auto& a, const auto& b) { return a.first == b.first; }),
                     points.end());
        mesh.points.resize(points.size());
        for (std::size_t v = 0; v < points.size(); ++v) {
            vertices.push_back(points[v].first);
            mesh.points[v] = {{points[v].second.x, points[v].second.y},
                              static_cast<std::uint32_t>(v)};
        }
        mesh.tris.resize(records.size());
        for (std::size_t k = 0; k < records.size(); ++k) {
            const GlobalTriangle& g = records[k].t;
            for (unsigned i = 0; i < 3; ++i) {
                mesh.tris[k].v[i] = g.v[i] == global_ghost ? detail::ghost : local_vertex(g.v[i]);
                mesh.tris[k].n[i] = detail::no_half_edge;  // the ring's outer links: never read
                if (g.n[i] == global_ghost) continue;
                const std::size_t at = slot_index(g.n[i] >> 2);
                if (at != records.size()) {
                    mesh.tris[k].n[i] = detail::half_edge(at, static_cast<unsigned>(g.n[i] & 3u));
                }
            }
        }
    }

    /// The local slot of global @p slot, or records.size().
    [[nodiscard]] std::size_t slot_index(std::uint64_t slot) const {
        const auto it =
            std::lower_bound(records.begin(), records.end(), slot,
                             [](const SlotRecord& r, std::uint64_t s) { return r.slot < s; });
        return it != records.end() && it->slot == slot
                   ? static_cast<std::size_t>(it - records.begin())
                   : records.size();
    }

    /// Local slot @p k after the insertion, in global numbers, with what changed.
    [[nodiscard]] SlotRecord result(std::size_t k) const {
        const SlotRecord& before = records[k];
        SlotRecord now = before;
        const Triangle& t = mesh.tris[k];
        for (unsigned i = 0; i < 3; ++i) {
            now.t.v[i] = t.v[i] == detail::ghost ? global_ghost : vertices[t.v[i]];
            now.p[i] =
                t.v[i] == detail::ghost ? XY{} : XY{mesh.points[t.v[i]].x, mesh.points[t.v[i]].y};
            if (t.n[i] != detail::no_half_edge) {
                now.t.n[i] = records[t.n[i] >> 2].slot << 2 | (t.n[i] & 3u);
            }
            now.bits[i] = mesh.bits[k][i];
        }
        if (now.t.v != before.t.v) {
            now.changed = 0xf;
        } else {
            for (unsigned i = 0; i < 3; ++i) {
                if (now.t.n[i] != before.t.n[i] || now.bits[i] != before.bits[i])
                    now.changed = static_cast<std::uint8_t>(now.changed | 1u << i);
            }
        }
        return now;
    }
};

/// Inserts @p order (segment indices) into @p gathered; an error message, or "".
std::string insert_here(Gathered& gathered,
                        const std::vector<GlobalSegment>& segments,
                        const std::vector<std::array<std::uint64_t, 2>>& position,
                        const std::vector<std::uint32_t>& order) {
    try {
        std::vector<double> z(gathered.mesh.points.size(), 0.0);
        detail::MeshEditor editor(gathered.mesh, z, 0.0);
        for (std::size_t k = 0; k < gathered.records.size(); ++k) {  // edges marked in place
            gathered.mesh.bits[k] = gathered.records[k].bits;
        }
        detail::MeshEditor::SegmentPlan plan;
        for (const std::uint32_t s : order) {  // planned first: a crossing adds no vertex
            editor.plan_segment(gathered.local_vertex(position[s][0]),
                                gathered.local_vertex(position[s][1]), plan);
            if (plan.crosses_constraint) {
                return "distributed breaklines: two segments cross (they must be split at "
                       "their crossings first)";
            }
            editor.apply_segment(plan, segments[s].bits);
        }
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace

ConstraintStats insert_constraints(Comm& comm,
                                   DistributedMesh& distributed,
                                   const std::vector<GlobalSegment>& segments,
                                   const Progress& progress) {
    LocalMesh& mesh = distributed.mesh;
    mesh.bits.assign(mesh.tris.size(), {0, 0, 0});
    ConstraintStats stats;
    if (segments.empty()) return stats;
    if (segments.size() >= none) throw Error("distributed breaklines: more than 2^32 - 2 segments");
    comm.set_phase("constraints");
    const auto ranks = static_cast<std::size_t>(comm.size());
    const Owners owners(comm, mesh);
    const auto ends = resolve_endpoints(comm, distributed, segments);
    std::vector<TouchSegment> geometry(segments.size());
    std::vector<std::array<std::uint64_t, 2>> position(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Endpoint& a = ends.at(segments[i].a);
        const Endpoint& b = ends.at(segments[i].b);
        geometry[i] = {a.p, b.p};
        position[i] = {a.position, b.position};
    }

    // Segments that are an edge already are marked where they are (serially too: they stay
    // edges, as no other segment crosses them); the others are grouped.
    std::vector<std::int64_t> is_edge = mark_existing_edges(mesh, segments, position);
    comm.allreduce(is_edge, Reduce::max);
    std::vector<std::uint32_t> rest;
    std::vector<TouchSegment> rest_geometry;
    for (std::uint32_t i = 0; i < segments.size(); ++i) {
        if (is_edge[i] != 0) continue;
        rest.push_back(i);
        rest_geometry.push_back(geometry[i]);
    }
    stats.marked = segments.size() - rest.size();

    // Groups: segments meeting one slot, or two slots that share an edge.
    Groups local(segments.size());
    std::vector<std::uint32_t> unions;
    const auto touched = touched_slots(mesh, SegmentGrid(rest_geometry), rest, local, unions);
    join_adjacent(comm, mesh, owners, touched, local, unions);
    Groups groups(segments.size());
    const auto all_unions = concatenated<std::uint32_t>(
        comm.allgatherv(to_bytes(std::span<const std::uint32_t>(unions))));
    for (std::size_t k = 0; k + 1 < all_unions.size(); k += 2)
        groups.unite(all_unions[k], all_unions[k + 1]);
    std::vector<int> destination(segments.size());
    for (std::uint32_t s = 0; s < segments.size(); ++s) {
        const std::uint32_t root = groups.find(s);
        if (root == s && is_edge[s] == 0) ++stats.components;
        destination[s] = owners.of_vertex(std::min(position[root][0], position[root][1]));
    }
    check_stop_everywhere(comm, progress);

    // Each group's slots, then their ring, to the group's rank.
    std::vector<Bytes> out(ranks);
    for (const auto& [s, seg] : touched) {
        append_value(out[static_cast<std::size_t>(destination[seg])],
                     record_of(mesh, mesh.first_slot + s));
    }
    std::vector<SlotRecord> records = concatenated<SlotRecord>(comm.alltoallv(std::move(out)));
    std::vector<std::uint64_t> ring;
    {
        std::vector<std::uint64_t> have;
        for (const SlotRecord& r : records) have.push_back(r.slot);
        std::sort(have.begin(), have.end());
        for (const SlotRecord& r : records) {
            for (const std::uint64_t n : r.t.n) {
                if (n != global_ghost && !std::binary_search(have.begin(), have.end(), n >> 2)) {
                    ring.push_back(n >> 2);
                }
            }
        }
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    out.assign(ranks, {});
    for (const std::uint64_t slot : ring)
        append_value(out[static_cast<std::size_t>(owners.of_slot(slot))], slot);
    const std::vector<Bytes> asked = comm.alltoallv(std::move(out));
    out.assign(ranks, {});
    for (std::size_t r = 0; r < ranks; ++r) {
        for (const std::uint64_t slot : from_bytes<std::uint64_t>(asked[r]))
            append_value(out[r], record_of(mesh, slot));
    }
    for (const SlotRecord& r : concatenated<SlotRecord>(comm.alltoallv(std::move(out))))
        records.push_back(r);
    stats.gathered = records.size();

    // Insertion in the serial priority order.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    for (std::uint32_t s = 0; s < segments.size(); ++s) {
        if (destination[s] != comm.rank() || is_edge[s] != 0) continue;
        keyed.emplace_back(detail::segment_priority(s, std::min(position[s][0], position[s][1])),
                           s);
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::uint32_t> order;
    for (const auto& [key, s] : keyed) order.push_back(s);
    Gathered gathered(std::move(records));
    const std::string failure =
        order.empty() ? std::string{} : insert_here(gathered, segments, position, order);
    if (comm.allreduce(failure.empty() ? 0 : 1, Reduce::max) != 0) throw_first_error(comm, failure);

    // The changed slots back to their owners.
    out.assign(ranks, {});
    if (!order.empty()) {
        for (std::size_t k = 0; k < gathered.records.size(); ++k) {
            const SlotRecord now = gathered.result(k);
            if (now.changed != 0)
                append_value(out[static_cast<std::size_t>(owners.of_slot(now.slot))], now);
        }
    }
    for (const SlotRecord& r : concatenated<SlotRecord>(comm.alltoallv(std::move(out)))) {
        GlobalTriangle t = mesh.at(r.slot);
        std::array<std::uint8_t, 3>& bits = mesh.bits[r.slot - mesh.first_slot];
        if ((r.changed & 8u) != 0) t.v = r.t.v;
        for (unsigned i = 0; i < 3; ++i) {
            if ((r.changed & (8u | 1u << i)) == 0) continue;
            t.n[i] = r.t.n[i];
            bits[i] = r.bits[i];
        }
        for (unsigned i = 0; i < 3; ++i) {
            if (t.v[i] != global_ghost) mesh.learn_point(t.v[i], r.p[i]);
        }
        mesh.set(r.slot, t);
        ++stats.changed;
    }
    progress.report(1.0, "breaklines inserted");
    return stats;
}

}  // namespace dtm::dist
