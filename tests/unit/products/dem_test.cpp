// SPDX-License-Identifier: MIT
// products::write_dem (`dtm grid` on one machine): a planar TIN sampled into an Arc/Info ASCII
// grid read back as text (every cell centre on the TIN has the plane's height, every other cell
// NoData, the count of cells with data is the count in the file), the grid's cell limit and the
// output checks made before any input is read; a TIN given up to write_dem (renumbered in place)
// gives the same file as one it only reads.
#include "dtm/products/dem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"
#include "support/terrain_fixtures.hpp"
#include "support/test_support.hpp"

namespace {

namespace test = dtm::test;

double plane(double x, double y) { return 200.0 + 0.25 * x - 0.5 * y; }

/// A square of side 10 with its centre, four triangles, heights on the plane.
dtm::Tin square_tin() {
    dtm::Tin tin;
    for (const auto& [x, y] : {std::pair{0.0, 0.0}, {10.0, 0.0}, {10.0, 10.0}, {0.0, 10.0}}) {
        tin.vertices.push_back({x, y, plane(x, y)});
    }
    tin.vertices.push_back({5.0, 5.0, plane(5.0, 5.0)});
    for (dtm::VertexIndex i = 0; i < 4; ++i) {
        tin.triangles.push_back({{i, (i + 1) % 4, 4}, {}});
    }
    dtm::link_neighbours(tin);
    return tin;
}

TEST(ProductsDem, EveryCellCentreOnTheTinHasTheSurfaceHeight) {
    const test::ScratchDir dir;
    dtm::products::DemOptions options;
    options.cell = 1.0;
    options.extent = dtm::Box2{-2.0, -2.0, 12.0, 12.0};
    options.nodata = -1.0F;
    const auto result =
        dtm::products::write_dem(square_tin(), "", options, dir / "dem.asc", dtm::Progress{});
    EXPECT_EQ(result.spec.cols, 14U);
    EXPECT_EQ(result.spec.rows, 14U);
    std::istringstream in(test::read_file(dir / "dem.asc"));
    std::string word;
    double value = 0.0;
    std::size_t cols = 0, rows = 0;
    for (int i = 0; i < 6; ++i) {  // ncols, nrows, xllcorner, yllcorner, cellsize, NODATA_value
        in >> word >> value;
        if (word == "ncols") cols = static_cast<std::size_t>(value);
        if (word == "nrows") rows = static_cast<std::size_t>(value);
    }
    ASSERT_EQ(cols, 14U);
    ASSERT_EQ(rows, 14U);
    std::uint64_t filled = 0;
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t c = 0; c < cols; ++c) {
            ASSERT_TRUE(in >> value) << "cell " << r << "," << c;
            const double x = -2.0 + static_cast<double>(c) + 0.5;
            const double y = 12.0 - static_cast<double>(r) - 0.5;
            if (x > 0.0 && x < 10.0 && y > 0.0 && y < 10.0) {
                EXPECT_NEAR(value, plane(x, y), 1e-4) << "cell " << r << "," << c;
                ++filled;
            } else {
                EXPECT_EQ(value, -1.0) << "cell " << r << "," << c;
            }
        }
    }
    EXPECT_EQ(filled, 100U);
    EXPECT_EQ(result.filled, filled);
}

TEST(ProductsDem, AGivenUpTinGivesTheSameFileAsAReadOne) {
    // Vertices in input order (random in space): the rasteriser's renumbering is needed, in a
    // copy for the TIN it only reads, in place for the one given up.
    dtm::TerrainInput input;
    input.points = test::random_points(20000, 7);
    const dtm::Tin tin = dtm::triangulate(input).tin;
    const test::ScratchDir dir;
    for (const auto interpolation : {dtm::Interpolation::linear, dtm::Interpolation::cubic}) {
        dtm::products::DemOptions options;
        options.cell = 3.7;
        options.interpolation = interpolation;
        dtm::products::write_dem(tin, "", options, dir / "read.asc");
        dtm::Tin given = tin;
        dtm::products::write_dem(std::move(given), "", options, dir / "given.asc");
        EXPECT_EQ(test::read_file(dir / "given.asc"), test::read_file(dir / "read.asc"));
    }
}

TEST(ProductsDem, TheCellLimitNamesTheCellOption) {
    try {
        (void)dtm::products::dem_grid_spec({0.0, 0.0, 1e6, 1e6}, 1e-3, std::nullopt);
        FAIL() << "2^36 cells passed";
    } catch (const dtm::OptionError& e) {
        EXPECT_EQ(e.field(), "cell");
        EXPECT_NE(std::string(e.what()).find("2^36"), std::string::npos);
    }
    EXPECT_NO_THROW((void)dtm::products::dem_grid_spec({0.0, 0.0, 1e3, 1e3}, 1.0, std::nullopt));
}

TEST(ProductsDem, OutputsAreCheckedBeforeAnyInput) {
    const test::ScratchDir dir;
    dtm::products::DemOptions options;
    options.cell = 1.0;
    options.cog = true;
    EXPECT_THROW(dtm::products::check_dem_outputs(dir / "dem.asc", options), dtm::OptionError);
    options.cog = false;
    EXPECT_THROW(dtm::products::check_dem_outputs(dir / "dem.unknown-raster", options),
                 dtm::UsageError);
    options.hillshade = dir / "missing-folder" / "shade.tif";
    EXPECT_THROW(dtm::products::check_dem_outputs(dir / "dem.tif", options), dtm::UsageError);
    options.hillshade = dir / "shade.tif";
    EXPECT_NO_THROW(dtm::products::check_dem_outputs(dir / "dem.tif", options));
}

TEST(ProductsDem, ATinWithoutTrianglesIsAnInputError) {
    const test::ScratchDir dir;
    dtm::products::DemOptions options;
    options.cell = 1.0;
    EXPECT_THROW(dtm::products::write_dem(dtm::Tin{}, "", options, dir / "dem.tif"),
                 dtm::InputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "dem.tif"));
}

TEST(ProductsDem, TheHillshadeIsWrittenBesideTheDem) {
    const test::ScratchDir dir;
    dtm::products::DemOptions options;
    options.cell = 0.5;
    options.hillshade = dir / "shade.tif";
    const auto result = dtm::products::write_dem(square_tin(), "", options, dir / "dem.tif");
    EXPECT_EQ(result.filled, 400U);
    EXPECT_TRUE(std::filesystem::exists(dir / "dem.tif"));
    EXPECT_TRUE(std::filesystem::exists(dir / "shade.tif"));
}

}  // namespace
