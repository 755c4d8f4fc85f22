// SPDX-License-Identifier: MIT
// The explicit table of triangulation methods. Adding a method: its file pair in src/methods/,
// one row here, its section in docs/algorithms/methods.md.
#include "dtm/methods/registry.hpp"

#include <array>

#include "dc.hpp"
#include "delaunay_distance.hpp"
#include "dewall.hpp"
#include "enumerate.hpp"
#include "greedy.hpp"
#include "greedy_gilbert.hpp"
#include "greedy_naive.hpp"
#include "incremental_kirkpatrick.hpp"
#include "incremental_walk.hpp"
#include "lawson_flip.hpp"
#include "lifting.hpp"
#include "monotone.hpp"
#include "pseudo.hpp"
#include "randomized_dag.hpp"
#include "topological_dc.hpp"
#include "uniform_grid.hpp"
#include "voronoi_dc.hpp"
#include "voronoi_incremental.hpp"
#include "voronoi_topological.hpp"

namespace dtm::methods {
namespace {

// Rows in the order of the sources' chapters (000 §2.4, §3.x; then lecture 003).
// clang-format off
const std::array kMethods{
    MethodInfo{"dc", Family::delaunay, "000 §3.7; Guibas-Stolfi 1985", "O(n log n) worst case",
               "the production kernel: divide and conquer in parallel tiles, exact merges",
               true, false, Output::triangulation, "", &run_dc},
    MethodInfo{"enumerate", Family::enumeration, "000 §2.3 [HOSCH]",
               "O(T n^2) for T triangulations (n <= 12)",
               "every triangulation of up to 12 points and the optimum under each criterion", false,
               true, Output::all_triangulations, "", &run_enumerate},
    MethodInfo{"lawson-flip", Family::delaunay, "000 §2.4.1, §2.3; 004 Alg. 2; 003",
               "O(n^2) flips (004), plus the initial triangulation",
               "Lawson's local improvement: a sweep triangulation, then flips of illegal edges",
               false, true, Output::triangulation, "initial=sweep order=stack|pass",
               &run_lawson_flip},
    MethodInfo{"delaunay-distance", Family::delaunay, "004; 000 §2.4.3",
               "O(n^2); O(n log n) with suitable structures, O(n) for regular input (004)",
               "incremental construction by Delaunay distance with an active edge list",
               false, true, Output::triangulation, "", &run_delaunay_distance},
    MethodInfo{"lifting", Family::delaunay, "000 §2.4.4; Brown 1979, Clarkson-Shor 1989",
               "O(n log n) expected (randomized 3-D hull)",
               "lower convex hull of the points lifted to the paraboloid (exact orient3d)",
               false, false, Output::triangulation, "", &run_lifting},
    MethodInfo{"greedy-naive", Family::greedy, "000 §3.1a; 004 Alg. 1; Preparata-Shamos 1985",
               "O(n^3)",
               "greedy triangulation: all pairs by length, each tested against every edge", true,
               true, Output::triangulation, "", &run_greedy_naive},
    MethodInfo{"greedy-gilbert", Family::greedy, "000 §3.1b, §3.1.1; Gilbert 1979",
               "O(n^2 log n) time, O(n^2) memory",
               "greedy triangulation with one segment tree per point (at most 5000 points)", true,
               true, Output::triangulation, "", &run_greedy_gilbert},
    MethodInfo{"greedy", Family::greedy, "000 §3.1; Dickerson et al. 1997",
               "O(n log n) observed on uniform points",
               "greedy triangulation by length phases among still-open points (same edges)", true,
               false, Output::triangulation, "", &run_greedy},
    MethodInfo{"monotone", Family::constrained, "000 §3.2; Preparata-Shamos 1985", "O(n log n)",
               "constrained triangulation: regularisation by two plane sweeps, y-monotone "
               "polygons by the stack method",
               true, false, Output::triangulation, "domain=hull|rectangle", &run_monotone},
    MethodInfo{"voronoi-dc", Family::voronoi, "000 §3.4; Shamos-Hoey 1975", "O(n log n)",
               "Voronoi diagram by divide and conquer: the dividing chain sigma on a DCEL", false,
               false, Output::voronoi, "", &run_voronoi_dc},
    MethodInfo{"voronoi-incremental", Family::voronoi, "000 §3.5; Green-Sibson 1978",
               "O(n) average, O(n^2) worst",
               "incremental Voronoi diagram with three auxiliary generators, trusting each sign",
               false, false, Output::voronoi, "faults=P (test: corrupt in-circle signs)",
               &run_voronoi_incremental},
    MethodInfo{"voronoi-topological", Family::voronoi, "000 §3.6; Sugihara-Iri 1992",
               "O(n) average, O(n^2) worst",
               "topology-oriented incremental Voronoi diagram: valid topology under any signs",
               false, false, Output::voronoi, "faults=P (test: corrupt in-circle signs)",
               &run_voronoi_topological},
    MethodInfo{"topological-dc", Family::delaunay, "000 §3.7; Oishi and Sugihara 1993 [OIS93]",
               "O(N log N) average and worst case (000)",
               "topology-oriented divide and conquer: Guibas-Stolfi merge under conditions 1-6",
               false, false, Output::triangulation, "", &run_topological_dc},
    MethodInfo{"incremental-walk", Family::delaunay, "000 §3.8, §3.8.1",
               "O(N^2) (000); O(N^{1/2}) per walk for sorted input",
               "incremental insertion on a winged-edge structure, point location by walking",
               false, false, Output::triangulation, "order=hilbert|random|input",
               &run_incremental_walk},
    MethodInfo{"incremental-kirkpatrick", Family::delaunay, "000 §3.8, §3.8.2; Kirkpatrick 1983",
               "O(log N) location, O(N) space, O(N log N) preprocessing (000)",
               "incremental insertion on a winged-edge structure, Kirkpatrick's hierarchy",
               false, false, Output::triangulation, "", &run_incremental_kirkpatrick},
    MethodInfo{"dewall", Family::delaunay, "000 §3.9; Cignoni et al. 1992 [CIG92]",
               "O(N log N) (000)",
               "DeWall: the wall across the cut first, then both halves in parallel (TBB)",
               false, false, Output::triangulation, "", &run_dewall},
    MethodInfo{"uniform-grid", Family::delaunay, "000 §3.10; Fang and Piegl 1993",
               "O(N) (000, measured on a 486: Fig. 36)",
               "uniform-grid advancing front with the vertex-list output (the thesis' method)",
               false, false, Output::triangulation, "tol=<distance>", &run_uniform_grid},
    MethodInfo{"randomized-dag", Family::delaunay, "003 Alg. 1-4; de Berg et al. ch. 9",
               "O(n log n) expected time, O(n) expected memory",
               "randomized incremental insertion, point location in the history DAG",
               false, false, Output::triangulation,
               "super-triangle=symbolic|finite order=brio|random", &run_randomized_dag},
    MethodInfo{"pseudo", Family::pseudo, "001 (Hobza 2010, Trcka 2007)",
               "O(n log n) observed (001 §4.1)",
               "pseudo-triangulation by incremental insertion with the generalized flip", false,
               false, Output::polygon_faces,
               "swap=none|post|incremental flip=brute|fast criterion=random|min-length|"
               "max-length|maxmin-angle|minmax-angle|maxmin-sum-angle|minmax-sum-angle|"
               "maxmin-angle-hull|minmax-angle-hull",
               &run_pseudo},
};
// clang-format on

}  // namespace

std::span<const MethodInfo> registry() { return kMethods; }

const MethodInfo* find_method(std::string_view name) {
    for (const MethodInfo& m : kMethods) {
        if (m.name == name) return &m;
    }
    return nullptr;
}

std::string_view family_name(Family family) {
    switch (family) {
        case Family::delaunay:
            return "delaunay";
        case Family::voronoi:
            return "voronoi";
        case Family::optimal:
            return "optimal";
        case Family::greedy:
            return "greedy";
        case Family::constrained:
            return "constrained";
        case Family::pseudo:
            return "pseudo";
        case Family::enumeration:
            return "enumeration";
    }
    return "?";
}

}  // namespace dtm::methods
