// SPDX-License-Identifier: MIT
// `dtm methods run` for the methods whose output is not one TIN: enumerate writes a folder of
// t001.ply ... and prints the count and optima; pseudo writes polygon faces (.ply with polygon
// faces, .gpkg with one polygon per face) and takes --swap/--flip/--criterion as aliases.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <filesystem>
#include <sstream>

#include "dtm/io/formats/ply.hpp"
#include "dtm/io/tin_file.hpp"
#include "support/terrain_fixtures.hpp"
#include "support/test_support.hpp"

namespace dtm {
namespace {

using test::run_dtm;
using test::ScratchDir;

TEST(MethodsOutputs, EnumerateWritesEveryTriangulation) {
    ScratchDir dir;
    test::write_file(dir / "hosch.csv", "x,y,z\n5,9,0\n2,5,0\n4,2,0\n7,1.5,0\n8.5,4,0\n5,8,0\n");
    // A stale file of an earlier, larger run is removed.
    std::filesystem::create_directories(dir / "out");
    test::write_file(dir / "out" / "t011.ply", "old");
    const auto r = run_dtm({"methods", "run", "enumerate", (dir / "hosch.csv").string(), "-o",
                            (dir / "out").string(), "--stats"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("\"triangulations\": 10"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"maxmin-angle\": {"), std::string::npos);
    for (int i = 1; i <= 10; ++i) {
        const auto path = dir / "out" / (i < 10 ? "t00" + std::to_string(i) + ".ply" : "t010.ply");
        ASSERT_TRUE(std::filesystem::exists(path)) << path;
        EXPECT_EQ(io::read_tin_ply(path).tin.triangles.size(), 5u);
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "t011.ply"));
    // More than 12 points: refused with exit code 2.
    std::ostringstream many;
    for (const Point3& p : test::random_points(13, 3))
        many << p.x << ' ' << p.y << ' ' << p.z << '\n';
    test::write_file(dir / "many.xyz", many.str());
    EXPECT_EQ(run_dtm({"methods", "run", "enumerate", (dir / "many.xyz").string(), "-o",
                       (dir / "many").string()})
                  .exit_code,
              2);
}

TEST(MethodsOutputs, PseudoWritesPolygonFaces) {
    ScratchDir dir;
    std::ostringstream text;
    text.precision(17);
    for (const Point3& p : test::random_points(300, 5, test::sjtsk_e, test::sjtsk_n)) {
        text << p.x << ' ' << p.y << ' ' << p.z << '\n';
    }
    test::write_file(dir / "points.xyz", text.str());
    const auto ply = run_dtm({"methods", "run", "pseudo", (dir / "points.xyz").string(), "-o",
                              (dir / "faces.ply").string(), "--swap", "post", "--criterion",
                              "maxmin-angle", "--stats", "--crs", "EPSG:5514"});
    ASSERT_EQ(ply.exit_code, 0) << ply.err;
    EXPECT_NE(ply.out.find("\"swap\": \"post\""), std::string::npos) << ply.out;
    EXPECT_NE(ply.out.find("\"criterion\": \"maxmin-angle\""), std::string::npos);
    const std::string bytes = test::read_file(dir / "faces.ply");
    EXPECT_NE(bytes.find("element face 298\nproperty list uchar int vertex_indices\n"),
              std::string::npos);
    EXPECT_NE(bytes.find("comment crs "), std::string::npos);

    const auto gpkg = run_dtm({"methods", "run", "pseudo", (dir / "points.xyz").string(), "-o",
                               (dir / "faces.gpkg").string(), "--crs", "EPSG:5514"});
    ASSERT_EQ(gpkg.exit_code, 0) << gpkg.err;
    GDALAllRegister();
    GDALDataset* ds = static_cast<GDALDataset*>(
        GDALOpenEx((dir / "faces.gpkg").c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr));
    ASSERT_NE(ds, nullptr);
    OGRLayer* layer = ds->GetLayer(0);
    EXPECT_EQ(layer->GetFeatureCount(), 298);
    EXPECT_STREQ(layer->GetSpatialRef()->GetAuthorityCode(nullptr), "5514");
    GDALClose(ds);

    const auto bad = run_dtm({"methods", "run", "pseudo", (dir / "points.xyz").string(), "-o",
                              (dir / "faces.txt").string()});
    EXPECT_EQ(bad.exit_code, 2);
    const auto bad_param = run_dtm({"methods", "run", "pseudo", (dir / "points.xyz").string(), "-o",
                                    (dir / "f.ply").string(), "--swap", "sometimes"});
    EXPECT_EQ(bad_param.exit_code, 2);
}

}  // namespace
}  // namespace dtm
