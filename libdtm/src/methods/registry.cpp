// SPDX-License-Identifier: MIT
// The explicit table of triangulation methods. Adding a method: its file pair in src/methods/,
// one row here, its section in docs/algorithms/methods.md.
#include "dtm/methods/registry.hpp"

#include <array>

#include "dc.hpp"
#include "lawson_flip.hpp"
#include "randomized_dag.hpp"
#include "voronoi_dc.hpp"
#include "voronoi_incremental.hpp"
#include "voronoi_topological.hpp"

namespace dtm::methods {
namespace {

const std::array kMethods{
    MethodInfo{"dc", Family::delaunay, "000 §3.7; Guibas-Stolfi 1985", "O(n log n) worst case",
               "the production kernel: divide and conquer in parallel tiles, exact merges", true,
               false, Output::triangulation, "", &run_dc},
    MethodInfo{"lawson-flip", Family::delaunay, "000 §2.4.1, §2.3; 004 Alg. 2; 003",
               "O(n^2) flips (004), plus the initial triangulation",
               "Lawson's local improvement: a sweep triangulation, then flips of illegal edges",
               false, true, Output::triangulation, "initial=sweep order=stack|pass",
               &run_lawson_flip},
    MethodInfo{"randomized-dag", Family::delaunay, "003 Alg. 1-4; de Berg et al. ch. 9",
               "O(n log n) expected time, O(n) expected memory",
               "randomized incremental insertion, point location in the history DAG", false, false,
               Output::triangulation, "super-triangle=symbolic|finite", &run_randomized_dag},
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
};

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
