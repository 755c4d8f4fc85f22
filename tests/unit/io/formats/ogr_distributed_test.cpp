// SPDX-License-Identifier: MIT
// io::read_ogr_points_distributed (R-D2): on 1 to 16 in-process ranks, the points in order over
// the ranks are read_ogr's, for a GeoPackage of two layers, a `where` filter, features without
// geometry and a shapefile; the CRS is load_inputs'; a 2-D point in the last rank's share is
// read_ogr's message on every rank; lines in the points input are refused on every rank.
#include "io/formats/ogr_distributed.hpp"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/io/formats/ogr.hpp"
#include "dtm/io/inputs.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

/// A vector file of @p layers layers with @p per_layer features each: PointZ survey points with
/// an "elev" field, every 97th feature without geometry, one 2-D point at @p flat_at (if any).
void write_points(const fs::path& path,
                  const char* driver_name,
                  int layers,
                  int per_layer,
                  int flat_at = -1,
                  bool with_line = false) {
    GDALAllRegister();
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name);
    ASSERT_NE(driver, nullptr);
    GDALDataset* ds = driver->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
    ASSERT_NE(ds, nullptr);
    OGRSpatialReference srs;
    srs.importFromEPSG(5514);
    std::mt19937_64 rng(20261204);
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    int n = 0;
    for (int l = 0; l < layers; ++l) {
        OGRLayer* layer = ds->CreateLayer(("survey" + std::to_string(l)).c_str(), &srs,
                                          with_line ? wkbUnknown : wkbPoint25D, nullptr);
        OGRFieldDefn elev("elev", OFTReal);
        layer->CreateField(&elev);
        for (int i = 0; i < per_layer; ++i, ++n) {
            OGRFeature* f = OGRFeature::CreateFeature(layer->GetLayerDefn());
            const double x = -750000.0 - std::round(u(rng) * 1000.0) / 1000.0;
            const double y = -1050000.0 - std::round(u(rng) * 1000.0) / 1000.0;
            const double z = 250.0 + u(rng) / 10.0;
            f->SetField("elev", z);
            if (with_line && n == per_layer / 2) {
                OGRLineString line;
                line.addPoint(x, y, z);
                line.addPoint(x + 5.0, y + 5.0, z);
                f->SetGeometry(&line);
            } else if (n % 97 != 5) {
                OGRPoint p(x, y, z);
                if (n == flat_at) p.flattenTo2D();
                f->SetGeometry(&p);
            }
            EXPECT_EQ(layer->CreateFeature(f), OGRERR_NONE);
            OGRFeature::DestroyFeature(f);
        }
    }
    GDALClose(ds);
}

struct Read {
    std::vector<dtm::Point3> points;
    std::string crs;
    std::string error;
    std::vector<std::uint64_t> firsts;
};

Read read_on(int ranks, const dtm::io::InputFile& file, const dtm::io::ReadOptions& options) {
    Read out;
    std::vector<std::vector<dtm::Point3>> parts(static_cast<std::size_t>(ranks));
    std::vector<std::string> errors(static_cast<std::size_t>(ranks));
    out.firsts.resize(static_cast<std::size_t>(ranks));
    std::mutex lock;
    dtm::dist::run_in_process(ranks, [&](dtm::dist::Comm& comm) {
        const auto r = static_cast<std::size_t>(comm.rank());
        try {
            std::string crs;
            const dtm::io::DistributedPoints d =
                dtm::io::read_ogr_points_distributed(comm, file, options, crs);
            for (const auto& p : d.points) parts[r].push_back(p.p);
            out.firsts[r] = d.first_input;
            const std::lock_guard<std::mutex> guard(lock);
            out.crs = crs;
        } catch (const dtm::Error& e) {
            errors[r] = e.what();
        }
    });
    for (const auto& part : parts) out.points.insert(out.points.end(), part.begin(), part.end());
    for (const std::string& e : errors) {
        if (e != errors[0]) out.error = "ranks disagree: " + errors[0] + " | " + e;
    }
    if (out.error.empty()) out.error = errors[0];
    return out;
}

TEST(DistributedOgrPoints, EveryRankCountReadsTheSerialPointsInOrder) {
    const dtm::test::ScratchDir dir;
    write_points(dir / "survey.gpkg", "GPKG", 2, 1500);
    write_points(dir / "survey.shp", "ESRI Shapefile", 1, 2500);
    dtm::io::ReadOptions filtered;
    filtered.where = "elev > 260";
    dtm::io::ReadOptions one_layer;
    one_layer.layer = "survey1";
    const std::vector<std::pair<fs::path, dtm::io::ReadOptions>> cases{
        {dir / "survey.gpkg", {}},
        {dir / "survey.gpkg", filtered},
        {dir / "survey.gpkg", one_layer},
        {dir / "survey.shp", {}}};
    for (const auto& [path, options] : cases) {
        const dtm::io::InputFile file{path, dtm::io::InputRole::points};
        const dtm::io::ReadResult serial = dtm::io::read_ogr(file, options);
        dtm::io::LoadOptions load;
        load.files = {file};
        load.read = options;
        const std::string serial_crs = dtm::io::load_inputs(load).crs_wkt;
        ASSERT_GT(serial.terrain.points.size(), 500U) << path;
        for (const int ranks : {1, 2, 3, 7, 16}) {
            const Read d = read_on(ranks, file, options);
            const std::string what = path.filename().string() + " where '" + options.where +
                                     "' layer '" + options.layer + "' on " + std::to_string(ranks);
            EXPECT_EQ(d.error, "") << what;
            EXPECT_EQ(d.points, serial.terrain.points) << what;
            EXPECT_EQ(d.crs, serial_crs) << what;
        }
    }
}

TEST(DistributedOgrPoints, TheFirstBadFeatureIsTheSerialMessageOnEveryRank) {
    const dtm::test::ScratchDir dir;
    write_points(dir / "bad.gpkg", "GPKG", 1, 3000, 2900);  // in the last rank's share
    const dtm::io::InputFile file{dir / "bad.gpkg", dtm::io::InputRole::points};
    std::string serial;
    try {
        (void)dtm::io::read_ogr(file, {});
    } catch (const dtm::InputError& e) {
        serial = e.what();
    }
    ASSERT_NE(serial.find("2-D point"), std::string::npos) << serial;
    for (const int ranks : {1, 3, 4}) EXPECT_EQ(read_on(ranks, file, {}).error, serial) << ranks;
}

TEST(DistributedOgrPoints, LinesInThePointsInputAreRefusedOnEveryRank) {
    const dtm::test::ScratchDir dir;
    write_points(dir / "mixed.gpkg", "GPKG", 1, 400, -1, true);
    const Read d = read_on(3, {dir / "mixed.gpkg", dtm::io::InputRole::points}, {});
    EXPECT_NE(d.error.find("does not take line or polygon features"), std::string::npos) << d.error;
}

}  // namespace
