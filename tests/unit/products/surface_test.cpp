// SPDX-License-Identifier: MIT
// products::surface: a TIN input is used as it is; terrain is triangulated, with the note on
// the inputs whose rings took the surface height; contour input loses its flat triangles by
// default (and keeps them when asked); and the default cell and interval rules.
#include "dtm/products/surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dtm/products/rules.hpp"
#include "support/contour_terrain.hpp"

namespace {

dtm::io::LoadedInputs plane_inputs() {
    dtm::io::LoadedInputs in;
    in.terrain.points = {{0, 0, 0}, {100, 0, 100}, {100, 100, 300}, {0, 100, 200}, {50, 50, 150}};
    in.summaries.resize(2);
    in.summaries[1].boundaries = 1;
    return in;
}

TEST(Surface, TinInputIsUsedAsItIs) {
    dtm::io::LoadedInputs in;
    dtm::Tin tin;
    tin.vertices = {{0, 0, 1}, {10, 0, 2}, {0, 10, 3}};
    tin.triangles.resize(1);
    tin.triangles[0].v = {0, 1, 2};
    in.tin = tin;
    in.terrain.points = tin.vertices;
    const dtm::products::Surface s = dtm::products::surface(in, {});
    EXPECT_TRUE(s.from_tin);
    EXPECT_FALSE(in.tin.has_value());
    EXPECT_EQ(s.result.tin.triangles.size(), 1u);
    EXPECT_EQ(s.survey_points, 3u);
    EXPECT_EQ(s.result.input_to_vertex, (std::vector<dtm::VertexIndex>{0, 1, 2}));
}

TEST(Surface, TerrainIsTriangulatedAndRingsFromTheSurfaceAreNoted) {
    dtm::io::LoadedInputs in = plane_inputs();
    dtm::Polyline ring;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    ring.points = {{10, 10, nan}, {90, 10, nan}, {90, 90, nan}, {10, 90, nan}};
    ring.closed = true;
    in.terrain.boundaries.push_back(ring);
    const dtm::products::Surface s = dtm::products::surface(in, {});
    EXPECT_FALSE(s.from_tin);
    EXPECT_EQ(s.survey_points, 5u);
    EXPECT_TRUE(in.terrain.points.empty()) << "the terrain is consumed";
    EXPECT_EQ(s.result.line_heights.from_surface, 4u);
    for (const dtm::Point3& v : s.result.tin.vertices) EXPECT_NEAR(v.z, v.x + 2 * v.y, 1e-9);
    EXPECT_TRUE(in.summaries[0].warnings.empty());
    ASSERT_EQ(in.summaries[1].warnings.size(), 1u);
    EXPECT_EQ(in.summaries[1].warnings[0],
              "4 boundary/hole vertices without height took the height of the surface");
}

dtm::io::LoadedInputs contour_inputs(const dtm::TerrainInput& terrain) {
    dtm::io::LoadedInputs in;
    in.terrain = terrain;
    in.summaries.resize(1);
    in.summaries[0].path = "contours.shp";
    in.summaries[0].breaklines = terrain.breaklines.size();
    return in;
}

TEST(Surface, ContourInputLosesItsFlatTrianglesByDefault) {
    const dtm::TerrainInput terrain = dtm::test::contour_terrain_input(5.0, 2.0);
    const std::size_t flat_as_given = dtm::count_flat_triangles(dtm::triangulate(terrain).tin);
    dtm::products::SurfaceOptions options;
    options.lines_are_contours = true;
    dtm::io::LoadedInputs in = contour_inputs(terrain);
    const dtm::products::Surface s = dtm::products::surface(in, options);
    EXPECT_TRUE(s.contour_input);
    ASSERT_TRUE(s.contour_flats.has_value());
    EXPECT_EQ(s.contour_flats->flat_before, flat_as_given);
    EXPECT_GT(flat_as_given, s.result.tin.triangles.size() / 20) << "the fixture is terraced";
    EXPECT_EQ(s.contour_flats->flat_after, dtm::count_flat_triangles(s.result.tin));
    EXPECT_LT(20 * s.contour_flats->flat_after, s.result.tin.triangles.size());
    EXPECT_EQ(s.added_points.size(), s.contour_flats->points_added);
    EXPECT_GT(s.added_points.size(), 0u);
    EXPECT_EQ(s.survey_points, 0u) << "the added points are not survey points";

    options.contour_flats = dtm::products::ContourFlats::keep;
    dtm::io::LoadedInputs kept = contour_inputs(terrain);
    const dtm::products::Surface k = dtm::products::surface(kept, options);
    EXPECT_TRUE(k.contour_input);
    EXPECT_FALSE(k.contour_flats.has_value());
    EXPECT_EQ(dtm::count_flat_triangles(k.result.tin), flat_as_given);

    dtm::io::LoadedInputs plain = contour_inputs(terrain);
    const dtm::products::Surface p = dtm::products::surface(plain, dtm::TriangulateOptions{});
    EXPECT_FALSE(p.contour_input) << "lines without z_field heights are breaklines";
    EXPECT_FALSE(p.contour_flats.has_value());
}

TEST(Surface, FlatAreaInputsOutlineRealFlats) {
    // a lake: a closed 5 m-level ring inside the 5 m contour ring and no point inside it
    dtm::TerrainInput terrain;
    for (int k = 0; k < 24; ++k) {
        const double a = 2.0 * M_PI * k / 24.0;
        terrain.points.push_back({50 + 45 * std::cos(a), 50 + 45 * std::sin(a), 0.0});
    }
    dtm::Polyline ring;
    ring.closed = true;
    for (int k = 0; k < 24; ++k) {
        const double a = 2.0 * M_PI * k / 24.0;
        ring.points.push_back({50 + 20 * std::cos(a), 50 + 20 * std::sin(a), 5.0});
    }
    terrain.breaklines.push_back(ring);
    dtm::io::LoadedInputs in;
    in.terrain = terrain;
    in.summaries.resize(2);
    in.summaries[0].points = terrain.points.size();
    in.summaries[1].path = "lake.shp";
    in.summaries[1].breaklines = 1;
    dtm::products::SurfaceOptions options;
    options.lines_are_contours = true;
    options.flat_areas = {"lake.shp"};
    const dtm::products::Surface lake = dtm::products::surface(in, options);
    ASSERT_TRUE(lake.contour_flats.has_value());
    EXPECT_EQ(lake.contour_flats->true_flats, 1u);
    EXPECT_TRUE(lake.contour_flats->peaks.empty()) << "a lake gets no summit";
    EXPECT_GT(dtm::count_flat_triangles(lake.result.tin), 0u);

    in.terrain = terrain;
    options.flat_areas.clear();
    const dtm::products::Surface hill = dtm::products::surface(in, options);
    ASSERT_TRUE(hill.contour_flats.has_value());
    EXPECT_EQ(hill.contour_flats->peaks.size(), 1u) << "without the outline it is a summit";
}

TEST(Rules, NiceNumbersAreOneTwoTwoAndAHalfOrFiveTimesAPowerOfTen) {
    using dtm::products::nice_floor;
    using dtm::products::nice_next;
    EXPECT_DOUBLE_EQ(nice_floor(0.37), 0.25);
    EXPECT_DOUBLE_EQ(nice_floor(1.99), 1.0);
    EXPECT_DOUBLE_EQ(nice_floor(2.2), 2.0);
    EXPECT_DOUBLE_EQ(nice_floor(7.0), 5.0);
    EXPECT_DOUBLE_EQ(nice_floor(50.0), 50.0);
    EXPECT_DOUBLE_EQ(nice_next(1.0), 2.0);
    EXPECT_DOUBLE_EQ(nice_next(2.0), 2.5);
    EXPECT_DOUBLE_EQ(nice_next(2.5), 5.0);
    EXPECT_DOUBLE_EQ(nice_next(5.0), 10.0);
}

TEST(Rules, DefaultCellIsHalfThePointSpacingAndCapsTheCellCount) {
    dtm::SurfaceStats s;
    s.vertex_count = 10'000;
    s.planimetric_area = 1e6;  // spacing 10: cell 5
    s.extent.add(0, 0);
    s.extent.add(1000, 1000);
    EXPECT_DOUBLE_EQ(dtm::products::default_cell(s), 5.0);
    s.vertex_count = 100'000'000;  // spacing 0.1: cell 0.05 would make 4e8 cells
    const double cell = dtm::products::default_cell(s);
    EXPECT_LE((1000 / cell + 1) * (1000 / cell + 1), 50e6);
    EXPECT_DOUBLE_EQ(cell, 0.2);
}

TEST(Rules, DefaultIntervalGivesAboutTwentyLevels) {
    dtm::SurfaceStats s;
    s.z_min = 310.38;
    s.z_max = 331.76;  // range 21.38: 1.069 -> 1
    EXPECT_DOUBLE_EQ(dtm::products::default_interval(s), 1.0);
    s.z_max = s.z_min;
    EXPECT_DOUBLE_EQ(dtm::products::default_interval(s), 1.0);
}

}  // namespace
