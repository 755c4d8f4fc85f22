// SPDX-License-Identifier: MIT
// [voronoi-incremental] The classic incremental Voronoi diagram, thesis 000 §3.5 (after
// Preparata and Shamos 1985; Green and Sibson 1978): start from the diagram of three auxiliary
// generators whose triangle contains every point, so that no region is ever unbounded and no
// new ray appears; for each new generator p locate the region V(i) containing it (the nearest
// generator, by a walk over the diagram itself), then trace the boundary of V(p): the bisector
// of p and p_i cuts V(i) in two points; cross at one into the neighbour V(j), follow V(j) to
// where the bisector of p and p_j leaves it, and so on around until V(i) is reached again.
// Everything inside (the vertices whose circle contains p) is deleted, the traced boundary
// added (procedure A of voronoi_incremental_graph.cpp).
//
// Exact in-circle signs make the traced region always close. This method trusts each sign on
// its own, which is what Sugihara and Iri show breaks under numerical error (000 §3.6, Fig. 1):
// with the test option faults=P (corrupted signs) it stops with an error when the region does
// not close or the deleted vertices do not form a tree, where voronoi-topological goes on.
// Insertion order: along a Hilbert curve, so each location walk is short (Sugihara and Iri use
// buckets for the same purpose). Expected time O(n) after the O(n log n) sort (000 §3.5:
// average O(N), worst O(N^2); the conclusion table's O(N^2 log N) is its erratum 10).
#include "voronoi_incremental.hpp"

#include <string>

#include "dtm/core/error.hpp"

namespace dtm::methods {
namespace detail {

void choose_tree_classic(IncrementalVoronoi& graph,
                         std::uint32_t g,
                         const Point2& p,
                         std::vector<std::uint32_t>& tree) {
    (void)g;
    const auto in = [&](std::uint32_t v) {
        if (graph.label(v) == Label::unknown) {
            const bool inside = graph.inside(v, p) > 0;
            graph.set_label(v, inside ? Label::in : Label::out);
            if (inside) tree.push_back(v);
        }
        return graph.label(v) == Label::in;
    };
    const std::uint32_t near = graph.nearest(p);
    if (near == no_index) {  // the first generator: only the centre of the auxiliary three
        graph.set_label(0, Label::in);
        tree.push_back(0);
        return;
    }
    // Where the bisector of p and p_i leaves V(i): an edge from inside the circle test to
    // outside on V(i)'s boundary.
    const std::uint32_t start = graph.face_edge(near);
    std::uint32_t b0 = no_index;
    std::uint32_t h = start;
    do {
        if (in(graph.origin(h)) && !in(graph.dest(h))) {
            b0 = h;
            break;
        }
        h = graph.next(h);
    } while (h != start);
    if (b0 == no_index) {
        throw Error(
            "voronoi-incremental: the bisector does not cut the nearest region "
            "(inconsistent in-circle signs)");
    }
    // Around the new region: into the region on the other side of each crossed edge, along it
    // to where the next bisector leaves it.
    std::uint32_t b = b0;
    std::size_t guard = 0;
    do {
        std::uint32_t e = graph.next(b ^ 1u);
        while (in(graph.dest(e))) {
            e = graph.next(e);
            if (++guard > 64 + 16 * tree.size()) {
                throw Error(
                    "voronoi-incremental: the new region does not close "
                    "(inconsistent in-circle signs)");
            }
        }
        b = e;
        if (++guard > 64 + 16 * tree.size()) {
            throw Error(
                "voronoi-incremental: the new region does not close "
                "(inconsistent in-circle signs)");
        }
    } while (b != b0);
}

}  // namespace detail

MethodResult run_voronoi_incremental(const MethodInput& input,
                                     const MethodOptions& options,
                                     const Progress& progress) {
    return detail::run_incremental(input, options, progress, "voronoi-incremental",
                                   &detail::choose_tree_classic);
}

}  // namespace dtm::methods
