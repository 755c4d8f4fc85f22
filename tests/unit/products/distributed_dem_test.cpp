// SPDX-License-Identifier: MIT
// products::distributed_dem on 1 to 64 in-process ranks (R-P3): the VRT of the per-rank tiles
// reads back, cell for cell and bit for bit, as the serial triangulation rasterised on the grid
// `dtm grid` picks (an independent path: triangulate + rasterize on one thread); uniform points,
// a cocircular lattice whose rows of centres run along triangle edges, S-JTSK magnitudes, a given
// extent, fewer grid rows than ranks, fewer points than ranks, and random delays before every
// send; the hillshade and slope tiles against gdaldem of the serial DEM.
#include "dtm/products/distributed_dem.hpp"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "dtm/algo/rasterize.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/io/grid_writer.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

struct Case {
    std::string name;
    std::vector<dtm::Point3> points;
    double cell = 1.0;
    std::optional<dtm::Box2> extent;
};

std::vector<Case> cases() {
    std::vector<Case> out;
    std::mt19937_64 rng(20261203);
    std::uniform_real_distribution<double> u(0.0, 200.0);
    Case uniform{"uniform", {}, 0.7, {}};
    for (int i = 0; i < 3000; ++i) {
        const double x = u(rng), y = u(rng);
        uniform.points.push_back({x, y, 300.0 + 0.05 * x + 3.0 * std::sin(y / 9.0)});
    }
    out.push_back(uniform);
    Case lattice{"lattice", {}, 0.25, {}};  // centres on lattice rows, columns and diagonals
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 40; ++j) {
            lattice.points.push_back(
                {i * 2.0 + 0.125, j * 2.0 + 0.125, 100.0 + ((i * 7 + j * 13) % 17) / 3.0});
        }
    }
    out.push_back(lattice);
    Case sjtsk{"sjtsk", {}, 0.5, dtm::Box2{}};
    for (int i = 0; i < 2000; ++i) {
        const double x = -750'000.0 + std::round(u(rng) * 1000.0) / 1000.0;
        const double y = -1'050'000.0 + std::round(u(rng) * 1000.0) / 1000.0;
        sjtsk.points.push_back({x, y, 250.0 + std::fmod(u(rng), 10.0)});
    }
    sjtsk.extent = dtm::Box2{-749'950.0, -1'049'960.0, -749'870.5, -1'049'880.0};
    out.push_back(sjtsk);
    Case few_rows{"few rows", {}, 5.0, {}};  // 3 rows: most ranks compute none
    for (int i = 0; i < 50; ++i) few_rows.points.push_back({u(rng), u(rng) / 15.0, u(rng)});
    out.push_back(few_rows);
    Case tiny{"fewer points than ranks", {}, 0.5, {}};  // 5 points: most ranks hold none
    for (int i = 0; i < 5; ++i) tiny.points.push_back({u(rng) / 20.0, u(rng) / 20.0, u(rng)});
    out.push_back(tiny);
    return out;
}

std::string csv(const std::vector<dtm::Point3>& points) {
    std::string text = "x,y,z\n";
    char line[128];
    for (const dtm::Point3& p : points) {
        std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g\n", p.x, p.y, p.z);
        text += line;
    }
    return text;
}

dtm::Grid serial_dem(const Case& c) {
    dtm::TerrainInput input;
    input.points = c.points;
    const dtm::Tin tin = dtm::triangulate(input, {}).tin;
    const dtm::GridSpec spec = c.extent ? dtm::extent_grid_spec(*c.extent, c.cell)
                                        : dtm::snapped_grid_spec(dtm::tin_bounds(tin), c.cell);
    return dtm::rasterize(tin, spec, {.nodata = -9999.0F, .threads = 1});
}

std::vector<float> read_vrt(const fs::path& vrt, const dtm::GridSpec& spec) {
    GDALAllRegister();
    GDALDataset* ds = GDALDataset::Open(vrt.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
    EXPECT_NE(ds, nullptr) << vrt;
    if (ds == nullptr) return {};
    std::vector<float> values(spec.cols * spec.rows);
    double gt[6];
    EXPECT_EQ(ds->GetGeoTransform(gt), CE_None);
    EXPECT_EQ(gt[0], spec.xmin);
    EXPECT_EQ(gt[3], spec.ymax);
    EXPECT_EQ(gt[1], spec.cell);
    EXPECT_EQ(ds->GetRasterXSize(), static_cast<int>(spec.cols));
    EXPECT_EQ(ds->GetRasterYSize(), static_cast<int>(spec.rows));
    const int cols = static_cast<int>(spec.cols), rows = static_cast<int>(spec.rows);
    EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, cols, rows, values.data(), cols, rows,
                                             GDT_Float32, 0, 0, nullptr),
              CE_None);
    GDALClose(ds);
    return values;
}

dtm::products::DistributedDemResult run(const Case& c,
                                        const fs::path& folder,
                                        int ranks,
                                        unsigned jitter = 0,
                                        bool derivatives = false) {
    dtm::products::DistributedDemOptions options;
    if (derivatives) {
        options.hillshade = folder / ("hs-" + std::to_string(ranks) + ".vrt");
        options.slope = folder / ("slope-" + std::to_string(ranks) + ".vrt");
    }
    options.source.input = {folder / "points.csv", dtm::io::InputRole::points};
    options.cell = c.cell;
    options.extent = c.extent;
    options.output = folder / ("dem-" + std::to_string(ranks) + ".vrt");
    std::vector<dtm::products::DistributedDemResult> results(static_cast<std::size_t>(ranks));
    dtm::dist::run_in_process(ranks,
                              [&](dtm::dist::Comm& comm) {
                                  results[static_cast<std::size_t>(comm.rank())] =
                                      dtm::products::distributed_dem(comm, options, {});
                              },
                              {jitter, 7});
    for (const auto& r : results) {
        EXPECT_EQ(r.spec.rows, results[0].spec.rows);
        EXPECT_EQ(r.filled, results[0].filled);
    }
    return results[0];
}

TEST(DistributedDem, TilesOfAnyRankCountMosaicToTheSerialDemBitForBit) {
    for (const Case& c : cases()) {
        const dtm::test::ScratchDir dir;
        dtm::test::write_file(dir / "points.csv", csv(c.points));
        const dtm::Grid serial = serial_dem(c);
        std::uint64_t serial_filled = 0;
        for (const float v : serial.values) serial_filled += v != -9999.0F ? 1 : 0;
        for (const int ranks : {1, 2, 7, 16, 64}) {
            const std::string what = c.name + " on " + std::to_string(ranks) + " ranks";
            const auto result = run(c, dir.path(), ranks);
            EXPECT_EQ(result.ranks, ranks) << what;
            ASSERT_EQ(result.spec.cols, serial.spec.cols) << what;
            ASSERT_EQ(result.spec.rows, serial.spec.rows) << what;
            EXPECT_EQ(result.spec.xmin, serial.spec.xmin) << what;
            EXPECT_EQ(result.spec.ymax, serial.spec.ymax) << what;
            EXPECT_EQ(result.filled, serial_filled) << what;
            EXPECT_EQ(result.vertices, c.points.size()) << what;
            EXPECT_EQ(result.tiles.size(),
                      std::min<std::size_t>(serial.spec.rows, static_cast<std::size_t>(ranks)))
                << what;
            const std::vector<float> cells =
                read_vrt(dir / ("dem-" + std::to_string(ranks) + ".vrt"), serial.spec);
            ASSERT_EQ(cells.size(), serial.values.size()) << what;
            EXPECT_EQ(std::memcmp(cells.data(), serial.values.data(), cells.size() * sizeof(float)),
                      0)
                << what;
        }
    }
}

TEST(DistributedDem, RandomDelaysChangeNoCell) {
    const Case c = cases().front();
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "points.csv", csv(c.points));
    const dtm::Grid serial = serial_dem(c);
    for (const int ranks : {3, 16}) {
        const auto result = run(c, dir.path(), ranks, 300);
        const std::vector<float> cells =
            read_vrt(dir / ("dem-" + std::to_string(ranks) + ".vrt"), serial.spec);
        EXPECT_TRUE(cells == serial.values) << ranks << " ranks";
    }
}

/// Every cell of the raster @p path as doubles (exact for Byte and Float32).
std::vector<double> cells_of(const fs::path& path) {
    GDALAllRegister();
    GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
    EXPECT_NE(ds, nullptr) << path;
    if (ds == nullptr) return {};
    const int cols = ds->GetRasterXSize(), rows = ds->GetRasterYSize();
    std::vector<double> values(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows));
    EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, cols, rows, values.data(), cols, rows,
                                             GDT_Float64, 0, 0, nullptr),
              CE_None);
    GDALClose(ds);
    return values;
}

TEST(DistributedDem, HillshadeAndSlopeTilesEqualGdaldemOfTheSerialDem) {
    const std::vector<Case> all = cases();
    for (const Case& c : {all[0], all[3]}) {  // uniform; 3 rows: one-row tiles, idle ranks
        const dtm::test::ScratchDir dir;
        dtm::test::write_file(dir / "points.csv", csv(c.points));
        dtm::io::write_grid(serial_dem(c), dir / "serial.tif", {});
        dtm::io::write_dem_derivative(dir / "serial.tif", dir / "serial-hs.tif",
                                      dtm::io::DemDerivative::hillshade);
        dtm::io::write_dem_derivative(dir / "serial.tif", dir / "serial-slope.tif",
                                      dtm::io::DemDerivative::slope);
        const std::vector<double> hs = cells_of(dir / "serial-hs.tif");
        const std::vector<double> slope = cells_of(dir / "serial-slope.tif");
        ASSERT_FALSE(hs.empty());
        for (const int ranks : {2, 7, 16}) {
            const std::string what = c.name + " on " + std::to_string(ranks) + " ranks";
            const auto result = run(c, dir.path(), ranks, 0, true);
            const std::size_t tiles =
                std::min<std::size_t>(result.spec.rows, static_cast<std::size_t>(ranks));
            EXPECT_EQ(result.derived_tiles.size(), 2 * tiles) << what;
            EXPECT_TRUE(cells_of(dir / ("hs-" + std::to_string(ranks) + ".vrt")) == hs) << what;
            EXPECT_TRUE(cells_of(dir / ("slope-" + std::to_string(ranks) + ".vrt")) == slope)
                << what;
        }
    }
}

}  // namespace
