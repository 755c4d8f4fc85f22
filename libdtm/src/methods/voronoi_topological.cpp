// SPDX-License-Identifier: MIT
// [voronoi-topological] The topology-oriented incremental Voronoi diagram: K. Sugihara, M. Iri,
// "Construction of the Voronoi diagram for 'one million' generators in single-precision
// arithmetic", Proc. IEEE 80(9), 1992; thesis 000 §3.6.
//
// Topology first, numbers second. Adding generator p to the graph G (auxiliary generators and
// outer curve as in voronoi-incremental) deletes a set T of vertices chosen so that, whatever
// the in-circle signs say, G stays a planar graph whose regions are one per generator and no
// two of which share two edges:
//   B1  T = {the vertex of the nearest generator's region with the smallest H} (C1: T is never
//       empty); H is evaluated in doubles with the cofactors of method 2 (eq. 7-10) and only
//       ranks candidates; among the ranked vertices the first one the exact predicate puts
//       inside is taken, so with exact signs T always starts inside;
//   B2  grow T by a vertex adjacent to it when its in-circle sign says inside (H < 0) and
//       (C4) it is adjacent to only one vertex of T (T stays a tree, C2), and (C5) on every
//       region already incident to T it is adjacent to a vertex of T along that region (each
//       region meets T in one piece, C3). Rejected vertices are labelled out; the vertices of
//       the outer curve are out for good. Labels are reset in time proportional to their number.
// Then procedure A (voronoi_incremental_graph.cpp). With exact signs T is exactly the set of
// vertices whose circle contains p (a true conflict vertex adjacent to T never violates C4 or
// C5: a second path to T would close a cycle in the conflict tree). With the test option
// faults=P each sign is corrupted with probability P, and the result is still a valid planar
// graph of n regions (tests/unit/methods/voronoi_topological_test.cpp).
#include "voronoi_topological.hpp"

#include <algorithm>
#include <utility>

namespace dtm::methods {
namespace detail {

void choose_tree_topological(IncrementalVoronoi& graph,
                             std::uint32_t g,
                             const Point2& p,
                             std::vector<std::uint32_t>& tree) {
    (void)g;
    const auto accept = [&](std::uint32_t v) {
        graph.set_label(v, Label::in);
        tree.push_back(v);
        std::uint32_t h = graph.out(v);
        for (int i = 0; i < 3; ++i, h = graph.cw(h)) graph.set_incident(graph.face(h));
    };
    // B1.
    const std::uint32_t near = graph.nearest(p);
    if (near == no_index) {
        accept(0);  // the centre of the three auxiliary generators
    } else {
        std::vector<std::pair<double, std::uint32_t>> ranked;
        const std::uint32_t start = graph.face_edge(near);
        std::uint32_t h = start;
        do {
            ranked.emplace_back(graph.h_value(graph.origin(h), p), graph.origin(h));
            h = graph.next(h);
        } while (h != start);
        std::sort(ranked.begin(), ranked.end());
        std::uint32_t chosen = ranked.front().second;
        for (const auto& [value, v] : ranked) {
            if (graph.inside(v, p) > 0) {
                chosen = v;
                break;
            }
        }
        accept(chosen);
    }
    // B2: breadth first over the vertices adjacent to T.
    std::size_t head = 0;
    std::vector<std::uint32_t> queue;
    const auto push_neighbours = [&](std::uint32_t v) {
        std::uint32_t h = graph.out(v);
        for (int i = 0; i < 3; ++i, h = graph.cw(h)) {
            if (graph.label(graph.dest(h)) == Label::unknown) queue.push_back(graph.dest(h));
        }
    };
    push_neighbours(tree.front());
    while (head < queue.size()) {
        const std::uint32_t v = queue[head++];
        if (graph.label(v) != Label::unknown) continue;
        if (graph.on_curve(v)) {
            graph.set_label(v, Label::out);
            continue;
        }
        const std::uint32_t h0 = graph.out(v);
        const std::uint32_t n[3] = {graph.dest(h0), graph.dest(graph.cw(h0)),
                                    graph.dest(graph.ccw(h0))};
        const auto in = [&](std::uint32_t u) { return graph.label(u) == Label::in; };
        // C4: adjacent to one vertex of T only.
        bool ok = (in(n[0]) ? 1 : 0) + (in(n[1]) ? 1 : 0) + (in(n[2]) ? 1 : 0) == 1;
        // C5: along each region already incident to T, adjacent to a vertex of T.
        std::uint32_t h = h0;
        for (int i = 0; i < 3 && ok; ++i, h = graph.cw(h)) {
            if (graph.incident(graph.face(h)))
                ok = in(graph.dest(h)) || in(graph.dest(graph.ccw(h)));
        }
        if (ok && graph.inside(v, p) > 0) {
            accept(v);
            push_neighbours(v);
        } else {
            graph.set_label(v, Label::out);
        }
    }
}

}  // namespace detail

MethodResult run_voronoi_topological(const MethodInput& input,
                                     const MethodOptions& options,
                                     const Progress& progress) {
    return detail::run_incremental(input, options, progress, "voronoi-topological",
                                   &detail::choose_tree_topological);
}

}  // namespace dtm::methods
