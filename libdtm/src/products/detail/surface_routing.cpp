// SPDX-License-Identifier: MIT
// Routing the TIN's faces to the ranks that need them (surface_routing.hpp): per destination a
// list of the vertices its faces name and the faces with indices into that list (16-24 bytes a
// face and 32 a vertex instead of three coordinates per corner), one alltoallv each; the
// receiver numbers the vertices by one sort of (number, received index) and orders the faces by
// their serial index, so the rebuilt Tin keeps the serial TIN's relative orders.
#include "products/detail/surface_routing.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace dtm::products::detail {

Tin route_faces(dist::Comm& comm,
                dist::SurfaceMesh surface,
                const Destinations& destinations,
                Links links) {
    const auto p = static_cast<std::size_t>(comm.size());
    std::vector<dist::Bytes> vertices(p), faces(p);
    std::vector<std::uint32_t> sent(p, 0);  // vertices sent to each rank so far
    constexpr std::size_t none = ~std::size_t{0};
    std::vector<std::size_t> last_rank(surface.vertices.size(), none);
    std::vector<std::uint32_t> index_there(surface.vertices.size(), 0);
    for (const dist::SurfaceFace& f : surface.faces) {
        const RankRange to = destinations(f, surface.vertices);
        for (std::size_t r = to.first; r <= to.last && r < p; ++r) {
            dist::SurfaceFace there = f;
            for (std::uint32_t& v : there.v) {
                if (last_rank[v] != r) {
                    last_rank[v] = r;
                    index_there[v] = sent[r]++;
                    dist::append_value(vertices[r], surface.vertices[v]);
                }
                v = index_there[v];
            }
            dist::append_value(faces[r], there);
        }
    }
    surface = {};
    std::vector<std::size_t>().swap(last_rank);
    std::vector<std::uint32_t>().swap(index_there);
    const auto got_vertices = comm.alltoallv(std::move(vertices));
    const auto got_faces = comm.alltoallv(std::move(faces));

    std::vector<std::pair<std::uint64_t, std::uint64_t>> order;  // (number, received index)
    std::vector<Point3> received;
    std::vector<std::size_t> offset;  // of each source's vertices in `received`
    for (const dist::Bytes& bytes : got_vertices) {
        offset.push_back(received.size());
        for (const dist::SurfaceVertex& v : dist::from_bytes<dist::SurfaceVertex>(bytes)) {
            order.emplace_back(v.id, received.size());
            received.push_back(v.p);
        }
    }
    std::sort(order.begin(), order.end());
    Tin tin;
    std::vector<VertexIndex> vertex_of(received.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (i == 0 || order[i - 1].first != order[i].first) {
            tin.vertices.push_back(received[order[i].second]);
        }
        vertex_of[order[i].second] = static_cast<VertexIndex>(tin.vertices.size() - 1);
    }
    std::vector<std::pair<std::uint64_t, Triangle>> ordered;  // (serial index, triangle)
    for (std::size_t src = 0; src < got_faces.size(); ++src) {
        for (const dist::SurfaceFace& f : dist::from_bytes<dist::SurfaceFace>(got_faces[src])) {
            Triangle t;
            for (unsigned i = 0; i < 3; ++i) {
                t.v[i] = vertex_of[offset[src] + f.v[i]];
                t.n[i] = (f.border >> i & 1U) != 0 ? no_triangle : 0;
            }
            ordered.emplace_back(f.face, t);
        }
    }
    std::sort(ordered.begin(), ordered.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    tin.triangles.reserve(ordered.size());
    for (const auto& [face, t] : ordered) tin.triangles.push_back(t);
    if (links == Links::shared_edges) link_neighbours(tin);
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
