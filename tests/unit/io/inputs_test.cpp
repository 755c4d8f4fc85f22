// SPDX-License-Identifier: MIT
// load_inputs: roles, CRS resolution (S-JTSK, lat/lon -> UTM, the target CRS), 2-D lines left
// without heights, PLY TINs, summaries, and the real hurdville survey.
#include "dtm/io/inputs.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dtm/algo/line_heights.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/tin_file.hpp"
#include "support/test_support.hpp"

namespace {

using dtm::io::InputRole;
using dtm::io::LoadOptions;

LoadOptions files(std::initializer_list<std::pair<std::filesystem::path, InputRole>> list) {
    LoadOptions options;
    for (const auto& [path, role] : list) options.files.push_back({path, role});
    return options;
}

TEST(LoadInputs, CzechListWithCrs5514BecomesKrovakEastNorthWhateverTheColumnOrder) {
    for (const char* name : {"readers/czech_list.csv", "readers/czech_list_xy.csv",
                             "readers/czech_list_noheader.txt"}) {
        LoadOptions options = files({{dtm::test::data_path(name), InputRole::points}});
        options.crs.default_crs = "EPSG:5514";
        const auto loaded = dtm::io::load_inputs(options);
        ASSERT_GE(loaded.terrain.points.size(), 3u) << name;
        EXPECT_EQ(loaded.terrain.points[0], (dtm::Point3{-745123.45, -1045123.12, 312.45})) << name;
        EXPECT_EQ(dtm::io::crs_label(loaded.crs_wkt), "EPSG:5514");
        EXPECT_EQ(loaded.summaries.at(0).crs, "EPSG:5514");
        EXPECT_EQ(loaded.summaries[0].bbox[0], -745130.10);  // in East-North too
    }
}

TEST(LoadInputs, TextFileTakesItsCrsFromASidecarPrj) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(
        dir / "list.txt",
        dtm::test::read_file(dtm::test::data_path("readers/czech_list_noheader.txt")));
    dtm::test::write_file(dir / "list.prj", dtm::io::crs_to_wkt("EPSG:5514"));
    const auto loaded = dtm::io::load_inputs(files({{dir / "list.txt", InputRole::points}}));
    EXPECT_EQ(loaded.summaries.at(0).crs, "EPSG:5514");
    EXPECT_EQ(loaded.terrain.points.at(0), (dtm::Point3{-745123.45, -1045123.12, 312.45}));
}

TEST(LoadInputs, WithoutCrsCzechPositiveCoordinatesAreLeftAlone) {
    const auto loaded = dtm::io::load_inputs(
        files({{dtm::test::data_path("readers/czech_list.csv"), InputRole::points}}));
    EXPECT_GT(loaded.terrain.points[0].x, 0.0);
    EXPECT_TRUE(loaded.crs_wkt.empty());
    ASSERT_EQ(loaded.labels.ids.size(), 4u);
    EXPECT_EQ(loaded.labels.ids[0], "4001");
}

TEST(LoadInputs, LatLonIsProjectedToItsUtmZone) {
    const auto loaded = dtm::io::load_inputs(
        files({{dtm::test::data_path("readers/gnss_latlon.csv"), InputRole::points}}));
    EXPECT_EQ(dtm::io::crs_label(loaded.crs_wkt), "EPSG:32633");
    ASSERT_EQ(loaded.terrain.points.size(), 3u);
    EXPECT_NEAR(loaded.terrain.points[0].x, 458608.862147838, 1e-3);
    EXPECT_NEAR(loaded.terrain.points[0].y, 5548519.73260518, 1e-3);
    EXPECT_EQ(loaded.terrain.points[0].z, 245.10);
    EXPECT_EQ(loaded.summaries[0].crs, "EPSG:4326");
}

TEST(LoadInputs, TargetCrsTransformsEveryInput) {
    LoadOptions options =
        files({{dtm::test::data_path("readers/gnss_latlon.csv"), InputRole::points}});
    options.crs.target_crs = "EPSG:32634";
    const auto loaded = dtm::io::load_inputs(options);
    EXPECT_EQ(dtm::io::crs_label(loaded.crs_wkt), "EPSG:32634");
    EXPECT_LT(loaded.terrain.points[0].x, 166000.0 + 50000.0);  // far west of zone 34
}

/// load_inputs(@p options) throws an OptionError naming @p field, its message starting with
/// @p start.
void expect_option_error(const LoadOptions& options,
                         const std::string& field,
                         const std::string& start) {
    try {
        (void)dtm::io::load_inputs(options);
        ADD_FAILURE() << "no exception";
    } catch (const dtm::OptionError& e) {
        EXPECT_EQ(e.field(), field);
        EXPECT_EQ(std::string(e.what()).rfind(start, 0), 0u) << e.what();
    }
}

TEST(LoadInputs, GeographicTargetCrsIsRefused) {
    LoadOptions options =
        files({{dtm::test::data_path("readers/gnss_latlon.csv"), InputRole::points}});
    options.crs.target_crs = "EPSG:4326";
    expect_option_error(options, "target_crs", "`target_crs`: expected a projected CRS");
}

TEST(LoadInputs, UnknownCrsIsAnOptionErrorNamingTheField) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "p.xyz", "1 2 3\n4 5 6\n7 9 10\n");
    LoadOptions options = files({{dir / "p.xyz", InputRole::points}});
    options.crs.default_crs = "EPSG:999999999";
    expect_option_error(options, "default_crs", "`default_crs`: expected a CRS");
}

TEST(LoadInputs, InputsInAnotherCrsGoIntoTheFirstOnes) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "a.csv", "x,y,z\n458600,5548500,1\n458700,5548600,2\n");
    dtm::test::write_file(dir / "b.csv", "lat,lon,h\n50.0875,14.4214,3\n");
    LoadOptions options = files({{dir / "a.csv", InputRole::points}});
    options.crs.default_crs = "EPSG:32633";
    options.files.push_back({dir / "b.csv", InputRole::points});
    const auto loaded = dtm::io::load_inputs(options);
    ASSERT_EQ(loaded.terrain.points.size(), 3u);
    EXPECT_NEAR(loaded.terrain.points[2].x, 458608.862, 1e-2);
    EXPECT_EQ(dtm::io::crs_label(loaded.crs_wkt), "EPSG:32633");
}

TEST(LoadInputs, LabelsStayParallelToThePointsWhicheverInputHasThem) {
    // The first input's arrays are taken over, the later ones appended.
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "plain.csv", "x,y,z\n1,2,3\n4,5,6\n");
    dtm::test::write_file(dir / "named.csv", "id,x,y,z,code\nA,7,8,9,k\n");
    for (const bool named_first : {false, true}) {
        const char* first = named_first ? "named.csv" : "plain.csv";
        const char* second = named_first ? "plain.csv" : "named.csv";
        const auto loaded = dtm::io::load_inputs(
            files({{dir / first, InputRole::points}, {dir / second, InputRole::points}}));
        ASSERT_EQ(loaded.terrain.points.size(), 3u);
        ASSERT_EQ(loaded.labels.ids.size(), 3u);
        ASSERT_EQ(loaded.labels.codes.size(), 3u);
        const std::size_t named = named_first ? 0 : 2;
        EXPECT_EQ(loaded.terrain.points[named].x, 7.0);
        EXPECT_EQ(loaded.labels.ids[named], "A");
        EXPECT_EQ(loaded.labels.codes[named], "k");
        EXPECT_EQ(loaded.labels.ids[named_first ? 2 : 0], "");
        EXPECT_EQ(loaded.terrain.points[named_first ? 1 : 0].x, 1.0);
    }
}

TEST(LoadInputs, LeavesMissingHeightsToTheTriangulator) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "p.csv", "0.5 0 1\n10.5 0 2\n10.5 10 3\n");
    dtm::test::write_file(dir / "l.csv", "1,0.5,0\n1,5.5,5\n");
    dtm::test::write_file(dir / "b.csv", "1,1.5,1\n1,9.5,1\n1,9.5,8\n");
    const auto loaded = dtm::io::load_inputs(files({{dir / "p.csv", InputRole::points},
                                                    {dir / "l.csv", InputRole::breaklines},
                                                    {dir / "b.csv", InputRole::boundary}}));
    EXPECT_TRUE(std::isnan(loaded.terrain.breaklines.at(0).points[0].z));
    EXPECT_TRUE(std::isnan(loaded.terrain.boundaries.at(0).points[0].z));
    EXPECT_EQ(loaded.summaries[1].breakline_vertices, 2u);
    for (const auto& s : loaded.summaries) EXPECT_TRUE(s.warnings.empty());
}

TEST(LoadInputs, PlyTinInputSetsTinAndPoints) {
    dtm::test::ScratchDir dir;
    dtm::Tin tin;
    tin.vertices = {{0, 0, 1}, {10, 0, 2}, {0, 10, 3}};
    dtm::Triangle t;
    t.v = {0, 1, 2};
    tin.triangles = {t};
    dtm::io::write_tin_ply(tin, dir / "t.ply", {});
    const auto loaded = dtm::io::load_inputs(files({{dir / "t.ply", InputRole::points}}));
    ASSERT_TRUE(loaded.tin.has_value());
    EXPECT_EQ(loaded.tin->triangles.size(), 1u);
    EXPECT_EQ(loaded.terrain.points.size(), 3u);
    EXPECT_EQ(loaded.summaries[0].format, "dtm PLY TIN");
}

TEST(LoadInputs, UnknownExtensionListsTheKnownOnes) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "a.foo", "1 2 3\n");
    try {
        (void)dtm::io::load_inputs(files({{dir / "a.foo", InputRole::points}}));
        FAIL();
    } catch (const dtm::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("csv"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("shp"), std::string::npos);
    }
}

TEST(LoadInputs, SummaryCountsDuplicatesBboxAndSkippedLines) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "p.csv", "x,y,z\n1,2,3\n1,2,4\n5,6,7\nbad,1,2\n");
    LoadOptions options = files({{dir / "p.csv", InputRole::points}});
    options.read.skip_bad_lines = true;
    const auto loaded = dtm::io::load_inputs(options);
    const auto& s = loaded.summaries.at(0);
    EXPECT_EQ(s.points, 3u);
    EXPECT_EQ(s.duplicates, 1u);
    EXPECT_EQ(s.skipped_lines, 1u);
    EXPECT_EQ(loaded.skipped_lines, 1u);
    EXPECT_EQ(s.bbox, (std::array<double, 4>{1, 2, 5, 6}));
    EXPECT_EQ(s.z_range, (std::array<double, 2>{3, 7}));
}

TEST(LoadInputsRealData, HurdvilleSurveyWithBoundaryAndHoles) {
    const std::string d = "points-breaklines-pputils-hurdville/";
    if (!dtm::test::shared_data_available(d + "nodes.csv")) GTEST_SKIP();
    const auto p = [&](const char* f) { return dtm::test::shared_data_path(d + f); };
    const auto loaded = dtm::io::load_inputs(files({{p("nodes.csv"), InputRole::points},
                                                    {p("lines.csv"), InputRole::soft_breaklines},
                                                    {p("boundary.csv"), InputRole::boundary},
                                                    {p("holes.csv"), InputRole::holes}}));
    EXPECT_EQ(loaded.terrain.points.size(), 5552u);
    EXPECT_EQ(loaded.summaries[0].duplicates, 124u);
    EXPECT_EQ(loaded.terrain.soft_breaklines.size(), 156u);
    ASSERT_EQ(loaded.terrain.boundaries.size(), 1u);
    EXPECT_EQ(loaded.terrain.hole_seeds.size(), 16u);
    dtm::TerrainInput terrain = loaded.terrain;  // the heights come with the triangulation
    EXPECT_GT(dtm::resolve_line_heights(terrain).from_surface, 0u);
    for (const auto& v : terrain.boundaries[0].points) {
        EXPECT_GE(v.z, 206.0);
        EXPECT_LE(v.z, 240.5);
    }
}

TEST(LoadInputsRealData, JvfCsvWithShapefileCrs) {
    const std::string d = "points-cz-sjtsk-jvf-dtm/derived/";
    if (!dtm::test::shared_data_available(d + "zps_points_xyz.csv")) GTEST_SKIP();
    const auto loaded = dtm::io::load_inputs(
        files({{dtm::test::shared_data_path(d + "zps_points_pointz.shp"), InputRole::points},
               {dtm::test::shared_data_path(d + "zps_points_xyz.csv"), InputRole::points},
               {dtm::test::shared_data_path(d + "zps_breaklines_terenni_hrana_shapeid_xyz.csv"),
                InputRole::breaklines}}));
    EXPECT_EQ(dtm::io::crs_label(loaded.crs_wkt), "EPSG:5514");
    EXPECT_EQ(loaded.terrain.points.size(), 2 * 917u);
    EXPECT_EQ(loaded.terrain.breaklines.size(), 55u);
    EXPECT_EQ(loaded.labels.ids.size(), 2 * 917u);
    EXPECT_EQ(loaded.labels.ids[917], "72000330010094405");
}

}  // namespace
