// SPDX-License-Identifier: MIT
// GridWriter: GeoTIFF (tiled, DEFLATE), COG, ASCII grid by extension, CRS, NoData, geotransform,
// streamed rows land where they belong, atomic output, and gdaldem derivatives.
#include "dtm/io/grid_writer.hpp"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <memory>

#include "dtm/core/error.hpp"
#include "support/test_support.hpp"

namespace {

struct Closer {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

Dataset open_raster(const std::filesystem::path& path) {
    return Dataset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
}

std::string epsg_wkt(int code) {
    OGRSpatialReference srs;
    srs.importFromEPSG(code);
    char* wkt = nullptr;
    srs.exportToWkt(&wkt);
    std::string text(wkt);
    CPLFree(wkt);
    return text;
}

dtm::Grid sample_grid() {
    dtm::Grid grid;
    grid.spec = {.xmin = -750'010.0, .ymax = -1'049'990.0, .cell = 0.5, .cols = 300, .rows = 270};
    grid.nodata = -9999.0F;
    for (std::size_t r = 0; r < grid.spec.rows; ++r) {
        for (std::size_t c = 0; c < grid.spec.cols; ++c) {
            grid.values.push_back(c < 10
                                      ? grid.nodata
                                      : static_cast<float>(200.0 + 0.25 * static_cast<double>(r) +
                                                           0.5 * static_cast<double>(c)));
        }
    }
    return grid;
}

void expect_same_raster(const std::filesystem::path& path, const dtm::Grid& grid, bool with_crs) {
    Dataset ds = open_raster(path);
    ASSERT_TRUE(ds) << path;
    ASSERT_EQ(ds->GetRasterXSize(), static_cast<int>(grid.spec.cols));
    ASSERT_EQ(ds->GetRasterYSize(), static_cast<int>(grid.spec.rows));
    double gt[6];
    ASSERT_EQ(ds->GetGeoTransform(gt), CE_None);
    EXPECT_EQ(gt[0], grid.spec.xmin);
    EXPECT_EQ(gt[1], grid.spec.cell);
    EXPECT_EQ(gt[3], grid.spec.ymax);
    EXPECT_EQ(gt[5], -grid.spec.cell);
    int has_nodata = 0;
    EXPECT_EQ(ds->GetRasterBand(1)->GetNoDataValue(&has_nodata), -9999.0);
    EXPECT_TRUE(has_nodata);
    std::vector<float> values(grid.values.size());
    ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(
                  GF_Read, 0, 0, static_cast<int>(grid.spec.cols), static_cast<int>(grid.spec.rows),
                  values.data(), static_cast<int>(grid.spec.cols), static_cast<int>(grid.spec.rows),
                  GDT_Float32, 0, 0, nullptr),
              CE_None);
    EXPECT_EQ(values, grid.values);
    if (with_crs) {
        const OGRSpatialReference* srs = ds->GetSpatialRef();
        ASSERT_NE(srs, nullptr);
        OGRSpatialReference expected;
        expected.importFromEPSG(5514);
        EXPECT_TRUE(srs->IsSame(&expected));
    }
}

TEST(GridWriter, GeoTiffIsTiledDeflateWithCrsNoDataAndStreamedRowsInPlace) {
    const dtm::test::ScratchDir dir;
    const dtm::Grid grid = sample_grid();
    dtm::io::GridWriter writer(dir / "dem.tif", grid.spec, {.crs_wkt = epsg_wkt(5514)});
    const std::size_t cols = grid.spec.cols;
    for (std::size_t r = 0; r < grid.spec.rows; r += 7) {  // bands of 7 rows, last one shorter
        const std::size_t n = std::min<std::size_t>(7, grid.spec.rows - r);
        writer.write_rows(r, n, std::span(grid.values).subspan(r * cols, n * cols));
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "dem.tif"));  // nothing visible before commit
    writer.commit();
    expect_same_raster(dir / "dem.tif", grid, true);
    Dataset ds = open_raster(dir / "dem.tif");
    EXPECT_STREQ(ds->GetMetadataItem("COMPRESSION", "IMAGE_STRUCTURE"), "DEFLATE");
    int bx = 0, by = 0;
    ds->GetRasterBand(1)->GetBlockSize(&bx, &by);
    EXPECT_EQ(bx, 256);
    EXPECT_EQ(by, 256);
    EXPECT_EQ(ds->GetRasterBand(1)->GetRasterDataType(), GDT_Float32);
}

TEST(GridWriter, CogOptionWritesACloudOptimizedGeoTiff) {
    const dtm::test::ScratchDir dir;
    const dtm::Grid grid = sample_grid();
    dtm::io::write_grid(grid, dir / "dem.tif", {.crs_wkt = epsg_wkt(5514), .cog = true});
    expect_same_raster(dir / "dem.tif", grid, true);
    Dataset ds = open_raster(dir / "dem.tif");
    EXPECT_STREQ(ds->GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE"), "COG");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}),
              1);  // no staging left
}

TEST(GridWriter, AscExtensionPicksTheArcInfoAsciiDriver) {
    const dtm::test::ScratchDir dir;
    const dtm::Grid grid = sample_grid();
    dtm::io::write_grid(grid, dir / "dem.asc", {.crs_wkt = epsg_wkt(5514)});
    Dataset ds = open_raster(dir / "dem.asc");
    ASSERT_TRUE(ds);
    EXPECT_STREQ(ds->GetDriver()->GetDescription(), "AAIGrid");
    expect_same_raster(dir / "dem.asc", grid, true);
    EXPECT_TRUE(std::filesystem::exists(dir / "dem.prj"));
    EXPECT_FALSE(std::filesystem::exists(dir / "dem.stage.tif"));
}

TEST(GridWriter, VrtMosaicsRowTilesIntoTheWholeRaster) {
    const dtm::test::ScratchDir dir;
    const dtm::Grid grid = sample_grid();
    const std::size_t cols = grid.spec.cols;
    const std::vector<std::size_t> starts = {0, 1, 100, 200, grid.spec.rows};  // uneven blocks
    std::vector<dtm::io::DemTile> tiles;
    for (std::size_t i = 0; i + 1 < starts.size(); ++i) {
        dtm::GridSpec spec = grid.spec;
        spec.rows = starts[i + 1] - starts[i];
        spec.ymax = grid.spec.ymax - static_cast<double>(starts[i]) * grid.spec.cell;
        const auto file = dir / ("dem-" + std::to_string(i) + ".tif");
        dtm::io::GridWriter writer(file, spec, {.crs_wkt = epsg_wkt(5514)});
        writer.write_rows(0, spec.rows,
                          std::span(grid.values).subspan(starts[i] * cols, spec.rows * cols));
        writer.commit();
        tiles.push_back({file, starts[i], spec.rows});
    }
    dtm::io::write_dem_vrt(dir / "dem.vrt", grid.spec, tiles, {.crs_wkt = epsg_wkt(5514)});
    expect_same_raster(dir / "dem.vrt", grid, true);
    const std::string vrt = dtm::test::read_file(dir / "dem.vrt");
    EXPECT_EQ(vrt.find(dir.path().string()), std::string::npos) << "tile paths are relative";
    tiles.push_back({dir / "missing.tif", 0, 1});
    EXPECT_THROW(dtm::io::write_dem_vrt(dir / "bad.vrt", grid.spec, tiles, {}), dtm::Error);
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.vrt"));
}

TEST(GridWriter, UnknownExtensionIsAUsageErrorAndUncommittedOutputLeavesNothing) {
    const dtm::test::ScratchDir dir;
    const dtm::Grid grid = sample_grid();
    EXPECT_THROW(dtm::io::GridWriter(dir / "dem.nosuchformat", grid.spec, {}), dtm::UsageError);
    {
        dtm::io::GridWriter writer(dir / "dem.tif", grid.spec, {});
        writer.write_rows(0, 1, std::span(grid.values).first(grid.spec.cols));
    }  // destroyed without commit
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

TEST(GridWriter, DemDerivativesComeFromGdalDemProcessing) {
    const dtm::test::ScratchDir dir;
    const dtm::Grid grid = sample_grid();  // a plane: slope 0.25/0.5 and 0.5/0.5 per metre
    dtm::io::write_grid(grid, dir / "dem.tif", {.crs_wkt = epsg_wkt(5514)});
    dtm::io::write_dem_derivative(dir / "dem.tif", dir / "slope.tif",
                                  dtm::io::DemDerivative::slope);
    dtm::io::write_dem_derivative(dir / "dem.tif", dir / "hs.tif",
                                  dtm::io::DemDerivative::hillshade);
    dtm::io::write_dem_derivative(dir / "dem.tif", dir / "aspect.tif",
                                  dtm::io::DemDerivative::aspect);
    Dataset slope = open_raster(dir / "slope.tif");
    ASSERT_TRUE(slope);
    float v = 0.0F;
    ASSERT_EQ(slope->GetRasterBand(1)->RasterIO(GF_Read, 100, 100, 1, 1, &v, 1, 1, GDT_Float32, 0,
                                                0, nullptr),
              CE_None);
    EXPECT_NEAR(v, std::atan(std::hypot(1.0, 0.5)) * 180.0 / M_PI, 1e-3);
    EXPECT_TRUE(open_raster(dir / "hs.tif"));
    EXPECT_TRUE(open_raster(dir / "aspect.tif"));
}

/// Every cell of @p path as doubles (exact for Byte and Float32), with its type and NoData.
struct Cells {
    std::vector<double> values;
    GDALDataType type = GDT_Unknown;
    double nodata = 0.0;
    int has_nodata = 0;
    std::string crs;
};

Cells read_cells(const std::filesystem::path& path) {
    Dataset ds = open_raster(path);
    EXPECT_TRUE(ds) << path;
    Cells out;
    if (!ds) return out;
    GDALRasterBand* band = ds->GetRasterBand(1);
    out.type = band->GetRasterDataType();
    out.nodata = band->GetNoDataValue(&out.has_nodata);
    out.crs = ds->GetProjectionRef();
    const int cols = ds->GetRasterXSize(), rows = ds->GetRasterYSize();
    out.values.resize(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows));
    EXPECT_EQ(band->RasterIO(GF_Read, 0, 0, cols, rows, out.values.data(), cols, rows, GDT_Float64,
                             0, 0, nullptr),
              CE_None);
    return out;
}

TEST(GridWriter, DerivativeRowTilesEqualTheWholeRastersDerivative) {
    const dtm::test::ScratchDir dir;
    dtm::Grid grid = sample_grid();  // made rough, with NoData inside, so every row differs
    for (std::size_t i = 0; i < grid.values.size(); ++i) {
        if (grid.values[i] == grid.nodata) continue;
        grid.values[i] += static_cast<float>((i * 7919) % 23) * 0.37F;
        if (i % 97 == 5) grid.values[i] = grid.nodata;
    }
    dtm::io::write_grid(grid, dir / "dem.tif", {.crs_wkt = epsg_wkt(5514)});
    const std::vector<std::size_t> starts = {0, 1, 2, 100, 101, 269, grid.spec.rows};
    const std::pair<dtm::io::DemDerivative, const char*> kinds[] = {
        {dtm::io::DemDerivative::hillshade, "hs"},
        {dtm::io::DemDerivative::slope, "slope"},
        {dtm::io::DemDerivative::aspect, "aspect"}};
    for (const auto& [kind, name] : kinds) {
        const auto whole = dir / (std::string(name) + ".tif");
        dtm::io::write_dem_derivative(dir / "dem.tif", whole, kind);
        std::vector<dtm::io::DemTile> tiles;
        for (std::size_t i = 0; i + 1 < starts.size(); ++i) {
            const auto tile = dir / (std::string(name) + "-" + std::to_string(i) + ".tif");
            dtm::io::write_dem_derivative_rows(dir / "dem.tif", tile, kind, starts[i],
                                               starts[i + 1] - starts[i]);
            tiles.push_back({tile, starts[i], starts[i + 1] - starts[i]});
        }
        const auto vrt = dir / (std::string(name) + ".vrt");
        dtm::io::write_derivative_vrt(vrt, grid.spec, tiles, epsg_wkt(5514));
        const Cells a = read_cells(whole), b = read_cells(vrt);
        EXPECT_EQ(a.type, b.type) << name;
        EXPECT_EQ(a.has_nodata, b.has_nodata) << name;
        EXPECT_EQ(a.nodata, b.nodata) << name;
        EXPECT_EQ(a.crs, b.crs) << name;
        ASSERT_EQ(a.values.size(), b.values.size()) << name;
        std::size_t differ = 0, nodata = 0;
        for (std::size_t i = 0; i < a.values.size(); ++i) {
            differ += a.values[i] != b.values[i] ? 1 : 0;
            nodata += a.values[i] == a.nodata ? 1 : 0;
        }
        EXPECT_EQ(differ, 0u) << name;
        EXPECT_GT(nodata, 0u) << name;  // the holes' neighbourhoods are NoData in both
        EXPECT_LT(nodata, a.values.size() / 2) << name;
    }
    EXPECT_THROW(dtm::io::write_dem_derivative_rows(dir / "dem.tif", dir / "bad.tif",
                                                    dtm::io::DemDerivative::slope, 200, 71),
                 dtm::Error);
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.tif"));
}

}  // namespace
