// SPDX-License-Identifier: MIT
// `dtm sections` on the sample road: products, the exact slab volumes equal `dtm volume` within
// the corridor the sections sweep (two independent paths: slab overlay vs clipping), and the
// end-area volumes stay close to them on this nearly prismatic road.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/analysis_fixtures.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

std::string feature_collection(const std::string& geometry) {
    return "{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\",\"properties\":{\"name\":"
           "\"EPSG:5514\"}},\"features\":[{\"type\":\"Feature\",\"properties\":{},\"geometry\":" +
           geometry + "}]}";
}

TEST(CliSections, ExactSlabVolumesEqualTheVolumeWithinTheCorridor) {
    const dtm::test::ScratchDir dir;
    auto r = dtm::test::build_sample_tin(dir / "built.ply", false);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = dtm::test::build_sample_tin(dir / "natural.ply", true);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // Along the road's centre line (tools/dtm-sample: from local (-10, 55) to (250, 82)), from
    // station 30 to 230, sections every 10 m, 30 m wide.
    const double e0 = -750300.0;
    const double n0 = -1050200.0;
    const double du = 260.0;
    const double dv = 27.0;
    const double len = std::hypot(du, dv);
    const double tu = du / len;
    const double tv = dv / len;
    const auto at = [&](double s, double d) {
        return std::pair{e0 - 10.0 + s * tu - d * tv, n0 + 55.0 + s * tv + d * tu};
    };
    char text[1024];
    const auto [ax, ay] = at(30.0, 0.0);
    const auto [bx, by] = at(230.0, 0.0);
    std::snprintf(text, sizeof text,
                  "{\"type\":\"LineString\",\"coordinates\":[[%.6f,%.6f],[%.6f,%.6f]]}", ax, ay, bx,
                  by);
    dtm::test::write_file(dir / "alignment.geojson", feature_collection(text));
    const auto [p0x, p0y] = at(30.0, 15.0);
    const auto [p1x, p1y] = at(230.0, 15.0);
    const auto [p2x, p2y] = at(230.0, -15.0);
    const auto [p3x, p3y] = at(30.0, -15.0);
    std::snprintf(text, sizeof text,
                  "{\"type\":\"Polygon\",\"coordinates\":[[[%.6f,%.6f],[%.6f,%.6f],[%.6f,%.6f],"
                  "[%.6f,%.6f],[%.6f,%.6f]]]}",
                  p0x, p0y, p3x, p3y, p2x, p2y, p1x, p1y, p0x, p0y);
    dtm::test::write_file(dir / "corridor.geojson", feature_collection(text));

    r = dtm::test::run_dtm({"sections", (dir / "built.ply").string(),
                            (dir / "natural.ply").string(), "--alignment",
                            (dir / "alignment.geojson").string(), "--interval", "10", "--width",
                            "30", "-o", (dir / "sec").string(), "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* f :
         {"sections.csv", "section_points.csv", "sections.gpkg", "sections.json", "sections.pdf"}) {
        EXPECT_TRUE(fs::exists(dir / "sec" / f)) << f;
    }
    r = dtm::test::run_dtm({"volume", (dir / "built.ply").string(), "--base",
                            (dir / "natural.ply").string(), "--within",
                            (dir / "corridor.geojson").string(), "-o", (dir / "vol").string(), "-q",
                            "--no-products"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string sections = dtm::test::read_file(dir / "sec" / "sections.json");
    const std::string volume = dtm::test::read_file(dir / "vol" / "volume.json");
    const double fill = dtm::test::json_number(volume, "volume", "fill");
    const double cut = dtm::test::json_number(volume, "volume", "cut");
    EXPECT_GT(fill, 100.0);
    EXPECT_NEAR(dtm::test::json_number(sections, "exact", "fill"), fill, 1e-6 * fill);
    EXPECT_NEAR(dtm::test::json_number(sections, "exact", "cut"), cut, 1e-6 * cut);
    // End areas on a nearly prismatic road: within 1 %.
    EXPECT_NEAR(dtm::test::json_number(sections, "end_area", "fill"), fill, 0.01 * fill);
    EXPECT_NEAR(dtm::test::json_number(sections, "end_area", "cut"), cut, 0.01 * cut);
}

TEST(CliSections, AnAlignmentOutsideTheSurfacesIsAnError) {
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "far.geojson",
                          feature_collection("{\"type\":\"LineString\",\"coordinates\":"
                                             "[[-740000,-1040000],[-739000,-1040000]]}"));
    const auto r = dtm::test::run_dtm(
        {"sections", dtm::test::sample_file("natural_points.csv").string(), "--alignment",
         (dir / "far.geojson").string(), "--interval", "10", "--width", "20", "--crs", "EPSG:5514",
         "-o", (dir / "sec").string(), "-q"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("far.geojson"), std::string::npos) << r.err;
}

}  // namespace
