// SPDX-License-Identifier: MIT
// products::surface with raster DEM input: an ESRI ASCII grid read through load_inputs is
// thinned (`dem.max_error`) to a TIN within the bound at every cell (the independent cell scan of
// support/dem_fixtures.hpp, cells rounded as the file holds them), clipped around a survey point
// (`dem.clip_radius`) with the survey point kept, and the options refuse a TIN input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/products/surface.hpp"
#include "support/dem_fixtures.hpp"
#include "support/test_support.hpp"

namespace {

namespace test = dtm::test;

double terrain(double x, double y) {
    return 410.0 + 6.0 * std::sin(x / 13.0 + y / 29.0) + 0.01 * x;
}

dtm::io::LoadedInputs load(const std::vector<std::filesystem::path>& files) {
    dtm::io::LoadOptions o;
    for (const auto& f : files) o.files.push_back({f, dtm::io::InputRole::points});
    return dtm::io::load_inputs(o);
}

TEST(SurfaceDem, ThinnedGridIsWithinTheBoundAtEveryCell) {
    const test::ScratchDir dir;
    test::Dem dem = test::make_dem(61, 47, terrain);
    for (dtm::Point3& p : dem.cells) p.z = std::round(p.z * 1e6) / 1e6;  // as in the file
    test::write_file(dir / "dem.asc", test::ascii_grid(dem));
    dtm::io::LoadedInputs inputs = load({dir / "dem.asc"});
    ASSERT_EQ(inputs.dem_cells.size(), 1U);
    EXPECT_EQ(inputs.dem_cells[0].last - inputs.dem_cells[0].first, dem.cells.size());
    dtm::products::SurfaceOptions options;
    options.dem.max_error = 0.1;
    const dtm::products::Surface s = dtm::products::surface(inputs, options);
    ASSERT_TRUE(s.dem.has_value());
    EXPECT_LE(test::worst_cell_error(s.result.tin, dem), 0.1 + 1e-9);
    EXPECT_LT(s.result.tin.vertices.size(), dem.cells.size() / 2);
    EXPECT_EQ(s.survey_points, s.dem->kept);
    bool noted = false;
    for (const std::string& w : inputs.summaries[0].warnings) {
        noted = noted || w.find("max error") != std::string::npos;
    }
    EXPECT_TRUE(noted);
}

TEST(SurfaceDem, ClipDropsCellsAroundTheSurveyAndKeepsTheSurvey) {
    const test::ScratchDir dir;
    const test::Dem dem = test::make_dem(31, 21, terrain);
    test::write_file(dir / "dem.asc", test::ascii_grid(dem));
    test::write_file(dir / "survey.csv", "x,y,z\n-749970.3,-1049979.6,415.25\n");
    dtm::io::LoadedInputs inputs = load({dir / "dem.asc", dir / "survey.csv"});
    dtm::products::SurfaceOptions options;
    options.dem.clip_radius = 3.0;
    const dtm::products::Surface s = dtm::products::surface(inputs, options);
    ASSERT_TRUE(s.dem.has_value());
    EXPECT_GE(s.dem->clipped, 4U);  // cells of 2 m: at least the four around the point
    EXPECT_EQ(s.survey_points, 1 + dem.cells.size() - s.dem->clipped);
    bool kept = false;
    for (const dtm::Point3& v : s.result.tin.vertices) {
        kept = kept || (v.x == -749970.3 && v.y == -1049979.6 && v.z == 415.25);
    }
    EXPECT_TRUE(kept);
}

TEST(SurfaceDem, OptionsWithoutARasterNameTheirField) {
    const test::ScratchDir dir;
    test::write_file(dir / "survey.csv", "x,y,z\n0,0,1\n1,0,1\n0,1,2\n");
    dtm::io::LoadedInputs inputs = load({dir / "survey.csv"});
    dtm::products::SurfaceOptions options;
    options.dem.max_error = 0.5;
    try {
        (void)dtm::products::surface(inputs, options);
        FAIL();
    } catch (const dtm::OptionError& e) {
        EXPECT_EQ(e.field(), "dem.max_error");
    }
}

}  // namespace
