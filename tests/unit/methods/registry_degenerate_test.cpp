// SPDX-License-Identifier: MIT
// Every method of the registry on the degenerate point sets (issue 11 part 1, issue 12): a grid
// (every unit square cocircular), points on one circle, collinear runs and exact duplicates, in
// plain and S-JTSK survey-millimetre coordinates. Each result passes the shared validator of its
// kind: a Delaunay triangulation (exact empty circles, every distinct point a vertex in input
// order, the convex hull, 2n-2-h triangles) for the Delaunay methods, the same minus the empty
// circles for the other triangulations, verify_voronoi for the Voronoi diagrams (and their dual
// as a Delaunay triangulation), check_pseudo_triangulation for pseudo-triangulations, every
// enumerated triangulation for enumerate. All points on one line and fewer than three distinct
// points must be refused with an InputError, never a crash or an invalid mesh.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/methods/registry.hpp"
#include "dtm/methods/voronoi.hpp"
#include "methods/pseudo.hpp"
#include "methods_fixtures.hpp"

namespace dtm::methods {
namespace {

using test::is_delaunay_triangulation;
using test::is_triangulation;

struct NamedSet {
    std::string name;
    std::vector<Point3> points;
};

/// The degenerate sets, @p n points each (enumerate gets small ones).
std::vector<NamedSet> degenerate_sets(std::size_t n) {
    std::vector<NamedSet> sets;
    for (const Distribution d : {Distribution::grid, Distribution::circle, Distribution::collinear,
                                 Distribution::duplicates}) {
        const std::string name(distribution_name(d));
        sets.push_back({name, generate_points(d, n, 3)});
        sets.push_back({name + "/sjtsk-mm", generate_points(d, n, 4, test::sjtsk_mm())});
    }
    return sets;
}

::testing::AssertionResult valid_result(const MethodInfo& m,
                                        const MethodResult& r,
                                        std::span<const Point3> pts) {
    switch (m.output) {
        case Output::triangulation:
            return m.family == Family::delaunay ? is_delaunay_triangulation(r.tin, pts)
                                                : is_triangulation(r.tin, pts);
        case Output::voronoi: {
            const CheckReport report = verify_voronoi(r.voronoi, pts);
            if (!report.ok()) return ::testing::AssertionFailure() << report.text();
            return is_delaunay_triangulation(r.tin, pts);
        }
        case Output::polygon_faces: {
            const std::vector<std::string> problems =
                check_pseudo_triangulation(r.tin.vertices, r.faces);
            if (!problems.empty()) return ::testing::AssertionFailure() << problems.front();
            if (r.tin.vertices.size() != test::distinct_points(pts).size()) {
                return ::testing::AssertionFailure() << "not every distinct point is a vertex";
            }
            return ::testing::AssertionSuccess();
        }
        case Output::all_triangulations: {
            if (r.all.empty()) return ::testing::AssertionFailure() << "no triangulation";
            for (const Tin& t : r.all) {
                auto ok = is_triangulation(t, pts);
                if (!ok) return ok;
            }
            return ::testing::AssertionSuccess();
        }
    }
    return ::testing::AssertionFailure() << "unknown output kind";
}

MethodResult run(const MethodInfo& m, std::span<const Point3> pts) {
    return m.run(MethodInput{pts, {}}, MethodOptions{}, Progress{});
}

TEST(RegistryDegenerate, EveryMethodGivesAValidResultOnDegenerateSets) {
    const std::vector<NamedSet> sets = degenerate_sets(64);
    const std::vector<NamedSet> small = degenerate_sets(9);
    for (const MethodInfo& m : registry()) {
        const bool tiny = m.output == Output::all_triangulations;
        for (const NamedSet& set : tiny ? small : sets) {
            SCOPED_TRACE(std::string(m.name) + " on " + set.name);
            MethodResult r;
            ASSERT_NO_THROW(r = run(m, set.points));
            EXPECT_TRUE(valid_result(m, r, set.points));
        }
    }
}

TEST(RegistryDegenerate, EveryMethodRefusesInputWithoutATriangle) {
    std::vector<Point3> line;
    for (int i = 0; i < 20; ++i) line.push_back({i * 0.5, 3.0 + i * 0.25, 1.0});
    const std::vector<NamedSet> sets{
        {"one line", line},
        {"two distinct points", {{0, 0, 1}, {1, 1, 2}, {0, 0, 3}, {1, 1, 4}}},
        {"one point", {{5, 5, 5}}},
        {"no point", {}},
    };
    for (const MethodInfo& m : registry()) {
        for (const NamedSet& set : sets) {
            SCOPED_TRACE(std::string(m.name) + " on " + set.name);
            try {
                const MethodResult r = run(m, set.points);
                // A method may also answer with an empty structure (a Voronoi diagram of one
                // generator has one region): no triangle may appear.
                EXPECT_TRUE(r.tin.triangles.empty());
                EXPECT_TRUE(r.faces.empty());
                EXPECT_TRUE(verify_topology(r.tin).ok());
            } catch (const InputError&) {
                // The documented refusal.
            }
        }
    }
}

}  // namespace
}  // namespace dtm::methods
