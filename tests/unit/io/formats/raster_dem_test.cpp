// SPDX-License-Identifier: MIT
// Raster DEMs as input: an ESRI ASCII grid (sniffed apart from point text) gives one point per
// cell centre with NoData skipped; the real GeoTIFF keeps its CRS and every valid cell.
#include "dtm/io/formats/raster_dem.hpp"

#include <gtest/gtest.h>

#include "dtm/io/formats/crs.hpp"
#include "dtm/io/reader.hpp"
#include "support/test_support.hpp"

namespace {

namespace io = dtm::io;
namespace test = dtm::test;

TEST(RasterDem, AsciiGridCellsBecomeCentrePointsWithoutNoData) {
    const auto path = test::data_path("dem/small.asc");
    EXPECT_EQ(io::find_reader(path).name, "ascii-grid");
    EXPECT_EQ(io::find_reader(test::data_path("readers/count_line.xyz")).name, "csv");
    const io::ReadResult r = io::read_raster_dem({path, io::InputRole::points}, {});
    ASSERT_EQ(r.terrain.points.size(), 5U);
    // The top row (y from -1045000 + 4 down to + 2) comes first: centre y = -1044997.
    EXPECT_EQ(r.terrain.points[0].x, -744999.0);
    EXPECT_EQ(r.terrain.points[0].y, -1044997.0);
    EXPECT_EQ(r.terrain.points[0].z, 10.0);
    EXPECT_EQ(r.terrain.points[3].x, -744999.0);
    EXPECT_EQ(r.terrain.points[3].y, -1044999.0);
    EXPECT_EQ(r.terrain.points[3].z, 13.0);
    EXPECT_EQ(r.terrain.points[4].x, -744995.0);
    EXPECT_EQ(r.terrain.points[4].z, 15.0);
}

TEST(RasterDem, GeoTiffKeepsItsCrsAndEveryCell) {
    if (!test::shared_data_available("dem-whiteboxR/DEM.tif")) GTEST_SKIP();
    const auto path = test::shared_data_path("dem-whiteboxR/DEM.tif");
    EXPECT_EQ(io::find_reader(path).name, "raster");
    const io::ReadResult r = io::read_raster_dem({path, io::InputRole::points}, {});
    EXPECT_EQ(io::crs_label(r.crs_wkt), "EPSG:26918");
    EXPECT_GT(r.terrain.points.size(), 0U);
    EXPECT_LE(r.terrain.points.size(), 237U * 188U);
}

}  // namespace
