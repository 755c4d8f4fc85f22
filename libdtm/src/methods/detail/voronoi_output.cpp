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
#include <bit>
#include <cmath>
#include <numeric>
#include <string>

#include "algo/detail/exact_duplicates.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/constructions.hpp"
#include "methods/detail/method_support.hpp"

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

/// The kept edges of the working graph as a bit set with ranks: the output index of kept
/// half-edge h is 2 rank(h / 2) + h % 2 (twins stay adjacent), a quarter bit per half-edge
/// instead of an index table.
class EdgeRank {
public:
    explicit EdgeRank(std::size_t edges) : bits_((edges + 63) / 64, 0), before_(bits_.size() + 1) {}
    void set(std::size_t e) { bits_[e / 64] |= std::uint64_t{1} << (e % 64); }
    void finish() {
        for (std::size_t i = 0; i < bits_.size(); ++i) {
            before_[i + 1] = before_[i] + static_cast<std::uint32_t>(std::popcount(bits_[i]));
        }
    }
    [[nodiscard]] bool kept(std::uint32_t h) const {
        const std::uint32_t e = h / 2;
        return ((bits_[e / 64] >> (e % 64)) & 1u) != 0;
    }
    [[nodiscard]] std::uint32_t out(std::uint32_t h) const {
        const std::uint32_t e = h / 2;
        const std::uint64_t below = (std::uint64_t{1} << (e % 64)) - 1;
        return 2 * (before_[e / 64] +
                    static_cast<std::uint32_t>(std::popcount(bits_[e / 64] & below))) +
               (h & 1u);
    }
    [[nodiscard]] std::uint32_t half_edges() const { return 2 * before_.back(); }

private:
    std::vector<std::uint64_t> bits_;
    std::vector<std::uint32_t> before_;
};

/// The dual Tin's triangles (faces: distinct generator ids < @p real): a fan per Voronoi
/// vertex, its generators counter-clockwise from the one left of its last out half-edge, the
/// links made from the corners. The rotation around a vertex is walked backwards, next(twin),
/// which needs no table of predecessors.
void dual_triangles(const VoronoiDiagram& d,
                    std::uint32_t real,
                    Tin& tin,
                    const Progress& progress) {
    const auto& he = d.half_edges;
    const std::size_t nv = d.vertices.size();
    std::vector<std::uint32_t> out(nv, no_index);
    std::size_t corners = 0;
    for (std::uint32_t h = 0; h < he.size(); ++h) {
        if (he[h].origin == no_index) continue;
        out[he[h].origin] = h;
        ++corners;
    }
    tin.triangles.reserve(corners - 2 * nv);  // sum of (degree - 2)
    std::vector<std::uint32_t> around;
    for (std::uint32_t v = 0; v < nv; ++v) {
        if ((v & 0xffffu) == 0) progress.check();
        around.clear();
        std::uint32_t h = out[v];
        do {
            around.push_back(h);
            h = he[h ^ 1u].next;
        } while (h != out[v]);
        std::reverse(around.begin() + 1, around.end());
        const auto g = [&](std::size_t i) { return he[around[i]].face; };
        for (std::size_t j = 0; j + 2 < around.size(); ++j) {
            Triangle t;
            t.v = {g(0), g(j + 1), g(j + 2)};
            tin.triangles.push_back(t);
        }
    }
    free_storage(out);
    link_in_place(tin.triangles, real);
}

}  // namespace

Sites make_sites(std::span<const Point3> points, const char* method) {
    Sites s;
    const auto first = dtm::detail::first_occurrences(points);
    s.first.assign(first.begin(), first.end());
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < points.size(); ++i) distinct += s.first[i] == i ? 1 : 0;
    s.xy.reserve(distinct + 3);  // exact: the incremental methods append 3 auxiliaries
    s.input.reserve(distinct);
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
                    Sites&& sites,
                    std::span<const Point3> input,
                    const FinishOptions& options,
                    CountingPredicates& predicates,
                    MethodResult& result,
                    const Progress& progress) {
    // The result (about 180 bytes per generator: the diagram, the Tin) is built over the
    // working graph and with little else alive: the output half-edges are compacted in place,
    // their indices ranked from a bit set, the sites freed as soon as each part is done.
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
    EdgeRank rank(nh / 2);
    std::uint64_t merges = 0;
    for (std::uint32_t h = 0; h < nh; h += 2) {
        if (!kept_edge(h)) continue;
        const std::uint32_t u = he[h].origin;
        const std::uint32_t w = he[h ^ 1u].origin;
        if (options.exact && u != no_index && w != no_index && state[u] == 1 && state[w] == 1) {
            const Point2& a = sites.xy[he[h].face];
            const Point2& b = sites.xy[he[h ^ 1u].face];
            const Point2& c = sites.xy[he[he[h ^ 1u].next ^ 1u].face];
            const Point2& d = sites.xy[he[he[h].next ^ 1u].face];
            if (predicates.incircle(a, b, c, d) == 0) {
                const std::uint32_t ru = find_root(id, u);
                const std::uint32_t rw = find_root(id, w);
                if (ru != rw) id[ru] = rw;
                ++merges;
                continue;  // contracted
            }
        }
        rank.set(h / 2);
    }
    rank.finish();
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
    free_storage(id);
    const auto finite = [&](std::uint32_t u) { return u != no_index && state[u] == 1; };
    // Positions: the circumcentre seen from the first output half-edge out of the vertex.
    std::vector<Point2> positions(nv);
    {
        std::vector<bool> placed(nv, false);
        for (std::uint32_t h = 0; h < nh; ++h) {
            const std::uint32_t u = he[h].origin;
            if (!rank.kept(h) || !finite(u) || placed[vertex_of[u]]) continue;
            placed[vertex_of[u]] = true;
            positions[vertex_of[u]] =
                geom::circumcentre(sites.xy[he[h].face], sites.xy[he[h ^ 1u].face],
                                   sites.xy[he[he[h ^ 1u].next ^ 1u].face]);
        }
    }
    free_storage(sites.xy);
    free_storage(sites.first);
    // next: past the auxiliary and zero-length edges (only kept half-edges are rewritten, and
    // the walks only read the others).
    for (std::uint32_t h = 0; h < nh; ++h) {
        if (!rank.kept(h)) continue;
        std::uint32_t x = he[h].next;
        while (!rank.kept(x)) x = he[x].next;
        he[h].next = x;
    }
    // Output half-edges, in order, over the working ones (output index <= working index).
    std::vector<std::uint32_t> face_edge(real, VoronoiDiagram::none);  // by distinct generator
    std::uint64_t unbounded = 0;
    for (std::uint32_t h = 0; h < nh; ++h) {
        if (!rank.kept(h)) continue;
        const std::uint32_t o = rank.out(h);
        const HalfEdge from = he[h];
        const bool at_finite = finite(from.origin);
        HalfEdge& e = he[o];
        e.origin = at_finite ? vertex_of[from.origin] : VoronoiDiagram::none;
        e.next = rank.out(from.next);
        e.face = from.face;
        if (face_edge[e.face] == VoronoiDiagram::none) face_edge[e.face] = o;
        if (!at_finite && (o % 2 == 0 || he[o - 1].origin != VoronoiDiagram::none)) {
            ++unbounded;  // once per edge with an end at infinity (both twins are seen)
        }
    }
    const std::uint32_t no = rank.half_edges();
    he.resize(no);
    free_storage(state);
    free_storage(vertex_of);
    VoronoiDiagram& d = result.voronoi;
    d.vertices = std::move(positions);
    d.half_edges = std::move(he);
    std::uint64_t max_degree = 0;
    {
        std::vector<std::uint32_t> degree(nv, 0);
        for (const HalfEdge& e : d.half_edges) {
            if (e.origin != VoronoiDiagram::none)
                max_degree = std::max<std::uint64_t>(max_degree, ++degree[e.origin]);
        }
    }
    // The dual Tin: the distinct points as vertices, a fan per Voronoi vertex.
    Tin& tin = result.tin;
    if (options.exact) dual_triangles(d, real, tin, progress);
    tin.vertices.reserve(real);
    for (std::uint32_t i = 0; i < real; ++i) tin.vertices.push_back(input[sites.input[i]]);
    // Faces by input point: sites.input is increasing, so the move runs from the back.
    for (HalfEdge& e : d.half_edges) e.face = sites.input[e.face];
    face_edge.resize(input.size(), VoronoiDiagram::none);
    for (std::uint32_t k = real; k-- > 0;) {
        const std::uint32_t edge = face_edge[k];
        face_edge[k] = VoronoiDiagram::none;
        face_edge[sites.input[k]] = edge;
    }
    d.face_edge = std::move(face_edge);
    free_storage(sites.input);
    auto& extra = result.counters.extra;
    extra["voronoi_vertices"] = nv;
    extra["voronoi_edges"] = no / 2;
    extra["unbounded_edges"] = unbounded;
    extra["cocircular_merges"] = merges;
    extra["max_vertex_degree"] = max_degree;
    extra["duplicates"] = input.size() - real;
}

}  // namespace dtm::methods::detail
