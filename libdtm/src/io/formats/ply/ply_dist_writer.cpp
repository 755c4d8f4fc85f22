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

#include "dist/domain.hpp"
#include "dist/mesh_vertices.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/formats/ply.hpp"
#include "io/formats/ply/ply_dist_edges.hpp"

namespace dtm::io {

static_assert(std::endian::native == std::endian::little,
              "the binary PLY is little endian: the values are appended as they are in memory");

namespace {

struct EdgeRecord {
    std::int32_t a;
    std::int32_t b;
    std::uint8_t kind;
};

/// Rank 0: the PLY `edge` element's bytes (empty elsewhere), sorted by (a, b) as finish_tin
/// sorts them.
template <class Number>
std::vector<std::byte> constrained_edges(dist::Comm& comm,
                                         const dist::LocalMesh& mesh,
                                         const std::vector<std::uint64_t>& ghosts,
                                         const Number& number,
                                         bool trimmed) {
    std::vector<dist::Bytes> out(static_cast<std::size_t>(comm.size()));
    for (const detail::EdgeNumbers& e :
         detail::own_constrained_edges(comm, mesh, ghosts, number, trimmed)) {
        dist::append_value(out[0], EdgeRecord{static_cast<std::int32_t>(e.a),
                                              static_cast<std::int32_t>(e.b), e.kind});
    }
    std::vector<EdgeRecord> all = dist::concatenated<EdgeRecord>(comm.alltoallv(std::move(out)));
    std::sort(all.begin(), all.end(), [](const EdgeRecord& x, const EdgeRecord& y) {
        return x.a < y.a || (x.a == y.a && x.b < y.b);
    });
    std::vector<std::byte> bytes;
    bytes.reserve(9 * all.size());
    for (const EdgeRecord& e : all) {
        dist::append_value(bytes, e.a);
        dist::append_value(bytes, e.b);
        dist::append_value(bytes, e.kind);
    }
    return bytes;
}

}  // namespace

std::uint64_t write_distributed_ply(dist::Comm& comm,
                                    const dist::MergedShare& merged,
                                    const dist::DistributedMesh& kernel,
                                    const std::filesystem::path& path,
                                    const TinWriteOptions& options) {
    comm.set_phase("write tin");
    const dist::LocalMesh& mesh = kernel.mesh;
    const auto ghosts = dist::all_ghost_slots(comm, mesh);
    const std::uint64_t slots = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(mesh.tris.size()), dist::Reduce::sum));
    const std::uint64_t real = slots - ghosts.size();
    // With a domain (dist/domain.hpp) the face numbers leave the removed triangles out.
    const bool trimmed = !mesh.removed.empty();
    const dist::FaceNumbers kept =
        trimmed ? dist::kept_face_numbers(comm, mesh, ghosts) : dist::FaceNumbers{};
    const std::uint64_t faces = trimmed ? kept.count : real;
    const auto face_of = [&](std::uint64_t s) {
        if (trimmed) return kept.face[s];
        if (dtm::detail::is_ghost_triangle(mesh.tris[s])) return dist::FaceNumbers::none;
        return dist::serial_face(mesh.first_slot + s, ghosts, real);
    };
    const std::uint64_t vertices = merged.total_vertices;
    constexpr auto max_int = static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max());
    if (vertices > max_int || faces > max_int) {
        throw Error("cannot write " + path.string() +
                    ": more than 2^31 - 1 elements (a tiled TIN is not written yet)");
    }
    const auto numbers = dist::foreign_vertex_numbers(comm, kernel);
    const auto number = [&](std::uint32_t local) -> std::int32_t {
        const std::uint64_t position = mesh.global_vertex(local);
        const std::uint64_t v = mesh.own_vertex(position)
                                    ? kernel.input_ids[position - mesh.first_vertex]
                                    : numbers.at(position);
        return static_cast<std::int32_t>(v);
    };

    const std::vector<std::byte> edges = constrained_edges(comm, mesh, ghosts, number, trimmed);
    const auto edge_count = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(edges.size() / 9), dist::Reduce::max));

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
        const std::string header = ply_header(vertices, faces, edge_count, options);
        const std::uint64_t face_start = header.size() + 24 * vertices;
        auto file = comm.open_shared(temporary);
        if (comm.rank() == 0) {
            file->write_at(0, std::as_bytes(std::span<const char>(header.data(), header.size())));
        }
        // Vertices in runs (x and y from the kernel's positions, z from the merge), so that no
        // rank holds its whole block beside the kernel.
        static_assert(sizeof(Point3) == 24);
        dist::merged_vertex_runs(
            comm, merged, kernel, [&](std::uint64_t first, std::span<const Point3> run) {
                if (!run.empty()) file->write_at(header.size() + 24 * first, std::as_bytes(run));
            });
        // Faces: runs of consecutive face numbers (slots below R in place, the movers one by one
        // into the holes; with a domain, the removed ones left out), written at most 4 MiB at
        // a time.
        constexpr std::size_t block_limit = std::size_t{4} << 20;
        std::vector<std::byte> block;
        std::uint64_t run_start = 0;
        const auto flush = [&] {
            if (!block.empty()) file->write_at(face_start + 13 * run_start, block);
            block.clear();
        };
        for (std::uint64_t s = 0; s < mesh.tris.size(); ++s) {
            const std::uint64_t face = face_of(s);
            if (face == dist::FaceNumbers::none) continue;
            if (!block.empty() &&
                (face != run_start + block.size() / 13 || block.size() >= block_limit)) {
                flush();
            }
            if (block.empty()) run_start = face;
            block.push_back(std::byte{3});
            for (const std::uint32_t v : mesh.tris[s].v) dist::append_value(block, number(v));
        }
        flush();
        if (comm.rank() == 0 && !edges.empty()) file->write_at(face_start + 13 * faces, edges);
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
    return edge_count;
}

}  // namespace dtm::io
