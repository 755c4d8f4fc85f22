// SPDX-License-Identifier: MIT
// From a Voronoi method's working graph to MethodResult (voronoi_output.hpp).
//
// Degenerate vertices. The methods build graphs whose vertices all have degree 3; where k > 3
// generators are cocircular they leave k - 3 edges of length zero between vertices at the same
// centre. Here such an edge (between vertices u and w, regions a | b, the third regions c at u
// and d at w) is recognised exactly, incircle(a, b, c, d) == 0, and contracted: the output has
// one vertex of degree k, whose k generators, counter-clockwise on their circle, are the
// corners of a convex cocircular face of the Delaunay graph. The dual Tin fans such a face
// from its first generator (any triangulation of a cocircular polygon is Delaunay).
#include "methods/detail/voronoi_output.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "algo/detail/exact_duplicates.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/constructions.hpp"

namespace dtm::methods::detail {
namespace {

using HalfEdge = VoronoiDiagram::HalfEdge;

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

/// Faces around each output vertex and the dual Tin's triangles with their neighbours.
class DualTin {
public:
    DualTin(const VoronoiDiagram& d, std::vector<std::uint32_t> distinct_of_face)
        : d_(d), dist_(std::move(distinct_of_face)) {}

    void build(Tin& tin, const Progress& progress) {
        const auto& he = d_.half_edges;
        prev_.assign(he.size(), no_index);
        for (std::uint32_t h = 0; h < he.size(); ++h) prev_[he[h].next] = h;
        const std::size_t nv = d_.vertices.size();
        out_.assign(nv, no_index);
        for (std::uint32_t h = 0; h < he.size(); ++h) {
            if (he[h].origin != no_index) out_[he[h].origin] = h;
        }
        rot_.assign(he.size(), 0);
        first_.assign(nv + 1, 0);
        for (std::uint32_t v = 0; v < nv; ++v) {
            std::uint32_t h = out_[v];
            std::uint32_t i = 0;
            do {
                rot_[h] = i++;
                h = prev_[h] ^ 1u;
            } while (h != out_[v]);
            first_[v + 1] = first_[v] + (i - 2);
        }
        tin.triangles.resize(first_[nv]);
        std::vector<std::uint32_t> around;
        for (std::uint32_t v = 0; v < nv; ++v) {
            if ((v & 0xffffu) == 0) progress.check();
            around.clear();
            std::uint32_t h = out_[v];
            do {
                around.push_back(h);
                h = prev_[h] ^ 1u;
            } while (h != out_[v]);
            fan(v, around, tin);
        }
    }

private:
    const VoronoiDiagram& d_;
    std::vector<std::uint32_t> dist_;
    std::vector<std::uint32_t> prev_, out_, rot_, first_;

    /// Triangle of vertex v's fan that holds the Delaunay edge dual to its i-th out half-edge
    /// (between its faces i-1 and i).
    [[nodiscard]] std::uint32_t triangle_of(std::uint32_t v, std::uint32_t i) const {
        const std::uint32_t k = first_[v + 1] - first_[v] + 2;
        const std::uint32_t edge = (i + k - 1) % k;  // polygon edge (g_edge, g_edge+1)
        const std::uint32_t j = edge == 0 ? 0 : (edge == k - 1 ? k - 3 : edge - 1);
        return first_[v] + j;
    }

    [[nodiscard]] TriangleIndex across(std::uint32_t h) const {
        const std::uint32_t t = h ^ 1u;
        const std::uint32_t w = d_.half_edges[t].origin;
        if (w == no_index) return no_triangle;
        return triangle_of(w, rot_[t]);
    }

    void fan(std::uint32_t v, const std::vector<std::uint32_t>& h, Tin& tin) const {
        const auto k = static_cast<std::uint32_t>(h.size());
        const auto g = [&](std::uint32_t i) { return dist_[d_.half_edges[h[i]].face]; };
        for (std::uint32_t j = 0; j + 2 < k; ++j) {
            Triangle& t = tin.triangles[first_[v] + j];
            t.v = {g(0), g(j + 1), g(j + 2)};
            t.n[0] = across(h[j + 2]);
            t.n[1] = j + 3 == k ? across(h[0]) : first_[v] + j + 1;
            t.n[2] = j == 0 ? across(h[1]) : first_[v] + j - 1;
        }
    }
};

}  // namespace

Sites make_sites(std::span<const Point3> points, const char* method) {
    Sites s;
    const auto first = dtm::detail::first_occurrences(points);
    s.first.assign(first.begin(), first.end());
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (s.first[i] == i) {
            s.xy.push_back(points[i].xy());
            s.input.push_back(static_cast<VertexIndex>(i));
        }
    }
    s.real = static_cast<std::uint32_t>(s.xy.size());
    if (s.real < 2) {
        throw InputError(std::string("method ") + method +
                         ": needs at least two distinct points (got " + std::to_string(s.real) +
                         ")");
    }
    return s;
}

void finish_voronoi(VoronoiGraph&& graph,
                    const Sites& sites,
                    std::span<const Point3> input,
                    const FinishOptions& options,
                    CountingPredicates& predicates,
                    MethodResult& result,
                    const Progress& progress) {
    std::vector<HalfEdge>& he = graph.he;
    const std::uint32_t real = sites.real;
    const auto nh = static_cast<std::uint32_t>(he.size());
    const auto face_real = [&](std::uint32_t h) { return he[h].face < real; };
    const auto kept_edge = [&](std::uint32_t h) { return face_real(h) && face_real(h ^ 1u); };

    // Vertices: 0 unused, 1 finite, 2 at infinity (an auxiliary generator is one of its own).
    std::vector<std::uint8_t> state(graph.vertex_count, 0);
    for (std::uint32_t h = 0; h < nh; ++h) {
        const std::uint32_t o = he[h].origin;
        if (he[h].face == dead_face || o == no_index) continue;
        state[o] = std::max<std::uint8_t>(state[o], face_real(h) ? 1 : 2);
    }
    // Zero-length edges between finite vertices: cocircular generators.
    std::vector<std::uint32_t> id(graph.vertex_count);
    std::iota(id.begin(), id.end(), 0u);
    std::vector<bool> contracted(nh / 2, false);
    std::uint64_t merges = 0;
    if (options.exact) {
        for (std::uint32_t h = 0; h < nh; h += 2) {
            if (!kept_edge(h)) continue;
            const std::uint32_t u = he[h].origin;
            const std::uint32_t w = he[h ^ 1u].origin;
            if (u == no_index || w == no_index || state[u] != 1 || state[w] != 1) continue;
            const Point2& a = sites.xy[he[h].face];
            const Point2& b = sites.xy[he[h ^ 1u].face];
            const Point2& c = sites.xy[he[he[h ^ 1u].next ^ 1u].face];
            const Point2& d = sites.xy[he[he[h].next ^ 1u].face];
            if (predicates.incircle(a, b, c, d) == 0) {
                const std::uint32_t ru = find_root(id, u);
                const std::uint32_t rw = find_root(id, w);
                if (ru != rw) id[ru] = rw;
                contracted[h / 2] = true;
                ++merges;
            }
        }
    }
    progress.check();
    // Output vertices, numbered by their first finite member.
    std::vector<std::uint32_t> vertex_of(graph.vertex_count, no_index);
    std::uint32_t nv = 0;
    for (std::uint32_t v = 0; v < graph.vertex_count; ++v) {
        if (state[v] != 1) continue;
        const std::uint32_t r = find_root(id, v);
        if (vertex_of[r] == no_index) vertex_of[r] = nv++;
        vertex_of[v] = vertex_of[r];
    }
    id = {};
    std::vector<Point2> positions(nv);
    std::vector<bool> placed(nv, false);
    // Output half-edges: the kept, uncontracted ones, in order (twins stay adjacent).
    std::vector<std::uint32_t> out_index(nh, no_index);
    std::uint32_t no = 0;
    for (std::uint32_t h = 0; h < nh; h += 2) {
        if (kept_edge(h) && !contracted[h / 2]) {
            out_index[h] = no++;
            out_index[h + 1] = no++;
        }
    }
    VoronoiDiagram& d = result.voronoi;
    d.half_edges.resize(no);
    d.face_edge.assign(input.size(), VoronoiDiagram::none);
    std::uint64_t unbounded = 0;
    for (std::uint32_t h = 0; h < nh; ++h) {
        const std::uint32_t o = out_index[h];
        if (o == no_index) continue;
        std::uint32_t x = he[h].next;
        while (out_index[x] == no_index) x = he[x].next;  // auxiliary or zero-length edges
        const std::uint32_t u = he[h].origin;
        const bool finite = u != no_index && state[u] == 1;
        HalfEdge& e = d.half_edges[o];
        e.origin = finite ? vertex_of[u] : VoronoiDiagram::none;
        e.next = out_index[x];
        e.face = sites.input[he[h].face];
        if (d.face_edge[e.face] == VoronoiDiagram::none) d.face_edge[e.face] = o;
        if (!finite && (o % 2 == 0 || d.half_edges[o - 1].origin != VoronoiDiagram::none)) {
            ++unbounded;  // once per edge with an end at infinity (both twins are seen)
        }
        if (finite && !placed[e.origin]) {
            placed[e.origin] = true;
            positions[e.origin] =
                geom::circumcentre(sites.xy[he[h].face], sites.xy[he[h ^ 1u].face],
                                   sites.xy[he[he[h ^ 1u].next ^ 1u].face]);
        }
    }
    d.vertices = std::move(positions);
    he = {};
    out_index = {};

    // The dual Tin: the distinct points as vertices, a fan per Voronoi vertex.
    Tin& tin = result.tin;
    tin.vertices.reserve(real);
    for (std::uint32_t i = 0; i < real; ++i) tin.vertices.push_back(input[sites.input[i]]);
    std::uint64_t max_degree = 0;
    if (options.exact) {
        std::vector<std::uint32_t> distinct_of_face(input.size(), no_index);
        for (std::uint32_t i = 0; i < real; ++i) distinct_of_face[sites.input[i]] = i;
        DualTin(d, std::move(distinct_of_face)).build(tin, progress);
    }
    std::vector<std::uint32_t> degree(nv, 0);
    for (const HalfEdge& e : d.half_edges) {
        if (e.origin != VoronoiDiagram::none)
            max_degree = std::max<std::uint64_t>(max_degree, ++degree[e.origin]);
    }
    auto& extra = result.counters.extra;
    extra["voronoi_vertices"] = nv;
    extra["voronoi_edges"] = no / 2;
    extra["unbounded_edges"] = unbounded;
    extra["cocircular_merges"] = merges;
    extra["max_vertex_degree"] = max_degree;
    extra["duplicates"] = input.size() - real;
}

}  // namespace dtm::methods::detail
