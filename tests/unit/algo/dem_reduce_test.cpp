// SPDX-License-Identifier: MIT
// reduce_dem: held-out synthetic DEMs (smooth hills, a creased ridge, hashed noise) thinned to
// an error bound are checked cell by cell by an independent scan of the final TIN's triangles
// (barycentric heights, no dtm point location); breaklines stay TIN edges; clipping drops exactly
// the cells within the radius of a survey point or breakline (brute-force distances).
#include "dtm/algo/dem_reduce.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "support/dem_fixtures.hpp"

namespace {

using dtm::Point3;

using dtm::test::Dem;
using dtm::test::make_dem;
using dtm::test::worst_cell_error;

double hills(double x, double y) {
    return 300.0 + 8.0 * std::sin(x / 17.0) * std::cos(y / 23.0) + 0.02 * x * y / 50.0;
}
double ridge(double x, double y) { return 250.0 - 0.4 * std::abs(x - 60.0 - 0.3 * y) + 0.1 * y; }
double noise(double x, double y) {
    auto h =
        static_cast<std::uint32_t>(x * 73856093.0) ^ static_cast<std::uint32_t>(y * 19349663.0);
    h = (h ^ (h >> 13)) * 0x5bd1e995U;
    return 100.0 + 0.5 * std::sin(x / 9.0) + static_cast<double>(h % 1000U) / 4000.0;
}

TEST(DemReduce, HeldOutDemsAreWithinTheBoundAtEveryCell) {
    const std::pair<const char*, double (*)(double, double)> terrains[] = {
        {"hills", hills}, {"ridge", ridge}, {"noise", noise}};
    for (const auto& [name, f] : terrains) {
        const Dem dem = make_dem(71, 53, f);
        for (const double bound : {0.05, 0.5}) {
            dtm::DemReduceOptions o;
            o.max_error = bound;
            const dtm::DemReduceResult r = dtm::reduce_dem({}, dem.cells, o, {});
            ASSERT_TRUE(r.triangulated);
            EXPECT_LE(worst_cell_error(r.triangulation.tin, dem), bound + 1e-9)
                << name << " E=" << bound;
            EXPECT_LE(r.report.max_error, bound) << name;
            EXPECT_EQ(r.report.measured, dem.cells.size()) << name;
            EXPECT_EQ(r.report.kept, r.kept.size());
            EXPECT_LT(r.report.kept, dem.cells.size()) << name;
            EXPECT_EQ(r.report.vertices, r.triangulation.tin.vertices.size());
            EXPECT_TRUE(dtm::verify_topology(r.triangulation.tin).ok()) << name;
        }
    }
}

TEST(DemReduce, SmootherTerrainAndLooserBoundsNeedFewerCells) {
    const Dem dem = make_dem(71, 53, hills);
    std::size_t previous = dem.cells.size() + 1;
    for (const double bound : {0.01, 0.1, 1.0}) {
        dtm::DemReduceOptions o;
        o.max_error = bound;
        const dtm::DemReduceResult r = dtm::reduce_dem({}, dem.cells, o, {});
        EXPECT_LT(r.report.kept, previous) << bound;
        previous = r.report.kept;
    }
    // a plane needs its hull corners only
    const Dem plane = make_dem(40, 30, [](double x, double y) { return 10.0 + 0.1 * x - 0.2 * y; });
    dtm::DemReduceOptions o;
    o.max_error = 1e-6;
    EXPECT_EQ(dtm::reduce_dem({}, plane.cells, o, {}).report.kept, 4U);
}

TEST(DemReduce, BreaklinesAreKeptAndTheBoundHolds) {
    const Dem dem = make_dem(71, 53, ridge);
    dtm::TerrainInput survey;
    dtm::Polyline crest;  // the ridge's crease, a hard breakline at the DEM's heights
    for (int k = 0; k <= 10; ++k) {
        const double y = 1.0 + 10.0 * k;
        const double x = 60.0 + 0.3 * y;
        crest.points.push_back({dem.x0 + x, dem.y0 + y, ridge(x, y)});
    }
    survey.breaklines.push_back(crest);
    dtm::DemReduceOptions o;
    o.max_error = 0.05;
    const dtm::DemReduceResult r = dtm::reduce_dem(survey, dem.cells, o, {});
    ASSERT_TRUE(r.triangulated);
    const dtm::CheckReport kept =
        dtm::verify_constraints(r.triangulation.tin, r.terrain, r.triangulation.input_to_vertex);
    EXPECT_TRUE(kept.ok()) << kept.text();
    EXPECT_EQ(r.terrain.breaklines.size(), 1U);
    EXPECT_LE(worst_cell_error(r.triangulation.tin, dem), 0.05 + 1e-9);
}

TEST(DemReduce, ClipDropsExactlyTheCellsNearTheSurvey) {
    const Dem dem = make_dem(41, 31, hills);
    dtm::TerrainInput survey;
    survey.points.push_back({dem.x0 + 20.3, dem.y0 + 30.1, 301.0});
    dtm::Polyline line;
    line.points = {{dem.x0 + 40.0, dem.y0 + 5.0, 300.0}, {dem.x0 + 70.0, dem.y0 + 50.0, 302.0}};
    survey.soft_breaklines.push_back(line);
    dtm::DemReduceOptions o;
    o.clip_radius = 6.5;
    const dtm::DemReduceResult r = dtm::reduce_dem(survey, dem.cells, o, {});
    EXPECT_FALSE(r.triangulated);
    std::vector<std::size_t> expected;
    const Point3 a = line.points[0];
    const Point3 b = line.points[1];
    for (std::size_t k = 0; k < dem.cells.size(); ++k) {
        const Point3& p = dem.cells[k];
        const double t = std::clamp(((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) /
                                        ((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y)),
                                    0.0, 1.0);
        const double to_line = std::hypot(p.x - a.x - t * (b.x - a.x), p.y - a.y - t * (b.y - a.y));
        const double to_point = std::hypot(p.x - survey.points[0].x, p.y - survey.points[0].y);
        if (std::min(to_line, to_point) > 6.5) expected.push_back(k);
    }
    EXPECT_EQ(r.kept, expected);
    EXPECT_EQ(r.report.clipped, dem.cells.size() - expected.size());
    EXPECT_GT(r.report.clipped, 20U);
    ASSERT_EQ(r.terrain.points.size(), 1 + expected.size());
    EXPECT_EQ(r.terrain.points[0].z, 301.0);  // the survey first, then the kept cells
}

TEST(DemReduce, NegativeOptionsNameTheirField) {
    dtm::DemReduceOptions o;
    o.max_error = -1.0;
    try {
        (void)dtm::reduce_dem({}, {}, o, {});
        FAIL();
    } catch (const dtm::OptionError& e) {
        EXPECT_EQ(e.field(), "dem.max_error");
    }
}

}  // namespace
