// SPDX-License-Identifier: MIT
//
// Lookups over the distributed mesh (mesh_vertices.hpp). Each is a question to the rank that
// holds the answer: a sorted, duplicate-free list of numbers per owner in one alltoallv, the
// answers in the same order in a second one.
#include "dist/mesh_vertices.hpp"

#include <algorithm>
#include <functional>
#include <span>
#include <unordered_set>
#include <utility>

#include "dist/domain.hpp"
#include "dist/drop_pages.hpp"

namespace dtm::dist {

RunOwners::RunOwners(Comm& comm, std::uint64_t lo, std::uint64_t hi) {
    const std::uint64_t range[2] = {lo, hi};
    const auto all = concatenated<std::uint64_t>(
        comm.allgatherv(to_bytes(std::span<const std::uint64_t>(range, 2))));
    for (std::size_t r = 0; r < all.size() / 2; ++r) {
        if (all[2 * r + 1] > all[2 * r])
            runs_.push_back({all[2 * r], all[2 * r + 1], static_cast<int>(r)});
    }
}

int RunOwners::of(std::uint64_t number) const { return locate(number).first; }

std::pair<int, std::uint64_t> RunOwners::locate(std::uint64_t number) const {
    const auto it = std::upper_bound(runs_.begin(), runs_.end(), number,
                                     [](std::uint64_t n, const Run& r) { return n < r.lo; });
    return {std::prev(it)->rank, number - std::prev(it)->lo};
}

namespace {

/// Sends each owner the numbers it holds of @p wanted (sorted, unique; the numbers are
/// @p number of each element) and returns, per source rank, the numbers it asked for.
/// (A projection rather than a transform view: clang 14, which builds the fuzzers, cannot
/// compile libstdc++ 12's views.)
template <class Range, class Number = std::identity>
std::vector<Bytes> ask_owners(Comm& comm,
                              const RunOwners& owners,
                              const Range& wanted,
                              Number number = {}) {
    std::vector<Bytes> ask(static_cast<std::size_t>(comm.size()));
    for (const auto& w : wanted) {
        const std::uint64_t v = std::invoke(number, w);
        append_value(ask[static_cast<std::size_t>(owners.of(v))], v);
    }
    return comm.alltoallv(std::move(ask));
}

std::vector<std::uint64_t> sorted_unique(std::vector<std::uint64_t> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

}  // namespace

std::unordered_map<std::uint64_t, std::uint64_t> foreign_vertex_numbers(Comm& comm,
                                                                        const DistributedMesh& k) {
    const LocalMesh& mesh = k.mesh;
    const RunOwners owners(comm, mesh.first_vertex, mesh.first_vertex + mesh.own_points.size());
    const auto asked = ask_owners(comm, owners, sorted_unique(mesh.foreign_vertices));
    std::vector<Bytes> answer(asked.size());
    for (std::size_t s = 0; s < asked.size(); ++s) {
        for (const std::uint64_t v : from_bytes<std::uint64_t>(asked[s])) {
            append_value(answer[s], v);
            append_value(answer[s], k.input_ids[v - mesh.first_vertex]);
        }
    }
    std::unordered_map<std::uint64_t, std::uint64_t> numbers;
    const auto answered = concatenated<std::uint64_t>(comm.alltoallv(std::move(answer)));
    for (std::size_t i = 0; i + 1 < answered.size(); i += 2)
        numbers.emplace(answered[i], answered[i + 1]);
    return numbers;
}

std::vector<std::uint64_t> all_ghost_slots(Comm& comm, const LocalMesh& mesh) {
    std::vector<std::uint64_t> mine;
    for (std::uint64_t s = 0; s < mesh.tris.size(); ++s) {
        if (detail::is_ghost_triangle(mesh.tris[s])) mine.push_back(mesh.first_slot + s);
    }
    return concatenated<std::uint64_t>(
        comm.allgatherv(to_bytes(std::span<const std::uint64_t>(mine))));
}

std::uint64_t serial_face(std::uint64_t slot,
                          std::span<const std::uint64_t> ghosts,
                          std::uint64_t real) {
    if (slot < real) return slot;
    const auto holes_end = std::lower_bound(ghosts.begin(), ghosts.end(), real);
    const auto between = static_cast<std::uint64_t>(
        std::lower_bound(ghosts.begin(), ghosts.end(), slot) - holes_end);
    return ghosts[slot - real - between];
}

Tin surface_tin(const SurfaceMesh& mesh) {
    Tin tin;
    tin.vertices.reserve(mesh.vertices.size());
    for (const SurfaceVertex& v : mesh.vertices) tin.vertices.push_back(v.p);
    tin.triangles.reserve(mesh.faces.size());
    for (const SurfaceFace& f : mesh.faces) {
        Triangle t;
        t.v = {f.v[0], f.v[1], f.v[2]};
        tin.triangles.push_back(t);
    }
    return tin;
}

namespace {

/// surface_mesh(); with @p release (the kernel itself, given up), the kernel's arrays are freed
/// as soon as they are read no more: the triangles' pages behind the listing of the faces, the
/// points once the vertices hold their coordinates.
SurfaceMesh faces_and_vertices(Comm& comm,
                               const MergedShare& merged,
                               const DistributedMesh& k,
                               const SurfaceMeshOptions& options,
                               DistributedMesh* release) {
    const LocalMesh& mesh = k.mesh;
    const auto foreign = foreign_vertex_numbers(comm, k);
    const auto ghosts = all_ghost_slots(comm, mesh);
    const auto number = [&](std::uint32_t local) {
        const std::uint64_t position = mesh.global_vertex(local);
        return mesh.own_vertex(position) ? k.input_ids[position - mesh.first_vertex]
                                         : foreign.at(position);
    };
    // A removed neighbour (dist/domain.hpp) leaves the edge on the border, as a hull ghost does.
    const bool trimmed = !mesh.removed.empty();
    const std::unordered_set<std::uint64_t> removed_next_door =
        trimmed ? foreign_removed(comm, mesh) : std::unordered_set<std::uint64_t>{};
    const auto outside = [&](std::uint64_t slot) {
        if (std::binary_search(ghosts.begin(), ghosts.end(), slot)) return true;
        if (!trimmed) return false;
        return mesh.owns(slot) ? mesh.removed[slot - mesh.first_slot] != 0
                               : removed_next_door.contains(slot);
    };
    const auto slots = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(mesh.tris.size()), Reduce::sum));
    const std::uint64_t real = slots - ghosts.size();
    const FaceNumbers kept = trimmed ? kept_face_numbers(comm, mesh, ghosts) : FaceNumbers{};
    if (release != nullptr) {  // not read below
        std::vector<std::array<std::uint8_t, 3>>().swap(release->mesh.bits);
    }
    SurfaceMesh out;
    out.faces.reserve(mesh.tris.size());
    // Faces name the kernel's local vertices first; the used local vertices are then numbered
    // by one sort of the vertices themselves (below), not of a record per corner.
    const std::size_t local_count = mesh.own_points.size() + mesh.foreign_vertices.size();
    constexpr std::uint32_t unused = ~std::uint32_t{0};
    std::vector<std::uint32_t> index_of(local_count, unused);
    for (std::uint64_t s = 0; s < mesh.tris.size(); ++s) {
        const Triangle& t = mesh.tris[s];
        if (!mesh.kept(s)) continue;
        const GlobalTriangle g = mesh.at(mesh.first_slot + s);
        SurfaceFace f;
        f.face = trimmed ? kept.face[s] : serial_face(mesh.first_slot + s, ghosts, real);
        for (unsigned i = 0; i < 3; ++i) {
            f.v[i] = t.v[i];
            index_of[t.v[i]] = 0;
            // Kernel half-edge i runs v[i] -> v[i + 1], opposite corner i + 2
            // (tin_build_triangles).
            if (g.n[i] == global_ghost || outside(g.n[i] >> 2)) f.border |= 1U << ((i + 2) % 3);
        }
        out.faces.push_back(f);
        // The slots behind are read no more: their pages go while the faces grow.
        constexpr std::uint64_t drop_every = std::uint64_t{1} << 16;
        if (release != nullptr && (s + 1) % drop_every == 0) {
            drop_pages(mesh.tris.data(), mesh.tris.data() + s + 1);
        }
    }
    if (release != nullptr) {
        std::vector<Triangle>().swap(release->mesh.tris);
        std::vector<std::uint8_t>().swap(release->mesh.removed);
    }
    // With every own vertex, the positions no triangle names come too.
    if (options.every_own_vertex) {
        std::fill(index_of.begin(), index_of.begin() + std::ptrdiff_t(mesh.own_points.size()), 0);
    }
    // Every used local vertex with its number and coordinates, p.z holding its local index (exact
    // in a double) until the heights arrive; then the kernel's points can go, and one sort by
    // (number, local) with repeats of a number merged gives the vertices in ascending number.
    out.vertices.reserve(local_count -
                         static_cast<std::size_t>(std::ranges::count(index_of, unused)));
    for (std::uint32_t local = 0; local < local_count; ++local) {
        if (index_of[local] == unused) continue;
        const XY xy = mesh.point(mesh.global_vertex(local));
        out.vertices.push_back({number(local), {xy.x, xy.y, static_cast<double>(local)}});
    }
    if (release != nullptr) {  // the kernel's points are read no more
        LocalMesh& m = release->mesh;
        std::vector<XY>().swap(m.own_points);
        std::vector<std::uint64_t>().swap(m.foreign_vertices);
        std::vector<XY>().swap(m.foreign_xy);
        std::unordered_map<std::uint64_t, std::uint32_t>().swap(m.foreign_index);
        std::vector<std::uint64_t>().swap(m.foreign_edges);
        std::vector<std::uint64_t>().swap(release->input_ids);
    }
    std::sort(out.vertices.begin(), out.vertices.end(),
              [](const SurfaceVertex& a, const SurfaceVertex& b) {
                  return a.id < b.id || (a.id == b.id && a.p.z < b.p.z);
              });
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < out.vertices.size(); ++i) {
        const auto local = static_cast<std::uint32_t>(out.vertices[i].p.z);
        if (distinct == 0 || out.vertices[distinct - 1].id != out.vertices[i].id) {
            out.vertices[distinct++] = out.vertices[i];
        }
        index_of[local] = static_cast<std::uint32_t>(distinct - 1);
    }
    out.vertices.resize(distinct);
    for (SurfaceFace& f : out.faces) {
        for (std::uint32_t& v : f.v) v = index_of[v];
    }
    std::vector<std::uint32_t>().swap(index_of);
    // The heights from the vertices' owners in the merge: each owner is asked for the numbers
    // it holds, in ascending order, straight from the vertices (no list of them beside).
    const RunOwners owners(comm, merged.first_vertex, merged.first_vertex + merged.count());
    auto asked = ask_owners(comm, owners, out.vertices, &SurfaceVertex::id);
    std::vector<Bytes> answer(asked.size());
    for (std::size_t r = 0; r < asked.size(); ++r) {
        answer[r].reserve(asked[r].size());  // a height (8 bytes) for each number (8 bytes)
        for (const std::uint64_t v : from_bytes<std::uint64_t>(asked[r])) {
            append_value(answer[r], merged.z(v - merged.first_vertex));
        }
        Bytes().swap(asked[r]);
    }
    // Answers come back in source-rank order, each in the asked (ascending) order: that is the
    // vertices' order, since owners hold ascending runs.
    const auto heights = concatenated<double>(comm.alltoallv(std::move(answer)));
    for (std::size_t w = 0; w < out.vertices.size(); ++w) out.vertices[w].p.z = heights[w];
    return out;
}

}  // namespace

SurfaceMesh surface_mesh(Comm& comm,
                         const MergedShare& merged,
                         const DistributedMesh& kernel,
                         const SurfaceMeshOptions& options) {
    return faces_and_vertices(comm, merged, kernel, options, nullptr);
}

SurfaceMesh surface_mesh(Comm& comm,
                         const MergedShare& merged,
                         DistributedMesh&& kernel,
                         const SurfaceMeshOptions& options) {
    DistributedMesh k = std::move(kernel);
    return faces_and_vertices(comm, merged, k, options, &k);
}

void merged_vertex_runs(Comm& comm,
                        const MergedShare& merged,
                        const DistributedMesh& k,
                        const std::function<void(std::uint64_t, std::span<const Point3>)>& run) {
    const LocalMesh& mesh = k.mesh;
    const RunOwners owners(comm, merged.first_vertex, merged.first_vertex + merged.count());
    const auto largest = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(merged.count()), Reduce::max));
    const std::uint64_t length = std::max<std::uint64_t>(65536, (largest + 15) / 16);
    const std::uint64_t rounds = (largest + length - 1) / length;
    // Per own position, the round its vertex travels in (at most 16).
    std::vector<std::uint8_t> round_of(k.input_ids.size());
    for (std::size_t v = 0; v < k.input_ids.size(); ++v) {
        round_of[v] = static_cast<std::uint8_t>(owners.locate(k.input_ids[v]).second / length);
    }
    struct Record {
        std::uint64_t place;  // in the owner's run
        double x, y;
    };
    std::vector<Point3> block;
    for (std::uint64_t round = 0; round < rounds; ++round) {
        std::vector<Bytes> out(static_cast<std::size_t>(comm.size()));
        for (std::size_t v = 0; v < round_of.size(); ++v) {
            if (round_of[v] != round) continue;
            const auto [rank, place] = owners.locate(k.input_ids[v]);
            const XY& xy = mesh.own_points[v];
            append_value(out[static_cast<std::size_t>(rank)], Record{place, xy.x, xy.y});
        }
        const auto records = concatenated<Record>(comm.alltoallv(std::move(out)));
        const std::uint64_t first = std::min<std::uint64_t>(round * length, merged.count());
        block.resize(std::min<std::uint64_t>(length, merged.count() - first));
        for (const Record& r : records) {
            block[r.place - first] = {r.x, r.y, merged.z(r.place)};
        }
        run(merged.first_vertex + first, block);
    }
}

}  // namespace dtm::dist
