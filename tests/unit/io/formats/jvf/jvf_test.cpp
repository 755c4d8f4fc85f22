// SPDX-License-Identifier: MIT
// JVF DTM: the CTU sample gives its 893 detail points (with ids, at the coordinates of the
// derived CSV) and 55 terrain edges as hard 3-D breaklines, in EPSG:5514; a change file warns.
#include "dtm/io/formats/jvf.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "dtm/io/formats/crs.hpp"
#include "dtm/io/reader.hpp"
#include "support/test_support.hpp"

namespace {

namespace io = dtm::io;
namespace test = dtm::test;

constexpr const char* sample = "points-cz-sjtsk-jvf-dtm/ukazka_ZPS.xml";

TEST(Jvf, SampleGivesItsPointsAndTerrainEdges) {
    if (!test::shared_data_available(sample)) GTEST_SKIP();
    const auto path = test::shared_data_path(sample);
    EXPECT_EQ(io::find_reader(path).name, "jvf");
    const io::ReadResult r = io::read_jvf({path, io::InputRole::points}, {});
    EXPECT_EQ(r.terrain.points.size(), 893U);
    EXPECT_EQ(r.terrain.breaklines.size(), 55U);
    EXPECT_EQ(io::crs_label(r.crs_wkt), "EPSG:5514");
    ASSERT_EQ(r.labels.ids.size(), 893U);
    EXPECT_EQ(r.labels.ids[0], "72000330010094405");
    EXPECT_EQ(r.terrain.points[0].x, -520813.83);
    EXPECT_EQ(r.terrain.points[0].y, -1164286.00);
    EXPECT_EQ(r.terrain.points[0].z, 267.94);
    std::size_t vertices = 0;
    for (const dtm::Polyline& l : r.terrain.breaklines) {
        vertices += l.points.size() + (l.closed ? 1 : 0);
        for (const dtm::Point3& p : l.points) EXPECT_FALSE(std::isnan(p.z));
    }
    EXPECT_GE(vertices, 195U);
    // Every point is a podrobný bod of the derived CSV (id,gml_id,type_code,type,x,y,z), same xyz.
    const auto csv = test::shared_data_path("points-cz-sjtsk-jvf-dtm/derived/zps_points_xyz.csv");
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    std::map<std::string, std::array<double, 3>> derived;
    while (std::getline(in, line)) {
        std::stringstream row(line);
        std::string f[7];
        for (auto& field : f) std::getline(row, field, ',');
        derived[f[0]] = {std::stod(f[4]), std::stod(f[5]), std::stod(f[6])};
    }
    std::size_t matched = 0;
    for (std::size_t i = 0; i < r.terrain.points.size(); ++i) {
        const auto it = derived.find(r.labels.ids[i]);
        if (it == derived.end()) continue;
        ++matched;
        EXPECT_EQ(it->second[0], r.terrain.points[i].x);
        EXPECT_EQ(it->second[1], r.terrain.points[i].y);
        EXPECT_EQ(it->second[2], r.terrain.points[i].z);
    }
    EXPECT_EQ(matched, 893U);
}

TEST(Jvf, ChangeFileIsWarnedAbout) {
    test::ScratchDir dir;
    test::write_file(
        dir / "zmeny.jvf.xml",
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
        "<JVFDTM xmlns=\"objtyp\" xmlns:gml=\"http://www.opengis.net/gml/3.2\"><DataJVFDTM>"
        "<TypZapisu xmlns=\"cmn\">změnové věty</TypZapisu><Data><PodrobnyBodZPS><ZaznamyObjektu>"
        "<ZaznamObjektu><AtributyObjektu><SpolecneAtributyVsechObjektu xmlns=\"atr\"><ID>7</ID>"
        "</SpolecneAtributyVsechObjektu></AtributyObjektu><GeometrieObjektu><pointProperty "
        "xmlns=\"http://www.opengis.net/gml/3.2\"><Point srsDimension=\"3\" srsName=\"EPSG:5514\">"
        "<pos>-1 -2 3</pos></Point></pointProperty></GeometrieObjektu></ZaznamObjektu>"
        "</ZaznamyObjektu></PodrobnyBodZPS></Data></DataJVFDTM></JVFDTM>\n");
    const io::ReadResult r = io::read_jvf({dir / "zmeny.jvf.xml", io::InputRole::points}, {});
    ASSERT_EQ(r.terrain.points.size(), 1U);
    EXPECT_EQ(r.labels.ids[0], "7");
    ASSERT_FALSE(r.summary.warnings.empty());
    EXPECT_NE(r.summary.warnings[0].find("change file"), std::string::npos);
}

}  // namespace
