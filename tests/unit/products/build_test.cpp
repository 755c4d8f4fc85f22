// SPDX-License-Identifier: MIT
// products::build as a library call: every product in the folder in the report's order, the
// stages timed, options in the caller's wording, the cubic surface for the DEM when asked, and
// nothing changed by a failed or cancelled run.
#include "dtm/products/build.hpp"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/products/rules.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;

namespace {

double hill(double x, double y) { return 100.0 + 5.0 * std::sin(x / 15.0) * std::cos(y / 20.0); }

/// A 30 x 30 survey of a smooth hill, in local metres.
dtm::io::LoadOptions survey(const dtm::test::ScratchDir& dir) {
    std::string text = "x,y,z\n";
    for (int j = 0; j < 30; ++j) {
        for (int i = 0; i < 30; ++i) {
            const double x = 2.0 * i + 0.3 * std::sin(j);
            const double y = 2.0 * j + 0.3 * std::cos(i);
            text += std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(hill(x, y)) +
                    "\n";
        }
    }
    dtm::test::write_file(dir / "points.csv", text);
    dtm::io::LoadOptions options;
    options.files.push_back({dir / "points.csv", dtm::io::InputRole::points});
    return options;
}

std::vector<std::string> names_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

TEST(Build, WritesEveryProductAndReportsThemInOrder) {
    const dtm::test::ScratchDir dir;
    const dtm::products::BuildReport report = dtm::products::build(survey(dir), dir / "out");
    const std::vector<std::string> expected{"tin.ply", "tin.2dm",       "surface.vtp",
                                            "dem.tif", "hillshade.tif", "contours.gpkg",
                                            "map.pdf", "dtm.qgs",       "report.json"};
    EXPECT_EQ(report.outputs, expected);
    std::vector<std::string> sorted = expected;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(names_in(dir / "out"), sorted);
    EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"out", "points.csv"}));
    std::vector<std::string> stages;
    for (const auto& t : report.timings) stages.push_back(t.stage);
    EXPECT_EQ(stages, (std::vector<std::string>{"read", "triangulate", "write_tin", "dem",
                                                "contours", "map", "project"}));
    EXPECT_EQ(report.accounting.survey_points.total, 900u);
    EXPECT_EQ(report.surface.vertex_count, 900u);
    EXPECT_GT(report.contour_lines, 0u);
    EXPECT_GT(report.dem.cols, 0u);
    EXPECT_EQ(report.cell_rule, dtm::products::default_cell_rule);
}

TEST(Build, GivenCellAndIntervalAreReportedInTheCallersWording) {
    const dtm::test::ScratchDir dir;
    dtm::products::BuildOptions options;
    options.cell = 0.5;
    options.interval = 0.25;
    const auto plain = dtm::products::build(survey(dir), dir / "a", options);
    EXPECT_EQ(plain.cell_rule, "given (`cell`)");
    EXPECT_EQ(plain.interval_rule, "given (`interval`)");
    EXPECT_EQ(plain.dem.cell, 0.5);
    EXPECT_EQ(plain.contour_interval, 0.25);
    options.wording = [](std::string_view text) {
        std::string s(text);
        s.replace(s.find('`'), s.rfind('`') - s.find('`') + 1, "--option");
        return s;
    };
    const auto worded = dtm::products::build(survey(dir), dir / "b", options);
    EXPECT_EQ(worded.cell_rule, "given (--option)");
    EXPECT_NE(dtm::test::read_file(dir / "b" / "report.json").find("given (--option)"),
              std::string::npos);
}

/// RMS difference of the DEM of @p report in @p folder from the hill, over its data cells.
double dem_rmse(const fs::path& folder, const dtm::products::BuildReport& report) {
    GDALAllRegister();
    GDALDataset* ds = GDALDataset::Open((folder / "dem.tif").c_str(), GDAL_OF_RASTER);
    EXPECT_NE(ds, nullptr);
    if (ds == nullptr) return 0.0;
    const dtm::GridSpec& g = report.dem;
    std::vector<float> v(g.cols * g.rows);
    EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(
                  GF_Read, 0, 0, static_cast<int>(g.cols), static_cast<int>(g.rows), v.data(),
                  static_cast<int>(g.cols), static_cast<int>(g.rows), GDT_Float32, 0, 0, nullptr),
              CE_None);
    const double nodata = ds->GetRasterBand(1)->GetNoDataValue();
    GDALClose(ds);
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t r = 0; r < g.rows; ++r) {
        for (std::size_t c = 0; c < g.cols; ++c) {
            const float z = v[r * g.cols + c];
            if (z == static_cast<float>(nodata)) continue;
            const double e = z - hill(g.center_x(c), g.center_y(r));
            sum += e * e;
            ++n;
        }
    }
    EXPECT_GT(n, g.cols * g.rows / 2);
    return std::sqrt(sum / static_cast<double>(n));
}

TEST(Build, CubicInterpolationGivesTheDemAndIsReported) {
    const dtm::test::ScratchDir dir;
    dtm::products::BuildOptions options;
    options.cell = 0.5;
    const auto linear = dtm::products::build(survey(dir), dir / "linear", options);
    options.interpolation = dtm::Interpolation::cubic;
    const auto cubic = dtm::products::build(survey(dir), dir / "cubic", options);
    EXPECT_EQ(linear.interpolation, "linear");
    EXPECT_EQ(cubic.interpolation, "cubic");
    EXPECT_NE(
        dtm::test::read_file(dir / "cubic" / "report.json").find(R"("interpolation": "cubic")"),
        std::string::npos);
    const double e_linear = dem_rmse(dir / "linear", linear);
    const double e_cubic = dem_rmse(dir / "cubic", cubic);
    EXPECT_LT(e_cubic, 0.25 * e_linear) << "the hill is smooth: the cubic is much closer";
    EXPECT_FALSE(cubic.contour_flats.has_value()) << "points are no contours";
}

TEST(Build, CancelledRunLeavesTheFolderAsItWas) {
    const dtm::test::ScratchDir dir;
    fs::create_directories(dir / "out");
    dtm::test::write_file(dir / "out" / "tin.ply", "earlier result");
    const dtm::Progress progress([](double, std::string_view what) { return what != "contour"; });
    EXPECT_THROW((void)dtm::products::build(survey(dir), dir / "out", {}, progress),
                 dtm::Cancelled);
    EXPECT_EQ(names_in(dir / "out"), std::vector<std::string>{"tin.ply"});
    EXPECT_EQ(dtm::test::read_file(dir / "out" / "tin.ply"), "earlier result");
    EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"out", "points.csv"}));
}

TEST(Build, OutputFolderThatIsAFileIsAnOptionError) {
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "out", "a file");
    try {
        (void)dtm::products::build(survey(dir), dir / "out");
        FAIL() << "no exception";
    } catch (const dtm::OptionError& e) {
        EXPECT_EQ(e.field(), "out_dir");
        EXPECT_NE(std::string(e.what()).find("is a file, not a folder"), std::string::npos);
    }
    EXPECT_EQ(dtm::test::read_file(dir / "out"), "a file");
}

}  // namespace
