// SPDX-License-Identifier: MIT
// JVF DTM: the CTU sample gives its 893 detail points (with ids, at the coordinates of the
// derived CSV) and 55 terrain edges as hard 3-D breaklines, in EPSG:5514, and the same TIN as the
// derived PointZ/PolyLineZ shapefiles (read by OGR); a change file warns.
#include "dtm/io/formats/jvf.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "dtm/algo/triangulate.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/formats/ogr.hpp"
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

/// The TIN's triangles as sorted corner positions, sorted: equal for equal TINs whatever the
/// vertex numbering.
std::vector<std::array<std::array<double, 3>, 3>> triangle_set(const dtm::Tin& tin) {
    std::vector<std::array<std::array<double, 3>, 3>> out;
    for (const dtm::Triangle& t : tin.triangles) {
        std::array<std::array<double, 3>, 3> corners{};
        for (std::size_t k = 0; k < 3; ++k) {
            const dtm::Point3& p = tin.vertices[t.v[k]];
            corners[k] = {p.x, p.y, p.z};
        }
        std::sort(corners.begin(), corners.end());
        out.push_back(corners);
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(Jvf, SampleGivesTheSameTinAsItsDerivedShapefiles) {
    constexpr const char* points_shp = "points-cz-sjtsk-jvf-dtm/derived/zps_points_pointz.shp";
    constexpr const char* lines_shp =
        "points-cz-sjtsk-jvf-dtm/derived/zps_breaklines_polylinez.shp";
    if (!test::shared_data_available(sample) || !test::shared_data_available(points_shp)) {
        GTEST_SKIP();
    }
    const io::ReadResult jvf =
        io::read_jvf({test::shared_data_path(sample), io::InputRole::points}, {});
    io::ReadOptions detail_points;  // the shapefile also holds 24 small-structure points
    detail_points.where = "type_code = '0100000218'";
    const io::ReadResult points =
        io::read_ogr({test::shared_data_path(points_shp), io::InputRole::points}, detail_points);
    const io::ReadResult lines =
        io::read_ogr({test::shared_data_path(lines_shp), io::InputRole::breaklines}, {});
    ASSERT_EQ(points.terrain.points.size(), 893U);
    ASSERT_EQ(lines.terrain.breaklines.size(), 55U);
    dtm::TerrainInput derived;
    derived.points = points.terrain.points;
    derived.breaklines = lines.terrain.breaklines;
    const dtm::TriangulateResult a = dtm::triangulate(jvf.terrain);
    const dtm::TriangulateResult b = dtm::triangulate(derived);
    EXPECT_GT(a.tin.triangles.size(), 1000U);
    EXPECT_EQ(a.tin.vertices.size(), b.tin.vertices.size());
    EXPECT_EQ(a.tin.constraints.size(), b.tin.constraints.size());
    EXPECT_TRUE(triangle_set(a.tin) == triangle_set(b.tin));
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
