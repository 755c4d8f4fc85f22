// SPDX-License-Identifier: MIT
//
// The distributed PLY (ply_dist_writer.hpp). The serial TIN's face order is the kernel's slot
// order with the ghost slots (hull ghosts and the two unused slots: O(sqrt n)) removed: ghost
// slots below R, the number of real triangles, take the real triangles above R in order. Every
// rank learns all ghost slots (one allgatherv), so it knows where each of its triangles goes:
// a real slot s < R stays at s; the k-th real slot at or above R goes to the k-th ghost slot
// below R. Face vertices are kernel positions; their vertex numbers (merged input order) come
// from the positions' owners for positions another rank holds. Offsets follow from the counts:
// header, 24 bytes per vertex, 13 per face.
#include "io/formats/ply/ply_dist_writer.hpp"

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <string>
#include <unordered_map>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/ply.hpp"

namespace dtm::io {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the binary PLY is little endian: the values are appended as they are in memory");

/// The owner of each kernel position: ranks hold contiguous runs, in rank order.
class PositionOwners {
public:
    PositionOwners(dist::Comm& comm, const dist::LocalMesh& mesh) {
        const std::uint64_t range[2] = {mesh.first_vertex,
                                        mesh.first_vertex + mesh.own_points.size()};
        const auto all = dist::concatenated<std::uint64_t>(
            comm.allgatherv(dist::to_bytes(std::span<const std::uint64_t>(range, 2))));
        for (std::size_t r = 0; r < all.size() / 2; ++r) {
            if (all[2 * r + 1] > all[2 * r])
                runs_.push_back({all[2 * r], all[2 * r + 1], static_cast<int>(r)});
        }
    }
    [[nodiscard]] int of(std::uint64_t position) const {
        const auto it = std::upper_bound(runs_.begin(), runs_.end(), position,
                                         [](std::uint64_t p, const Run& r) { return p < r.lo; });
        return std::prev(it)->rank;
    }

private:
    struct Run {
        std::uint64_t lo, hi;
        int rank;
    };
    std::vector<Run> runs_;
};

/// Vertex numbers of the positions this rank's triangles name (own ones from the kernel's
/// input_ids, the others asked of their owners).
std::unordered_map<std::uint64_t, std::uint64_t> vertex_numbers(dist::Comm& comm,
                                                                const dist::DistributedMesh& k) {
    const dist::LocalMesh& mesh = k.mesh;
    const auto ranks = static_cast<std::size_t>(comm.size());
    const PositionOwners owners(comm, mesh);
    std::vector<std::uint64_t> foreign = mesh.foreign_vertices;
    std::sort(foreign.begin(), foreign.end());
    std::vector<dist::Bytes> ask(ranks);
    for (const std::uint64_t v : foreign)
        dist::append_value(ask[static_cast<std::size_t>(owners.of(v))], v);
    const auto asked = comm.alltoallv(std::move(ask));
    std::vector<dist::Bytes> answer(ranks);
    for (std::size_t s = 0; s < ranks; ++s) {
        for (const std::uint64_t v : dist::from_bytes<std::uint64_t>(asked[s])) {
            dist::append_value(answer[s], v);
            dist::append_value(answer[s], k.input_ids[v - mesh.first_vertex]);
        }
    }
    std::unordered_map<std::uint64_t, std::uint64_t> numbers;
    const auto answered = dist::concatenated<std::uint64_t>(comm.alltoallv(std::move(answer)));
    for (std::size_t i = 0; i + 1 < answered.size(); i += 2)
        numbers.emplace(answered[i], answered[i + 1]);
    return numbers;
}

}  // namespace

void write_distributed_ply(dist::Comm& comm,
                           const dist::MergedShare& merged,
                           const dist::DistributedMesh& kernel,
                           const std::filesystem::path& path,
                           const TinWriteOptions& options) {
    comm.set_phase("write tin");
    const dist::LocalMesh& mesh = kernel.mesh;
    // The ghost slots of all ranks, in slot order (ranks hold ascending slot runs).
    std::vector<std::uint64_t> mine;
    for (std::uint64_t s = 0; s < mesh.tris.size(); ++s) {
        if (detail::is_ghost_triangle(mesh.tris[s])) {
            mine.push_back(mesh.first_slot + s);
        }
    }
    const auto ghosts = dist::concatenated<std::uint64_t>(
        comm.allgatherv(dist::to_bytes(std::span<const std::uint64_t>(mine))));
    const std::uint64_t slots = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(mesh.tris.size()), dist::Reduce::sum));
    const std::uint64_t faces = slots - ghosts.size();
    const std::uint64_t vertices = merged.total_vertices;
    constexpr auto max_int = static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max());
    if (vertices > max_int || faces > max_int) {
        throw Error("cannot write " + path.string() +
                    ": more than 2^31 - 1 elements (a tiled TIN is not written yet)");
    }
    const auto numbers = vertex_numbers(comm, kernel);
    const auto number = [&](std::uint32_t local) -> std::int32_t {
        const std::uint64_t position = mesh.global_vertex(local);
        const std::uint64_t v = mesh.own_vertex(position)
                                    ? kernel.input_ids[position - mesh.first_vertex]
                                    : numbers.at(position);
        return static_cast<std::int32_t>(v);
    };

    // A temporary sibling named by rank 0, renamed by it when every rank has written.
    dist::Bytes name_bytes;
    if (comm.rank() == 0) {
        const std::string name = path.string() + ".part-" + std::to_string(::getpid());
        const auto* p = reinterpret_cast<const std::byte*>(name.data());
        name_bytes.assign(p, p + name.size());
    }
    comm.bcast(name_bytes, 0);
    const std::string temporary(reinterpret_cast<const char*>(name_bytes.data()),
                                name_bytes.size());
    try {
        const std::string header = ply_header(vertices, faces, 0, options);
        const std::uint64_t face_start = header.size() + 24 * vertices;
        auto file = comm.open_shared(temporary);
        if (comm.rank() == 0) {
            file->write_at(0, std::as_bytes(std::span<const char>(header.data(), header.size())));
        }
        std::vector<std::byte> block;
        block.reserve(24 * merged.vertices.size());
        for (const dist::Vertex& v : merged.vertices) {
            dist::append_value(block, v.p.x);
            dist::append_value(block, v.p.y);
            dist::append_value(block, v.p.z);
        }
        file->write_at(header.size() + 24 * merged.first_vertex, block);
        // Faces: runs of slots below R in place, the movers one by one into the holes.
        const std::uint64_t real_end = faces;  // R
        const auto holes_end = std::lower_bound(ghosts.begin(), ghosts.end(), real_end);
        block.clear();
        std::uint64_t run_start = 0;
        const auto flush = [&] {
            if (!block.empty()) file->write_at(face_start + 13 * run_start, block);
            block.clear();
        };
        std::vector<std::byte> one;
        for (std::uint64_t s = 0; s < mesh.tris.size(); ++s) {
            const Triangle& t = mesh.tris[s];
            const std::uint64_t slot = mesh.first_slot + s;
            if (detail::is_ghost_triangle(t)) {
                flush();
                continue;
            }
            std::vector<std::byte>& out = slot < real_end ? block : one;
            if (slot < real_end && block.empty()) run_start = slot;
            out.push_back(std::byte{3});
            for (const std::uint32_t v : t.v) dist::append_value(out, number(v));
            if (slot >= real_end) {
                flush();
                // The k-th real slot at or above R fills the k-th hole below R.
                const std::uint64_t ghosts_between = static_cast<std::uint64_t>(
                    std::lower_bound(ghosts.begin(), ghosts.end(), slot) - holes_end);
                const std::uint64_t k = slot - real_end - ghosts_between;
                file->write_at(face_start + 13 * ghosts[k], one);
                one.clear();
            }
        }
        flush();
        file->close();
    } catch (const Error&) {
        if (comm.rank() == 0) std::filesystem::remove(temporary);
        throw;
    }
    comm.barrier();
    std::int64_t failed = 0;
    std::string message;
    if (comm.rank() == 0) {
        std::error_code error;
        std::filesystem::rename(temporary, path, error);
        if (error) {
            failed = 1;
            message = "cannot write " + path.string() + ": " + error.message();
            std::filesystem::remove(temporary);
        }
    }
    if (comm.allreduce(failed, dist::Reduce::max) != 0) {
        throw Error(comm.rank() == 0 ? message : "cannot write " + path.string());
    }
}

}  // namespace dtm::io
