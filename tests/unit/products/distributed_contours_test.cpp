// SPDX-License-Identifier: MIT
// products::distributed_contours on 1 to 64 in-process ranks (R-P4): the OGR VRT over the
// per-rank GeoPackages reads back, feature for feature and bit for bit, as the serial
// triangulation's contour lines (triangulate + contour on one thread, an independent path):
// uniform points with smoothing, a lattice whose heights sit on the levels, explicit levels,
// more ranks than levels, fewer points than ranks, and random delays before every send.
#include "dtm/products/distributed_contours.hpp"

#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_api.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/dist/in_process.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

struct Case {
    std::string name;
    std::vector<dtm::Point3> points;
    dtm::ContourOptions contour;
};

std::vector<Case> cases() {
    std::vector<Case> out;
    std::mt19937_64 rng(20261203);
    std::uniform_real_distribution<double> u(0.0, 200.0);
    Case uniform{"uniform smoothed", {}, {}};
    for (int i = 0; i < 3000; ++i) {
        const double x = u(rng), y = u(rng);
        uniform.points.push_back({x, y, 300.0 + 0.05 * x + 3.0 * std::sin(y / 9.0)});
    }
    uniform.contour.interval = 0.5;
    uniform.contour.smooth = 2;
    out.push_back(uniform);
    Case lattice{"lattice", {}, {}};  // heights on the levels: flats, ridges, doubled pieces
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 30; ++j) {
            lattice.points.push_back({i * 2.0, j * 2.0, 100.0 + (i * 7 + j * 13) % 6});
        }
    }
    lattice.contour.interval = 1.0;
    out.push_back(lattice);
    Case fixed = uniform;  // 3 levels: most of 64 ranks trace none
    fixed.name = "fixed levels";
    fixed.contour.fixed_levels = {298.5, 301.25, 304.0};
    fixed.contour.smooth = 1;
    out.push_back(fixed);
    Case tiny{"fewer points than ranks", {}, {}};  // 6 points: most ranks hold none
    for (int i = 0; i < 6; ++i) tiny.points.push_back({u(rng), u(rng), u(rng) / 10.0});
    tiny.contour.interval = 1.0;
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

struct Line {
    double level = 0.0;
    bool index = false, closed = false;
    std::vector<dtm::Point3> points;
    bool operator==(const Line&) const = default;
};

std::vector<Line> serial_lines(const Case& c) {
    dtm::TerrainInput input;
    input.points = c.points;
    const dtm::Tin tin = dtm::triangulate(input, {}).tin;
    dtm::ContourOptions options = c.contour;
    options.threads = 1;
    std::vector<Line> out;
    for (const dtm::Contour& k : dtm::contour(tin, options)) {
        std::vector<dtm::Point3> points = k.line;
        out.push_back({k.level.value, k.level.index, k.closed, points});
    }
    return out;
}

std::vector<Line> read_layer(const fs::path& path) {
    GDALAllRegister();
    GDALDatasetH ds =
        GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
    EXPECT_NE(ds, nullptr) << path;
    if (ds == nullptr) return {};
    OGRLayerH layer = GDALDatasetGetLayerByName(ds, "contours");
    EXPECT_NE(layer, nullptr);
    std::vector<Line> out;
    OGR_L_ResetReading(layer);
    while (OGRFeatureH f = OGR_L_GetNextFeature(layer)) {
        Line line;
        line.level = OGR_F_GetFieldAsDouble(f, OGR_F_GetFieldIndex(f, "elevation"));
        line.index = OGR_F_GetFieldAsInteger(f, OGR_F_GetFieldIndex(f, "index")) != 0;
        line.closed = OGR_F_GetFieldAsInteger(f, OGR_F_GetFieldIndex(f, "closed")) != 0;
        OGRGeometryH g = OGR_F_GetGeometryRef(f);
        for (int i = 0; g != nullptr && i < OGR_G_GetPointCount(g); ++i) {
            line.points.push_back({OGR_G_GetX(g, i), OGR_G_GetY(g, i), OGR_G_GetZ(g, i)});
        }
        out.push_back(std::move(line));
        OGR_F_Destroy(f);
    }
    GDALClose(ds);
    return out;
}

dtm::products::DistributedContourResult run(const Case& c,
                                            const fs::path& folder,
                                            int ranks,
                                            unsigned jitter = 0) {
    dtm::products::DistributedContourOptions options;
    options.source.input = {folder / "points.csv", dtm::io::InputRole::points};
    options.contour = c.contour;
    options.contour.threads = 1;
    options.output = folder / ("contours-" + std::to_string(ranks) + ".vrt");
    std::vector<dtm::products::DistributedContourResult> results(static_cast<std::size_t>(ranks));
    dtm::dist::run_in_process(ranks,
                              [&](dtm::dist::Comm& comm) {
                                  results[static_cast<std::size_t>(comm.rank())] =
                                      dtm::products::distributed_contours(comm, options, {});
                              },
                              {jitter, 11});
    for (const auto& r : results) EXPECT_EQ(r.lines, results[0].lines);
    return results[0];
}

TEST(DistributedContours, PiecesOfAnyRankCountReadAsTheSerialLinesBitForBit) {
    for (const Case& c : cases()) {
        const dtm::test::ScratchDir dir;
        dtm::test::write_file(dir / "points.csv", csv(c.points));
        const std::vector<Line> serial = serial_lines(c);
        ASSERT_GT(serial.size(), 2U) << c.name;
        for (const int ranks : {1, 2, 7, 16, 64}) {
            const std::string what = c.name + " on " + std::to_string(ranks) + " ranks";
            const auto result = run(c, dir.path(), ranks);
            EXPECT_EQ(result.ranks, ranks) << what;
            EXPECT_EQ(result.lines, serial.size()) << what;
            EXPECT_GE(result.pieces.size(), 1U) << what;  // ranges balanced by crossings
            EXPECT_LE(result.pieces.size(),
                      std::min<std::size_t>(result.levels, static_cast<std::size_t>(ranks)))
                << what;
            const std::vector<Line> lines =
                read_layer(dir / ("contours-" + std::to_string(ranks) + ".vrt"));
            ASSERT_EQ(lines.size(), serial.size()) << what;
            for (std::size_t i = 0; i < lines.size(); ++i) {
                ASSERT_TRUE(lines[i] == serial[i]) << what << ": line " << i;
            }
        }
    }
}

TEST(DistributedContours, LevelRangesBalanceTheCrossedTriangles) {
    const Case c = cases().front();  // 31 levels, 160 to 530 crossed triangles each
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "points.csv", csv(c.points));
    const auto result = run(c, dir.path(), 4);
    ASSERT_EQ(result.pieces.size(), 4U);
    std::vector<std::size_t> levels;  // distinct levels per piece
    for (const fs::path& piece : result.pieces) {
        std::vector<double> values;
        for (const Line& line : read_layer(piece)) values.push_back(line.level);
        values.erase(std::unique(values.begin(), values.end()), values.end());
        levels.push_back(values.size());
    }
    // The middle levels cross the most triangles, so the middle ranks take fewer levels than the
    // outer ones (an even split of the levels would give each rank 7 or 8).
    EXPECT_GT(levels[0], levels[1]);
    EXPECT_GT(levels[3], levels[2]);
}

TEST(DistributedContours, RandomDelaysChangeNoLine) {
    const Case c = cases()[1];
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "points.csv", csv(c.points));
    const std::vector<Line> serial = serial_lines(c);
    for (const int ranks : {3, 16}) {
        run(c, dir.path(), ranks, 300);
        EXPECT_TRUE(read_layer(dir / ("contours-" + std::to_string(ranks) + ".vrt")) == serial)
            << ranks << " ranks";
    }
}

TEST(DistributedContours, CubicSurfaceIsRefusedOnEveryRank) {
    const Case c = cases()[1];
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "points.csv", csv(c.points));
    Case cubic = c;
    cubic.contour.surface = dtm::Interpolation::cubic;
    EXPECT_THROW(run(cubic, dir.path(), 3), dtm::UsageError);
    EXPECT_FALSE(fs::exists(dir / "contours-3.vrt"));
}

}  // namespace
