// SPDX-License-Identifier: MIT
// `dtm contour`: exit codes, GeoPackage / shapefile / DXF outputs that OGR opens with the CRS,
// LineStringZ at the level, elevation and index attributes, exact positions on a plane.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <map>
#include <memory>
#include <sstream>

#include "support/test_support.hpp"

namespace {

struct Closer {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

/// Points of the plane z = 100 + (x - x0) on a jittered 11 x 11 grid: the contour of level L is
/// the straight line x = x0 + L - 100, whatever the triangulation.
std::filesystem::path write_ramp(const dtm::test::ScratchDir& dir) {
    std::ostringstream csv;
    csv.precision(12);
    csv << "x,y,z\n";
    for (int i = 0; i <= 10; ++i) {
        for (int j = 0; j <= 10; ++j) {
            const double dx = (i > 0 && i < 10) ? 0.013 * ((i * 7 + j * 3) % 5) : 0.0;
            csv << -750'000.0 + i + dx << ',' << -1'050'000.0 + j << ',' << 100.0 + i + dx << '\n';
        }
    }
    const auto path = dir / "ramp.csv";
    dtm::test::write_file(path, csv.str());
    return path;
}

Dataset open_vector(const std::filesystem::path& path) {
    GDALAllRegister();
    return Dataset(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
}

TEST(CliContour, GeoPackageHasLinesOnTheirLevelWithIndexAttributeAndCrs) {
    const dtm::test::ScratchDir dir;
    const auto r =
        dtm::test::run_dtm({"contour", write_ramp(dir).string(), "-o", (dir / "c.gpkg").string(),
                            "--interval", "0.5", "--index-every", "4", "--crs", "EPSG:5514", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Dataset ds = open_vector(dir / "c.gpkg");
    ASSERT_TRUE(ds);
    OGRLayer* layer = ds->GetLayer(0);
    ASSERT_NE(layer->GetSpatialRef(), nullptr);
    OGRSpatialReference expected;
    expected.importFromEPSG(5514);
    EXPECT_TRUE(layer->GetSpatialRef()->IsSame(&expected));
    std::map<double, int> index_of_level;
    for (auto& feature : *layer) {
        const double level = feature->GetFieldAsDouble("elevation");
        index_of_level[level] = feature->GetFieldAsInteger("index");
        const OGRLineString* line = feature->GetGeometryRef()->toLineString();
        ASSERT_GE(line->getNumPoints(), 2);
        for (int i = 0; i < line->getNumPoints(); ++i) {
            EXPECT_EQ(line->getZ(i), level);
            EXPECT_NEAR(line->getX(i), -750'000.0 + level - 100.0, 1e-6);
        }
    }
    // 100.5 ... 110: zmin = 100 is not cut (zmin < level); 110 = zmax is the eastern border line
    ASSERT_EQ(index_of_level.size(), 20U);
    EXPECT_EQ(index_of_level.at(101.0), 0);
    EXPECT_EQ(index_of_level.at(102.0), 1);  // 102 = 0.5 * 204, 204 % 4 == 0
    EXPECT_EQ(index_of_level.at(102.5), 0);
}

TEST(CliContour, ShapefileWithPrjAndDxfWithLayersAndFixedLevels) {
    const dtm::test::ScratchDir dir;
    const auto ramp = write_ramp(dir).string();
    auto r = dtm::test::run_dtm({"contour", ramp, "-o", (dir / "c.shp").string(), "--levels",
                                 "103,105.25", "--crs", "EPSG:5514", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "c.prj"));
    Dataset shp = open_vector(dir / "c.shp");
    ASSERT_TRUE(shp);
    EXPECT_EQ(shp->GetLayer(0)->GetFeatureCount(), 2);
    r = dtm::test::run_dtm(
        {"contour", ramp, "-o", (dir / "c.dxf").string(), "--interval", "1", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Dataset dxf = open_vector(dir / "c.dxf");
    ASSERT_TRUE(dxf);
    int index = 0, other = 0;
    for (auto& feature : *dxf->GetLayer(0)) {
        const std::string layer = feature->GetFieldAsString("Layer");
        index += layer == "CONTOUR_INDEX" ? 1 : 0;
        other += layer == "CONTOUR" ? 1 : 0;
    }
    EXPECT_EQ(index, 2);  // 105 and 110 of 101 ... 110 (every 5th by default)
    EXPECT_EQ(other, 8);
}

TEST(CliContour, BadUsageExitsWithTwoAndWritesNothing) {
    const dtm::test::ScratchDir dir;
    const auto ramp = write_ramp(dir).string();
    const auto out = (dir / "c.gpkg").string();
    EXPECT_EQ(dtm::test::run_dtm({"contour", ramp, "-o", out, "-q"}).exit_code, 2);  // no levels
    EXPECT_EQ(dtm::test::run_dtm({"contour", ramp, "-o", out, "--interval", "0", "-q"}).exit_code,
              2);
    EXPECT_EQ(
        dtm::test::run_dtm({"contour", ramp, "-o", out, "--interval", "1e-9", "-q"}).exit_code, 2);
    EXPECT_EQ(dtm::test::run_dtm(
                  {"contour", ramp, "-o", (dir / "c.xyz").string(), "--interval", "1", "-q"})
                  .exit_code,
              2);
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace

#include <set>

#include "dtm/io/formats/ply.hpp"
#include "dtm/io/tin_file.hpp"

namespace {

/// Level-set length of the TIN at @p level, triangle by triangle; a piece along an edge (both
/// ends on the level) counts once, and only when a triangle beside it goes below the level.
double independent_length(const dtm::Tin& tin, double level) {
    double sum = 0.0;
    std::set<std::pair<std::uint32_t, std::uint32_t>> along;
    for (const dtm::Triangle& t : tin.triangles) {
        std::vector<std::pair<double, double>> pts;
        std::vector<std::uint32_t> on;
        bool below = false;
        for (std::size_t e = 0; e < 3; ++e) {
            const dtm::Point3& p = tin.vertices[t.v[e]];
            const dtm::Point3& q = tin.vertices[t.v[(e + 1) % 3]];
            below = below || p.z < level;
            if (p.z == level) {
                pts.emplace_back(p.x, p.y);
                on.push_back(t.v[e]);
            } else if ((p.z < level && q.z > level) || (p.z > level && q.z < level)) {
                const double s = (level - p.z) / (q.z - p.z);
                pts.emplace_back(p.x + s * (q.x - p.x), p.y + s * (q.y - p.y));
            }
        }
        if (pts.size() != 2 ||
            (on.size() == 2 && (!below || !along.insert(std::minmax(on[0], on[1])).second))) {
            continue;
        }
        sum += std::hypot(pts[0].first - pts[1].first, pts[0].second - pts[1].second);
    }
    return sum;
}

/// Whether (x, y) is the linear interpolation of @p level on some TIN edge crossing it.
bool on_tin_edge(const dtm::Tin& tin, double x, double y, double level) {
    for (const dtm::Triangle& t : tin.triangles) {
        for (std::size_t e = 0; e < 3; ++e) {
            dtm::Point3 a = tin.vertices[t.v[e]], b = tin.vertices[t.v[(e + 1) % 3]];
            if (a.z > b.z) std::swap(a, b);
            if (!(a.z < level && level <= b.z)) continue;
            const double s = (level - a.z) / (b.z - a.z);
            if (std::abs(a.x + s * (b.x - a.x) - x) < 1e-6 &&
                std::abs(a.y + s * (b.y - a.y) - y) < 1e-6) {
                return true;
            }
        }
    }
    return false;
}

TEST(CliContour, RealSjtskSurveyContoursLieOnTinEdgesWithTheIndependentLengthPerLevel) {
    const std::string base = "points-cz-sjtsk-jvf-dtm/derived/";
    if (!dtm::test::shared_data_available(base + "zps_points_pointz.shp")) {
        GTEST_SKIP() << "shared data not available";
    }
    const dtm::test::ScratchDir dir;
    const std::string points = dtm::test::shared_data_path(base + "zps_points_pointz.shp").string();
    const std::string lines =
        dtm::test::shared_data_path(base + "zps_breaklines_polylinez.shp").string();
    ASSERT_EQ(dtm::test::run_dtm(
                  {"tin", points, "--breaklines", lines, "-o", (dir / "tin.ply").string(), "-q"})
                  .exit_code,
              0);
    // Contour the very same TIN (PLY input: no second triangulation).
    const auto r = dtm::test::run_dtm({"contour", (dir / "tin.ply").string(), "-o",
                                       (dir / "c.gpkg").string(), "--interval", "0.25", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const dtm::Tin tin = dtm::io::read_tin_ply(dir / "tin.ply").tin;
    Dataset ds = open_vector(dir / "c.gpkg");
    ASSERT_TRUE(ds);
    std::map<double, double> length;
    for (auto& feature : *ds->GetLayer(0)) {
        const double level = feature->GetFieldAsDouble("elevation");
        const OGRLineString* line = feature->GetGeometryRef()->toLineString();
        for (int i = 0; i < line->getNumPoints(); ++i) {
            ASSERT_EQ(line->getZ(i), level);
            ASSERT_TRUE(on_tin_edge(tin, line->getX(i), line->getY(i), level))
                << level << ": " << line->getX(i) << "," << line->getY(i);
            if (i > 0) {
                length[level] += std::hypot(line->getX(i) - line->getX(i - 1),
                                            line->getY(i) - line->getY(i - 1));
            }
        }
    }
    ASSERT_GT(length.size(), 5U);
    for (const auto& [level, got] : length) {
        EXPECT_NEAR(got, independent_length(tin, level), 1e-6 * (1.0 + got)) << level;
    }
}

}  // namespace
