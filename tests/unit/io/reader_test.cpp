// SPDX-License-Identifier: MIT
// The reader table: by extension (any case), content sniffing before plain rows (a text file
// with a WKT column goes to OGR), TINs through the table, unknown extensions named.
#include "dtm/io/reader.hpp"

#include <gtest/gtest.h>

#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/inputs.hpp"
#include "support/test_support.hpp"

namespace {

using dtm::io::find_reader;
using dtm::io::InputRole;

TEST(ReaderTable, ExtensionsChooseTheReaderInAnyCase) {
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "a.XYZ", "1 2 3\n");
    dtm::test::write_file(dir / "plan.PLT", "IN;");
    EXPECT_EQ(find_reader(dir / "a.XYZ").name, "csv");
    EXPECT_EQ(find_reader(dir / "plan.PLT").name, "hpgl");
    EXPECT_EQ(find_reader(dtm::io::FileHead{"x.gpkg", "gpkg", {}}).name, "ogr");
    EXPECT_EQ(find_reader(dtm::io::FileHead{"x.ply", "ply", {}}).name, "ply");
}

TEST(ReaderTable, TextWithAGeometryColumnGoesToOgrByItsContent) {
    EXPECT_EQ(
        find_reader(dtm::io::FileHead{"a.csv", "csv", "id,WKT\n1,\"POINT Z (1 2 3)\"\n"}).name,
        "csv-wkt");
    EXPECT_EQ(find_reader(dtm::io::FileHead{"a.csv", "csv", "# note\nid;x;y;z\n1;2;3;4\n"}).name,
              "csv");
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "p.csv",
                          "id,wkt\n1,\"POINT Z (10 20 30)\"\n2,\"POINT Z (11 20 31)\"\n"
                          "3,\"POINT Z (10 21 32)\"\n");
    dtm::io::LoadOptions options;
    options.files.push_back({dir / "p.csv", InputRole::points});
    const dtm::io::LoadedInputs loaded = dtm::io::load_inputs(options);
    EXPECT_EQ(loaded.summaries.at(0).format, "text (OGR, geometry column)");
    ASSERT_EQ(loaded.terrain.points.size(), 3u);
    EXPECT_EQ(loaded.terrain.points[2].z, 32.0);
}

TEST(ReaderTable, ATiledTinManifestAndGeoJsonShareJsonByTheirContent) {
    const std::string manifest = "{\n  \"format\": \"dtm-tin-tiles\",\n  \"version\": 1\n}\n";
    EXPECT_EQ(find_reader(dtm::io::FileHead{"tin.json", "json", manifest}).name, "tin-tiles");
    EXPECT_EQ(find_reader(dtm::io::FileHead{"tin.txt", "", manifest}).name, "tin-tiles");
    EXPECT_EQ(find_reader(dtm::io::FileHead{"a.json", "json",
                                            "{\"type\": \"FeatureCollection\", \"features\": []}"})
                  .name,
              "ogr");
}

TEST(ReaderTable, APlyTinComesThroughTheTableAsATin) {
    const dtm::test::ScratchDir dir;
    dtm::Tin tin;
    tin.vertices = {{0, 0, 1}, {10, 0, 2}, {0, 10, 3}};
    tin.triangles.resize(1);
    tin.triangles[0].v = {0, 1, 2};
    dtm::io::write_tin_ply(tin, dir / "t.ply", {.crs_wkt = "", .ascii = false});
    const dtm::io::ReadResult r =
        find_reader(dir / "t.ply").read({dir / "t.ply", InputRole::points}, {}, {});
    ASSERT_TRUE(r.tin.has_value());
    EXPECT_EQ(r.tin->triangles.size(), 1u);
    EXPECT_EQ(r.terrain.points.size(), 3u);
    EXPECT_THROW(
        (void)find_reader(dir / "t.ply").read({dir / "t.ply", InputRole::breaklines}, {}, {}),
        dtm::InputError);
}

TEST(ReaderTable, EveryRowHasAReaderAndExtensionsOrASniff) {
    for (const dtm::io::ReaderInfo& r : dtm::io::readers()) {
        EXPECT_NE(r.read, nullptr) << r.name;
        EXPECT_TRUE(!r.extensions.empty() || r.sniff != nullptr) << r.name;
        EXPECT_FALSE(r.description.empty()) << r.name;
    }
}

TEST(ReaderTable, UnknownExtensionIsAnInputErrorListingTheKnownOnesOnce) {
    try {
        (void)find_reader(dtm::io::FileHead{"a.foo", "foo", {}});
        FAIL() << "no exception";
    } catch (const dtm::InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("(ply, json, asc, csv, txt, xyz, pts, xml, hpgl,"), std::string::npos)
            << what;
        EXPECT_EQ(what.find("csv"), what.rfind("csv")) << what;
        EXPECT_NE(what.find("found '.foo'"), std::string::npos) << what;
    }
}

}  // namespace
