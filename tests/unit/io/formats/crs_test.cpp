// SPDX-License-Identifier: MIT
// CRS helpers: naming (.prj -> EPSG), S-JTSK (Y, X) -> Krovak East-North, UTM zones and
// GeographicLib projection checked against PROJ's values.
#include "dtm/io/formats/crs.hpp"

#include <gtest/gtest.h>

#include "dtm/core/error.hpp"
#include "support/test_support.hpp"

namespace {

TEST(Crs, EsriPrjTextIsIdentifiedAsEpsg5514) {
    const std::string rel = "points-cz-sjtsk-jvf-dtm/derived/zps_points_pointz.prj";
    if (!dtm::test::shared_data_available(rel)) GTEST_SKIP();
    const std::string prj = dtm::test::read_file(dtm::test::shared_data_path(rel));
    EXPECT_EQ(dtm::io::crs_label(prj), "EPSG:5514");
    EXPECT_TRUE(dtm::io::crs_is_sjtsk(prj));
    EXPECT_FALSE(dtm::io::crs_is_geographic(prj));
}

TEST(Crs, UserDefinitionsAndBadOnes) {
    const std::string wkt = dtm::io::crs_to_wkt("EPSG:32633");
    EXPECT_EQ(dtm::io::crs_label(wkt), "EPSG:32633");
    EXPECT_TRUE(dtm::io::crs_is_geographic(dtm::io::crs_to_wkt("EPSG:4326")));
    EXPECT_THROW((void)dtm::io::crs_to_wkt("EPSG:999999999"), dtm::UsageError);
    EXPECT_TRUE(dtm::io::crs_equivalent(wkt, dtm::io::crs_to_wkt("EPSG:32633")));
    EXPECT_FALSE(dtm::io::crs_equivalent(wkt, dtm::io::crs_to_wkt("EPSG:32634")));
}

TEST(Crs, SjtskPositiveYXBecomeEastNorthInEitherColumnOrder) {
    dtm::TerrainInput t;
    t.points = {{745123.45, 1045123.12, 312.45},  // Y, X
                {1045120.00, 745130.10, 312.90},  // X, Y
                {-745000.0, -1045000.0, 300.0}};  // already East-North
    t.breaklines.push_back({{{745100.0, 1045100.0, 1.0}}, false, ""});
    t.hole_seeds = {{745110.0, 1045110.0}};
    EXPECT_EQ(dtm::io::sjtsk_to_east_north(t), 4u);
    EXPECT_EQ(t.points[0], (dtm::Point3{-745123.45, -1045123.12, 312.45}));
    EXPECT_EQ(t.points[1], (dtm::Point3{-745130.10, -1045120.00, 312.90}));
    EXPECT_EQ(t.points[2], (dtm::Point3{-745000.0, -1045000.0, 300.0}));
    EXPECT_EQ(t.breaklines[0].points[0], (dtm::Point3{-745100.0, -1045100.0, 1.0}));
    EXPECT_EQ(t.hole_seeds[0], (dtm::Point2{-745110.0, -1045110.0}));
}

TEST(Crs, StandardUtmZones) {
    EXPECT_EQ(dtm::io::utm_zone_for(14.42, 50.09).epsg(), 32633);   // Prague
    EXPECT_EQ(dtm::io::utm_zone_for(151.2, -33.86).epsg(), 32756);  // Sydney
    EXPECT_EQ(dtm::io::utm_zone_for(5.5, 60.4).zone, 32);           // Norway exception
    EXPECT_EQ(dtm::io::utm_zone_for(-63.5, 45.4).epsg(), 32620);    // Nova Scotia
}

// Reference values from PROJ (gdaltransform -s_srs EPSG:4326 -t_srs EPSG:326xx/327xx); PROJ's
// extended transverse Mercator and GeographicLib agree to well under a millimetre in a zone.
TEST(Crs, GeographicLibUtmMatchesReferenceValues) {
    dtm::TerrainInput t;
    t.points = {{14.4214, 50.0875, 245.1}, {14.3, 49.9, 301.5}};
    dtm::io::project_to_utm(t, {33, true}, "test");
    EXPECT_NEAR(t.points[0].x, 458608.862147838, 1e-3);
    EXPECT_NEAR(t.points[0].y, 5548519.73260518, 1e-3);
    EXPECT_NEAR(t.points[1].x, 449729.278248239, 1e-3);
    EXPECT_NEAR(t.points[1].y, 5527747.24428034, 1e-3);
    EXPECT_EQ(t.points[0].z, 245.1);
    dtm::TerrainInput south;
    south.points = {{151.2153, -33.8568, 0.0}};
    dtm::io::project_to_utm(south, {56, false}, "test");
    EXPECT_NEAR(south.points[0].x, 334900.569652264, 1e-3);
    EXPECT_NEAR(south.points[0].y, 6252288.75288829, 1e-3);
}

TEST(Crs, LatitudeOutOfRangeIsAnInputError) {
    dtm::TerrainInput t;
    t.points = {{14.0, 95.0, 0.0}};
    EXPECT_THROW(dtm::io::project_to_utm(t, {33, true}, "f.csv"), dtm::InputError);
}

TEST(Crs, GdalTransformAgreesWithGeographicLib) {
    dtm::TerrainInput a;
    a.points = {{14.4214, 50.0875, 1.0}};
    dtm::TerrainInput b = a;
    dtm::io::transform_terrain(a, dtm::io::crs_to_wkt("EPSG:4326"),
                               dtm::io::crs_to_wkt("EPSG:32633"), "test");
    dtm::io::project_to_utm(b, {33, true}, "test");
    EXPECT_NEAR(a.points[0].x, b.points[0].x, 1e-3);
    EXPECT_NEAR(a.points[0].y, b.points[0].y, 1e-3);
}

}  // namespace
