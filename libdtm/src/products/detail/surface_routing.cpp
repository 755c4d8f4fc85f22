// SPDX-License-Identifier: MIT
// Routing the TIN's faces to the ranks that need them (surface_routing.hpp): per destination a
// list of the vertices its faces name and the faces with indices into that list (24 bytes a
// face and 32 a vertex instead of three coordinates per corner), each list allocated once at
// its counted size, one alltoallv each; the receiver numbers the vertices by one sort of
// (number, source, index), read in place from what it received, and, for contours, orders the
// faces by their serial index, so the rebuilt Tin keeps the serial TIN's relative orders; for a
// DEM the faces stay as received and the vertices take first-use order, the order rasterize
// reads without a copy. A rank's peak is its vertices and their outgoing lists beside the faces
// not yet listed (their pages go as the listing passes them), then what it received and the Tin
// (docs/distributed.md, R-M1).
#include "products/detail/surface_routing.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "algo/detail/raster_vertex_order.hpp"
#include "dist/drop_pages.hpp"

namespace dtm::products::detail {

namespace {

/// The per-destination lists of route_faces: vertices (each once per destination unless its
/// faces alternate between destinations) and faces indexing them. Two passes over the faces,
/// the first counting, so each list is allocated once at its size; the second gives the pages
/// of the faces it has passed back to the system (the faces are not read again).
struct Outgoing {
    std::vector<dist::Bytes> vertices, faces;
};

Outgoing outgoing_lists(std::size_t ranks,
                        dist::SurfaceMesh& surface,
                        const Destinations& destinations) {
    constexpr std::size_t none = ~std::size_t{0};
    std::vector<std::size_t> last_rank(surface.vertices.size());
    std::vector<std::uint32_t> index_there(surface.vertices.size(), 0);
    std::vector<std::size_t> face_count(ranks);
    Outgoing out{std::vector<dist::Bytes>(ranks), std::vector<dist::Bytes>(ranks)};
    for (const bool fill : {false, true}) {
        std::fill(last_rank.begin(), last_rank.end(), none);
        std::vector<std::uint32_t> sent(ranks, 0);  // vertices listed for each rank so far
        for (std::size_t i = 0; i < surface.faces.size(); ++i) {
            const dist::SurfaceFace& f = surface.faces[i];
            constexpr std::size_t drop_every = std::size_t{1} << 16;
            if (fill && i % drop_every == 0) {
                dist::drop_pages(surface.faces.data(), surface.faces.data() + i);
            }
            const RankRange to = destinations(f, surface.vertices);
            for (std::size_t r = to.first; r <= to.last && r < ranks; ++r) {
                dist::SurfaceFace there = f;
                for (std::uint32_t& v : there.v) {
                    if (last_rank[v] != r) {
                        last_rank[v] = r;
                        index_there[v] = sent[r]++;
                        if (fill) dist::append_value(out.vertices[r], surface.vertices[v]);
                    }
                    v = index_there[v];
                }
                if (fill) {
                    dist::append_value(out.faces[r], there);
                } else {
                    ++face_count[r];
                }
            }
        }
        if (fill) break;
        for (std::size_t r = 0; r < ranks; ++r) {
            out.vertices[r].reserve(sent[r] * sizeof(dist::SurfaceVertex));
            out.faces[r].reserve(face_count[r] * sizeof(dist::SurfaceFace));
        }
    }
    return out;
}

template <class T>
T value_at(const dist::Bytes& bytes, std::size_t i) {
    T value;
    std::memcpy(&value, bytes.data() + i * sizeof(T), sizeof(T));
    return value;
}

}  // namespace

Tin route_faces(dist::Comm& comm,
                dist::SurfaceMesh surface,
                const Destinations& destinations,
                Links links) {
    const auto p = static_cast<std::size_t>(comm.size());
    Outgoing out = outgoing_lists(p, surface, destinations);
    surface = {};
    auto got_vertices = comm.alltoallv(std::move(out.vertices));
    auto got_faces = comm.alltoallv(std::move(out.faces));

    // Vertices once each in ascending number, read in place from what was received.
    struct Received {
        std::uint64_t id;
        std::uint32_t source, index;
    };
    std::vector<Received> order;
    std::vector<std::size_t> offset;  // of each source's vertices in the received order
    for (std::size_t src = 0; src < p; ++src) {
        offset.push_back(order.size());
        const std::size_t n = got_vertices[src].size() / sizeof(dist::SurfaceVertex);
        for (std::size_t i = 0; i < n; ++i) {
            order.push_back({value_at<dist::SurfaceVertex>(got_vertices[src], i).id,
                             static_cast<std::uint32_t>(src), static_cast<std::uint32_t>(i)});
        }
    }
    offset.push_back(order.size());
    std::sort(order.begin(), order.end(), [](const Received& a, const Received& b) {
        return std::tie(a.id, a.source, a.index) < std::tie(b.id, b.source, b.index);
    });
    Tin tin;
    std::vector<VertexIndex> vertex_of(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        const Received& r = order[i];
        if (i == 0 || order[i - 1].id != r.id) {
            tin.vertices.push_back(
                value_at<dist::SurfaceVertex>(got_vertices[r.source], r.index).p);
        }
        vertex_of[offset[r.source] + r.index] = static_cast<VertexIndex>(tin.vertices.size() - 1);
    }
    std::vector<Received>().swap(order);
    std::vector<dist::Bytes>().swap(got_vertices);

    const auto triangle_of = [&](std::size_t src, const dist::SurfaceFace& f) {
        Triangle t;
        for (unsigned i = 0; i < 3; ++i) {
            t.v[i] = vertex_of[offset[src] + f.v[i]];
            t.n[i] = (f.border >> i & 1U) != 0 ? no_triangle : 0;
        }
        return t;
    };
    std::size_t face_count = 0;
    for (const dist::Bytes& bytes : got_faces)
        face_count += bytes.size() / sizeof(dist::SurfaceFace);
    if (links == Links::border_only) {
        // The rasteriser reads no triangle or vertex order: the faces as received.
        tin.triangles.reserve(face_count);
        for (std::size_t src = 0; src < p; ++src) {
            const std::size_t n = got_faces[src].size() / sizeof(dist::SurfaceFace);
            for (std::size_t i = 0; i < n; ++i)
                tin.triangles.push_back(
                    triangle_of(src, value_at<dist::SurfaceFace>(got_faces[src], i)));
            dist::Bytes().swap(got_faces[src]);
        }
        ::dtm::detail::make_vertices_coherent(tin);  // rasterize then reads it without a copy
        return tin;
    }
    std::vector<std::pair<std::uint64_t, Triangle>> ordered;  // (serial index, triangle)
    ordered.reserve(face_count);
    for (std::size_t src = 0; src < p; ++src) {
        const std::size_t n = got_faces[src].size() / sizeof(dist::SurfaceFace);
        for (std::size_t i = 0; i < n; ++i) {
            const auto f = value_at<dist::SurfaceFace>(got_faces[src], i);
            ordered.emplace_back(f.face, triangle_of(src, f));
        }
        dist::Bytes().swap(got_faces[src]);
    }
    std::sort(ordered.begin(), ordered.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    tin.triangles.reserve(ordered.size());
    for (const auto& [face, t] : ordered) tin.triangles.push_back(t);
    link_neighbours(tin);
    return tin;
}

std::filesystem::path piece_path(const std::filesystem::path& target,
                                 int rank,
                                 int ranks,
                                 const char* extension) {
    return target.parent_path() / (target.stem().string() + "-" + std::to_string(rank) + "-of-" +
                                   std::to_string(ranks) + "." + extension);
}

}  // namespace dtm::products::detail
