// SPDX-License-Identifier: MIT
// `dtm grid`: exit codes, a GeoTIFF that GDAL opens with the CRS, NoData outside the TIN, exact
// values on a planar surface, --extent, other drivers by extension, gdaldem derivatives,
// --interpolation.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <memory>
#include <sstream>

#include "support/test_support.hpp"

namespace {

struct Closer {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

double plane(double x, double y) {
    return 250.0 + 0.5 * (x + 750'000.0) - 0.25 * (y + 1'050'000.0);
}

/// A diamond of survey points at S-JTSK offsets on a plane: the TIN's linear interpolation of a
/// plane is the plane itself, whatever the triangulation.
std::filesystem::path write_diamond(const dtm::test::ScratchDir& dir) {
    std::ostringstream csv;
    csv << "x,y,z\n";
    csv.precision(12);
    for (int i = -10; i <= 10; ++i) {
        for (int j = -10; j <= 10; ++j) {
            if (std::abs(i) + std::abs(j) > 10) {
                continue;
            }
            const double x = -750'000.0 + 10.0 + i + 0.01 * (j % 3);
            const double y = -1'050'000.0 + 10.0 + j + 0.013 * (i % 2);
            csv << x << ',' << y << ',' << plane(x, y) << '\n';
        }
    }
    const auto path = dir / "points.csv";
    dtm::test::write_file(path, csv.str());
    return path;
}

Dataset open_raster(const std::filesystem::path& path) {
    GDALAllRegister();
    return Dataset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
}

TEST(CliGrid, WritesGeoTiffWithCrsPlaneValuesAndNoDataOutsideTheTin) {
    const dtm::test::ScratchDir dir;
    const auto points = write_diamond(dir);
    const auto r = dtm::test::run_dtm({"grid", points.string(), "-o", (dir / "dem.tif").string(),
                                       "--cell", "0.5", "--crs", "EPSG:5514", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Dataset ds = open_raster(dir / "dem.tif");
    ASSERT_TRUE(ds);
    ASSERT_NE(ds->GetSpatialRef(), nullptr);
    OGRSpatialReference expected;
    expected.importFromEPSG(5514);
    EXPECT_TRUE(ds->GetSpatialRef()->IsSame(&expected));
    double gt[6];
    ASSERT_EQ(ds->GetGeoTransform(gt), CE_None);
    EXPECT_EQ(gt[1], 0.5);
    EXPECT_EQ(std::fmod(gt[0], 0.5), 0.0);  // snapped to the cell size
    const int cols = ds->GetRasterXSize(), rows = ds->GetRasterYSize();
    std::vector<float> v(static_cast<std::size_t>(cols * rows));
    ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, cols, rows, v.data(), cols, rows,
                                             GDT_Float32, 0, 0, nullptr),
              CE_None);
    int has_nodata = 0;
    const double nodata = ds->GetRasterBand(1)->GetNoDataValue(&has_nodata);
    ASSERT_TRUE(has_nodata);
    EXPECT_EQ(v[0], static_cast<float>(nodata));  // the corner is outside the diamond
    std::size_t with_data = 0;
    for (int row = 0; row < rows; ++row) {
        for (int col = 0; col < cols; ++col) {
            const float value = v[static_cast<std::size_t>(row * cols + col)];
            if (value == static_cast<float>(nodata)) {
                continue;
            }
            ++with_data;
            const double x = gt[0] + (col + 0.5) * gt[1], y = gt[3] + (row + 0.5) * gt[5];
            ASSERT_NEAR(value, plane(x, y), 1e-3) << row << "," << col;
        }
    }
    EXPECT_GT(with_data, 600U);
    EXPECT_LT(with_data, static_cast<std::size_t>(cols * rows) * 3 / 4);
}

TEST(CliGrid, ExtentGivesTheOuterEdgesAndAscPicksTheAsciiGridDriver) {
    const dtm::test::ScratchDir dir;
    const auto points = write_diamond(dir);
    const auto r = dtm::test::run_dtm(
        {"grid", points.string(), "-o", (dir / "dem.asc").string(), "--cell", "1", "--extent",
         "-750005,-1049995,-749985,-1049985", "--nodata", "-1", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Dataset ds = open_raster(dir / "dem.asc");
    ASSERT_TRUE(ds);
    EXPECT_STREQ(ds->GetDriver()->GetDescription(), "AAIGrid");
    EXPECT_EQ(ds->GetRasterXSize(), 20);
    EXPECT_EQ(ds->GetRasterYSize(), 10);
    double gt[6];
    ds->GetGeoTransform(gt);
    EXPECT_EQ(gt[0], -750005.0);
    EXPECT_EQ(gt[3], -1049985.0);
    EXPECT_EQ(ds->GetRasterBand(1)->GetNoDataValue(), -1.0);
}

TEST(CliGrid, HillshadeSlopeAndAspectAreWrittenNextToTheDem) {
    const dtm::test::ScratchDir dir;
    const auto points = write_diamond(dir);
    const auto r = dtm::test::run_dtm(
        {"grid", points.string(), "-o", (dir / "dem.tif").string(), "--cell", "0.5", "--cog",
         "--hillshade", (dir / "hs.tif").string(), "--slope", (dir / "slope.tif").string(),
         "--aspect", (dir / "aspect.tif").string(), "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Dataset dem = open_raster(dir / "dem.tif");
    ASSERT_TRUE(dem);
    EXPECT_STREQ(dem->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE"), "COG");
    for (const char* name : {"hs.tif", "slope.tif", "aspect.tif"}) {
        EXPECT_TRUE(open_raster(dir / name)) << name;
    }
}

TEST(CliGrid, BadUsageExitsWithTwoAndWritesNothing) {
    const dtm::test::ScratchDir dir;
    const auto points = write_diamond(dir);
    const auto out = (dir / "dem.tif").string();
    EXPECT_EQ(dtm::test::run_dtm({"grid", points.string(), "-o", out, "-q"}).exit_code,
              2);  // no --cell
    EXPECT_EQ(
        dtm::test::run_dtm({"grid", points.string(), "-o", out, "--cell", "-1", "-q"}).exit_code,
        2);
    EXPECT_EQ(dtm::test::run_dtm(
                  {"grid", points.string(), "-o", out, "--cell", "1", "--extent", "1,2,3", "-q"})
                  .exit_code,
              2);
    EXPECT_EQ(dtm::test::run_dtm({"grid", points.string(), "-o", (dir / "dem.nosuch").string(),
                                  "--cell", "1", "-q"})
                  .exit_code,
              2);
    EXPECT_EQ(
        dtm::test::run_dtm({"grid", (dir / "missing.csv").string(), "-o", out, "--cell", "1", "-q"})
            .exit_code,
        2);
    EXPECT_EQ(
        dtm::test::run_dtm({"grid", points.string(), "-o", out, "--cell", "1e-6", "-q"}).exit_code,
        2);  // absurd raster size
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace

#include "dtm/geom/predicates.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/tin_file.hpp"

namespace {

TEST(CliGrid, RealSjtskSurveyWithBreaklinesEqualsBruteForceOnItsTin) {
    const std::string base = "points-cz-sjtsk-jvf-dtm/derived/";
    if (!dtm::test::shared_data_available(base + "zps_points_pointz.shp")) {
        GTEST_SKIP() << "shared data not available";
    }
    const dtm::test::ScratchDir dir;
    const std::vector<std::string> inputs{
        dtm::test::shared_data_path(base + "zps_points_pointz.shp").string(), "--breaklines",
        dtm::test::shared_data_path(base + "zps_breaklines_polylinez.shp").string()};
    std::vector<std::string> tin_args{"tin"}, grid_args{"grid"};
    tin_args.insert(tin_args.end(), inputs.begin(), inputs.end());
    grid_args.insert(grid_args.end(), inputs.begin(), inputs.end());
    tin_args.insert(tin_args.end(), {"-o", (dir / "tin.ply").string(), "-q"});
    grid_args.insert(grid_args.end(), {"-o", (dir / "dem.tif").string(), "--cell", "1.5", "-q"});
    ASSERT_EQ(dtm::test::run_dtm(tin_args).exit_code, 0);
    const auto r = dtm::test::run_dtm(grid_args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const dtm::Tin tin = dtm::io::read_tin_ply(dir / "tin.ply").tin;
    Dataset ds = open_raster(dir / "dem.tif");
    ASSERT_TRUE(ds);
    double gt[6];
    ds->GetGeoTransform(gt);
    const int cols = ds->GetRasterXSize(), rows = ds->GetRasterYSize();
    std::vector<float> v(static_cast<std::size_t>(cols * rows));
    ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, cols, rows, v.data(), cols, rows,
                                             GDT_Float32, 0, 0, nullptr),
              CE_None);
    const float nodata = static_cast<float>(ds->GetRasterBand(1)->GetNoDataValue());
    std::size_t checked = 0;
    for (int row = 0; row < rows; ++row) {
        for (int col = 0; col < cols; ++col) {
            const double x = gt[0] + (col + 0.5) * gt[1], y = gt[3] + (row + 0.5) * gt[5];
            double expected = std::nan("");
            for (const dtm::Triangle& t : tin.triangles) {
                const auto &a = tin.vertices[t.v[0]], &b = tin.vertices[t.v[1]],
                           &c = tin.vertices[t.v[2]];
                if (dtm::geom::orient2d(a.x, a.y, b.x, b.y, x, y) >= 0 &&
                    dtm::geom::orient2d(b.x, b.y, c.x, c.y, x, y) >= 0 &&
                    dtm::geom::orient2d(c.x, c.y, a.x, a.y, x, y) >= 0) {
                    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
                    const double wb = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
                    const double wc = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
                    expected = (1 - wb - wc) * a.z + wb * b.z + wc * c.z;
                    break;
                }
            }
            const float got = v[static_cast<std::size_t>(row * cols + col)];
            if (std::isnan(expected)) {
                ASSERT_EQ(got, nodata) << row << "," << col;
            } else {
                ASSERT_NEAR(got, expected, 1e-3) << row << "," << col;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 1000U);
}

TEST(CliGrid, InterpolationPicksTheSurfaceAndCubicFollowsACurvedOneCloser) {
    const dtm::test::ScratchDir dir;
    const auto bowl = [](double x, double y) { return 0.02 * (x * x + 0.5 * y * y + x * y); };
    std::ostringstream csv;
    csv << "x,y,z\n";
    for (int i = 0; i <= 12; ++i) {
        for (int j = 0; j <= 12; ++j) {
            const double x = 5.0 * i + 0.7 * std::sin(j), y = 5.0 * j + 0.6 * std::cos(i);
            csv << x << ',' << y << ',' << bowl(x, y) << '\n';
        }
    }
    dtm::test::write_file(dir / "bowl.csv", csv.str());
    double rmse[2] = {0.0, 0.0};
    const char* methods[2] = {"linear", "CUBIC"};
    for (int m = 0; m < 2; ++m) {
        const auto out = dir / (std::string(methods[m]) + ".tif");
        const auto r = dtm::test::run_dtm({"grid", (dir / "bowl.csv").string(), "-o", out.string(),
                                           "--cell", "1", "--extent", "10,10,50,50",
                                           "--interpolation", methods[m], "-q"});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        Dataset ds = open_raster(out);
        ASSERT_TRUE(ds);
        std::vector<float> v(40 * 40);
        ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 40, 40, v.data(), 40, 40,
                                                 GDT_Float32, 0, 0, nullptr),
                  CE_None);
        double sum = 0.0;
        for (int row = 0; row < 40; ++row) {
            for (int col = 0; col < 40; ++col) {
                const double e =
                    v[static_cast<std::size_t>(row * 40 + col)] - bowl(10.5 + col, 49.5 - row);
                sum += e * e;
            }
        }
        rmse[m] = std::sqrt(sum / 1600.0);
    }
    EXPECT_LT(rmse[1], 0.2 * rmse[0]) << "linear " << rmse[0] << ", cubic " << rmse[1];
    const auto lines = dtm::test::run_dtm({"contour", (dir / "bowl.csv").string(), "-o",
                                           (dir / "c.geojson").string(), "--interval", "1",
                                           "--interpolation", "cubic", "-q"});
    EXPECT_EQ(lines.exit_code, 0) << lines.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "c.geojson"));
    const auto bad =
        dtm::test::run_dtm({"grid", (dir / "bowl.csv").string(), "-o", (dir / "x.tif").string(),
                            "--cell", "1", "--interpolation", "spline"});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("--interpolation"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.tif"));
}

}  // namespace
