// SPDX-License-Identifier: MIT
//
// The distributed tiled TIN (tiles_dist_writer.hpp). A rank's tile is its kernel slots' real
// triangles (dist::surface_mesh with every own vertex, heights from the vertices' owners), sorted
// by their face number in the whole TIN, so that the manifest lists a few runs of consecutive
// numbers per tile (slots in place, the hull's holes filled by movers); its constrained edges are
// the ones the single PLY lists from this rank (io/formats/ply/ply_dist_edges.hpp). Rank 0 makes
// a run token (new_tile_token) so a new run never overwrites tiles an old manifest names.
#include "io/formats/tin_tiles/tiles_dist_writer.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>

#include "dist/mesh_vertices.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/formats/tin_tiles.hpp"
#include "io/formats/ply/ply_dist_edges.hpp"

namespace dtm::io {
namespace {

namespace fs = std::filesystem;

dist::Bytes text_bytes(const std::string& text) {
    const auto* p = reinterpret_cast<const std::byte*>(text.data());
    return {p, p + text.size()};
}

std::string bytes_text(const dist::Bytes& bytes) {
    return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

/// Rank 0's run token, on every rank.
std::string run_token(dist::Comm& comm) {
    dist::Bytes token;
    if (comm.rank() == 0) token = text_bytes(new_tile_token());
    comm.bcast(token, 0);
    return bytes_text(token);
}

/// Collective: throws on every rank if any rank failed, with the lowest failing rank's message.
void agree(dist::Comm& comm, const std::string& failure) {
    if (comm.allreduce(failure.empty() ? 0 : 1, dist::Reduce::max) != 0) {
        dist::throw_first_error(comm, failure);
    }
}

struct Tile {
    Tin tin;
    std::vector<std::uint64_t> ids;
    TinTile info;
};

Tile make_tile(dist::Comm& comm, const dist::MergedShare& merged, const dist::DistributedMesh& k) {
    const dist::LocalMesh& mesh = k.mesh;
    dist::SurfaceMesh surface = dist::surface_mesh(comm, merged, k, {.every_own_vertex = true});
    Tile tile;
    tile.ids.reserve(surface.vertices.size());
    tile.tin.vertices.reserve(surface.vertices.size());
    std::array<double, 4>& box = tile.info.extent;
    box = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const dist::SurfaceVertex& v : surface.vertices) {
        tile.ids.push_back(v.id);
        tile.tin.vertices.push_back(v.p);
        box = {std::min(box[0], v.p.x), std::min(box[1], v.p.y), std::max(box[2], v.p.x),
               std::max(box[3], v.p.y)};
    }
    std::sort(
        surface.faces.begin(), surface.faces.end(),
        [](const dist::SurfaceFace& a, const dist::SurfaceFace& b) { return a.face < b.face; });
    tile.tin.triangles.reserve(surface.faces.size());
    auto& runs = tile.info.face_runs;
    for (const dist::SurfaceFace& f : surface.faces) {
        Triangle& t = tile.tin.triangles.emplace_back();
        t.v = {f.v[0], f.v[1], f.v[2]};
        if (!runs.empty() && runs.back()[0] + runs.back()[1] == f.face) {
            ++runs.back()[1];
        } else {
            runs.push_back({f.face, 1});
        }
    }
    const auto ghosts = dist::all_ghost_slots(comm, mesh);
    const auto foreign = dist::foreign_vertex_numbers(comm, k);
    const auto number = [&](std::uint32_t local) -> std::uint64_t {
        const std::uint64_t position = mesh.global_vertex(local);
        return mesh.own_vertex(position) ? k.input_ids[position - mesh.first_vertex]
                                         : foreign.at(position);
    };
    const auto local = [&](std::uint64_t id) {
        return static_cast<VertexIndex>(std::lower_bound(tile.ids.begin(), tile.ids.end(), id) -
                                        tile.ids.begin());
    };
    std::vector<detail::EdgeNumbers> edges =
        detail::own_constrained_edges(comm, mesh, ghosts, number, !mesh.removed.empty());
    std::sort(edges.begin(), edges.end());
    for (const detail::EdgeNumbers& e : edges) {
        tile.tin.constraints.push_back(
            {local(e.a), local(e.b), static_cast<ConstraintKind>(e.kind)});
    }
    tile.info.vertices = tile.tin.vertices.size();
    tile.info.faces = tile.tin.triangles.size();
    tile.info.edges = tile.tin.constraints.size();
    return tile;
}

dist::Bytes info_bytes(const TinTile& t) {
    dist::Bytes out;
    for (const std::uint64_t v : {t.vertices, t.faces, t.edges, std::uint64_t{t.face_runs.size()}})
        dist::append_value(out, v);
    for (const double v : t.extent) dist::append_value(out, v);
    for (const auto& run : t.face_runs) dist::append_value(out, run);
    return out;
}

TinTile info_of(const dist::Bytes& bytes, std::string file) {
    TinTile t;
    t.file = std::move(file);
    std::size_t at = 0;
    const auto take = [&](auto& value) {
        std::memcpy(&value, bytes.data() + at, sizeof value);
        at += sizeof value;
    };
    std::uint64_t runs = 0;
    take(t.vertices);
    take(t.faces);
    take(t.edges);
    take(runs);
    for (double& v : t.extent) take(v);
    t.face_runs.resize(runs);
    for (auto& run : t.face_runs) take(run);
    return t;
}

}  // namespace

TilesWritten write_distributed_tiles(dist::Comm& comm,
                                     const dist::MergedShare& merged,
                                     const dist::DistributedMesh& kernel,
                                     const fs::path& manifest,
                                     const TinWriteOptions& options) {
    comm.set_phase("write tiles");
    Tile tile = make_tile(comm, merged, kernel);
    const std::string token = run_token(comm);
    TilesWritten written;
    for (int r = 0; r < comm.size(); ++r) {
        written.tiles.push_back(tin_tile_name(manifest, token, r, comm.size()));
    }
    const fs::path mine =
        manifest.parent_path() / written.tiles[static_cast<std::size_t>(comm.rank())];
    std::string failure;
    try {
        AtomicOutput out(mine);
        TinWriteOptions tile_options = options;
        tile_options.vertex_ids = tile.ids;
        write_tin_ply(tile.tin, out.temp_path(), tile_options);
        out.commit();
    } catch (const Error& e) {
        failure = e.what();
    }
    const auto remove_mine = [&] {
        std::error_code ignored;
        fs::remove(mine, ignored);
    };
    try {
        agree(comm, failure);
    } catch (const Error&) {
        remove_mine();
        throw;
    }
    tile.tin = Tin{};
    std::vector<dist::Bytes> out(static_cast<std::size_t>(comm.size()));
    out[0] = info_bytes(tile.info);
    const std::vector<dist::Bytes> infos = comm.alltoallv(std::move(out));
    written.constrained_edges = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(tile.info.edges), dist::Reduce::sum));
    if (comm.rank() == 0) {
        TinTilesManifest m;
        m.crs_wkt = options.crs_wkt;
        m.vertices = merged.total_vertices;
        m.edges = written.constrained_edges;
        for (std::size_t r = 0; r < infos.size(); ++r) {
            m.tiles.push_back(info_of(infos[r], written.tiles[r]));
            m.faces += m.tiles.back().faces;
        }
        try {
            commit_tin_manifest(manifest, m);
        } catch (const Error& e) {
            failure = e.what();
        }
    }
    try {
        agree(comm, failure);
    } catch (const Error&) {
        remove_mine();
        throw;
    }
    return written;
}

}  // namespace dtm::io
