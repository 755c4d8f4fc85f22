// SPDX-License-Identifier: MIT
// `dtm voronoi`: Thiessen polygons read back with GDAL/OGR: one valid MultiPolygon per point
// with the reader's id, the index and z, in the input CRS; the cells tile the boundary (their
// areas add up to it, by GEOS too); a bad extension leaves no file.
#include <gtest/gtest.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <set>
#include <string>

#include "support/test_support.hpp"

using dtm::test::run_dtm;
using dtm::test::RunResult;
using dtm::test::ScratchDir;

namespace {

struct Closer {
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

Dataset open(const std::filesystem::path& path) {
    GDALAllRegister();
    return Dataset(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
}

/// 300 survey points with ids in a 100 m square at S-JTSK, and an L-shaped boundary.
void write_inputs(const ScratchDir& dir) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    std::string csv = "id,x,y,z\n";
    for (int i = 0; i < 300; ++i) {
        csv += "P" + std::to_string(1000 + i) + "," + std::to_string(-750000.0 + u(rng)) + "," +
               std::to_string(-1050000.0 + u(rng)) + "," + std::to_string(300.0 + i * 0.01) + "\n";
    }
    dtm::test::write_file(dir / "points.csv", csv);
    dtm::test::write_file(dir / "boundary.geojson",
                          R"({"type": "FeatureCollection",
        "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::5514"}}, "features": [{"type": "Feature", "properties": {},
        "geometry": {"type": "Polygon", "coordinates": [[[-749990, -1049990], [-749910, -1049990],
        [-749910, -1049950], [-749950, -1049950], [-749950, -1049910], [-749990, -1049910],
        [-749990, -1049990]]]}}]})");
}

}  // namespace

TEST(CliVoronoi, CellsReadBackWithIdsZAndCrs) {
    const ScratchDir dir;
    write_inputs(dir);
    const RunResult r = run_dtm(
        {"voronoi", "points.csv", "--crs", "EPSG:5514", "-o", "cells.gpkg", "-q"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const Dataset ds = open(dir / "cells.gpkg");
    ASSERT_TRUE(ds);
    OGRLayer* layer = ds->GetLayer(0);
    EXPECT_EQ(layer->GetFeatureCount(), 300);
    const OGRSpatialReference* srs = layer->GetSpatialRef();
    ASSERT_NE(srs, nullptr);
    EXPECT_STREQ(srs->GetAuthorityCode(nullptr), "5514");
    double area = 0.0;
    std::set<std::string> ids;
    for (auto& f : *layer) {
        const OGRGeometry* g = f->GetGeometryRef();
        ASSERT_NE(g, nullptr);
        EXPECT_EQ(wkbFlatten(g->getGeometryType()), wkbMultiPolygon);
        EXPECT_TRUE(g->IsValid());
        area += g->toMultiPolygon()->get_Area();
        ids.insert(f->GetFieldAsString("id"));
        const int index = f->GetFieldAsInteger("index");
        EXPECT_EQ(std::string(f->GetFieldAsString("id")), "P" + std::to_string(1000 + index));
        EXPECT_NEAR(f->GetFieldAsDouble("z"), 300.0 + index * 0.01, 1e-9);
        EXPECT_NEAR(f->GetFieldAsDouble("area"), g->toMultiPolygon()->get_Area(), 1e-6);
    }
    EXPECT_EQ(ids.size(), 300u);
    EXPECT_GT(area, 0.9 * 100 * 100);  // the hull of the points, nearly the square
}

TEST(CliVoronoi, BoundaryShapefileTilesTheBoundary) {
    const ScratchDir dir;
    write_inputs(dir);
    const RunResult r = run_dtm({"voronoi", "points.csv", "--crs", "EPSG:5514", "--boundary",
                                 "boundary.geojson", "-o", "cells.shp", "-q"},
                                dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const Dataset ds = open(dir / "cells.shp");
    ASSERT_TRUE(ds);
    OGRLayer* layer = ds->GetLayer(0);
    double area = 0.0;
    std::unique_ptr<OGRGeometry> all;
    for (auto& f : *layer) {
        const OGRGeometry* g = f->GetGeometryRef();
        EXPECT_TRUE(g->IsValid());
        area += OGR_G_Area(OGRGeometry::ToHandle(const_cast<OGRGeometry*>(g)));  // (Multi)Polygon
        all.reset(all ? all->Union(g) : g->clone());
    }
    EXPECT_NEAR(area, 80.0 * 40.0 + 40.0 * 40.0, 1e-6);                     // the L
    EXPECT_NEAR(OGR_G_Area(OGRGeometry::ToHandle(all.get())), area, 1e-6);  // no overlaps (GEOS)
}

TEST(CliVoronoi, BadExtensionAndBreaklinesAreUsageErrors) {
    const ScratchDir dir;
    write_inputs(dir);
    EXPECT_EQ(run_dtm({"voronoi", "points.csv", "-o", "cells.dxf", "-q"}, dir.path()).exit_code, 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "cells.dxf"));
    EXPECT_EQ(
        run_dtm({"voronoi", "points.csv", "--breaklines", "boundary.geojson", "-o", "c.gpkg", "-q"},
                dir.path())
            .exit_code,
        2);
    EXPECT_FALSE(std::filesystem::exists(dir / "c.gpkg"));
}
