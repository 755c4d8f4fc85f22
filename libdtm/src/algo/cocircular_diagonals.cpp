// SPDX-License-Identifier: MIT
// Data-dependent diagonals where the Delaunay TIN is not unique (cocircular vertices).
//
// Points on a lattice (DEM cell centres, grid surveys) are cocircular in many quadruples; there
// every choice of diagonal is Delaunay and the triangulator decides by a symbolic tie-break.
// For interpolation the heights should decide: Dyn, Levin and Rippa's local optimisation
// procedure (LOP) flips an edge when the sum of a data-dependent cost over the five edges of its
// quadrilateral strictly drops. Here only edges whose quadrilateral is cocircular (exact
// incircle == 0: the quadrilateral is strictly convex and both triangulations share the
// circumcircle) are candidates, so the TIN stays (constrained) Delaunay; constrained edges are
// never flipped. The cost sums are compared exactly (detail::flip_improves), so each flip
// strictly lowers the total cost and the loop ends; a flip budget guards against the unforeseen.
// The default cost is the jump of the normal derivative across the edge (DLR's JND), which on
// the DEM-sampling cases of bench/compare_accuracy.py gave the Clough-Tocher surface the lowest
// errors of the criteria tried (angle between normals, Clough-Tocher bending energy).
//
// References: N. Dyn, D. Levin and S. Rippa, "Data dependent triangulations for piecewise
// linear interpolation", IMA J. Numer. Anal. 10(1), 1990 (the criteria and the LOP); E. Quak and
// L. L. Schumaker, "Cubic spline fitting using data dependent triangulations", CAGD 7, 1990
// (data-dependent triangulations under C1 cubic interpolants).
#include "dtm/algo/cocircular_diagonals.hpp"

#include <utility>
#include <vector>

#include "algo/detail/tin_flip.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

/// The edge at (t, slot), seen from its smaller triangle, is interior, unconstrained, its
/// quadrilateral cocircular, and a flip lowers the cost.
bool improvable(const Tin& tin,
                const detail::ConstrainedEdgeSet& constrained,
                TriangleIndex t,
                int slot,
                Criterion criterion,
                detail::EdgeQuad& q) {
    q = detail::edge_quad(tin, t, slot);
    if (!q.valid || q.u < t || constrained.contains(q.a, q.b)) return false;
    const auto& p = tin.vertices;
    // t = (c, a, b) counter-clockwise, d beyond ab.
    return geom::incircle(p[q.c], p[q.a], p[q.b], p[q.d]) == 0 &&
           detail::flip_improves(tin, q, criterion);
}

}  // namespace

bool has_improvable_cocircular_edge(const Tin& tin, Criterion criterion) {
    if (!is_data_dependent(criterion)) return false;
    const detail::ConstrainedEdgeSet constrained(tin);
    detail::EdgeQuad q;
    for (TriangleIndex t = 0; t < tin.triangles.size(); ++t) {
        for (int s = 0; s < 3; ++s) {
            if (improvable(tin, constrained, t, s, criterion, q)) return true;
        }
    }
    return false;
}

std::size_t choose_cocircular_diagonals(Tin& tin, Criterion criterion) {
    if (!is_data_dependent(criterion)) return 0;
    const detail::ConstrainedEdgeSet constrained(tin);
    std::vector<std::pair<TriangleIndex, int>> stack;  // edges to test, the first on top
    stack.reserve(3 * tin.triangles.size());
    for (auto t = static_cast<TriangleIndex>(tin.triangles.size()); t-- > 0;) {
        for (int s = 3; s-- > 0;) stack.emplace_back(t, s);
    }
    const std::size_t budget = 4 * stack.size() + 16;
    std::size_t flips = 0;
    detail::EdgeQuad q;
    while (!stack.empty() && flips < budget) {
        auto [t, s] = stack.back();
        stack.pop_back();
        // Test the edge from the triangle with the smaller index.
        const TriangleIndex u = tin.triangles[t].n[s];
        if (u != no_triangle && u < t) {
            const auto& n = tin.triangles[u].n;
            s = n[0] == t ? 0 : (n[1] == t ? 1 : 2);
            t = u;
        }
        if (!improvable(tin, constrained, t, s, criterion, q)) continue;
        detail::flip(tin, q);
        ++flips;
        // The four sides of the quadrilateral may have become improvable.
        for (const TriangleIndex k : {q.t, q.u}) {
            const TriangleIndex other = k == q.t ? q.u : q.t;
            for (int e = 0; e < 3; ++e) {
                if (tin.triangles[k].n[e] != other) stack.emplace_back(k, e);
            }
        }
    }
    return flips;
}

}  // namespace dtm
