// SPDX-License-Identifier: MIT
// LandXML: the writer's output is valid against the official 1.2 schema (xmllint), lxml reads
// north/east where they belong, write -> read -> write is byte-identical; the reader keeps the
// faces of real Civil 3D and OpenRoads exports with their counts and orientation, honours i="1"
// holes, other namespaces and ISO-8859-1, and names file and line in its errors.
#include "dtm/io/formats/landxml.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <string>

#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/reader.hpp"
#include "dtm/io/tin_file.hpp"
#include "support/test_support.hpp"
#include "support/tin_fixture.hpp"

namespace {

using dtm::ConstraintKind;
using dtm::Tin;
namespace io = dtm::io;
namespace test = dtm::test;

bool have(const char* command) {
    return std::system((std::string(command) + " >/dev/null 2>&1").c_str()) == 0;
}

/// The grid TIN with a hard breakline (its middle row), an outer boundary ring around it and a
/// soft line: every kind the writer stores.
Tin sample_tin() {
    Tin tin = test::grid_tin(5);
    for (dtm::VertexIndex i = 0; i < 4; ++i) {
        tin.constraints.push_back({i, i + 1, ConstraintKind::boundary});
        tin.constraints.push_back({20 + i, 21 + i, ConstraintKind::boundary});
        tin.constraints.push_back({i * 5, (i + 1) * 5, ConstraintKind::boundary});
        tin.constraints.push_back({i * 5 + 4, (i + 1) * 5 + 4, ConstraintKind::boundary});
    }
    tin.constraints.push_back({6, 12, ConstraintKind::soft_breakline});
    std::sort(tin.constraints.begin(), tin.constraints.end(), [](const auto& a, const auto& b) {
        return std::pair{a.a, a.b} < std::pair{b.a, b.b};
    });
    dtm::link_neighbours(tin);
    return tin;
}

io::TinWriteOptions sjtsk_options() {
    io::TinWriteOptions o;
    o.crs_wkt = io::crs_to_wkt("EPSG:5514");
    ::setenv("SOURCE_DATE_EPOCH", "1764633600", 1);  // 2025-12-02T00:00:00Z
    return o;
}

io::ReadResult read(const std::filesystem::path& path, io::ReadOptions options = {}) {
    return io::read_landxml({path, io::InputRole::points}, options);
}

TEST(LandXml, WrittenFileIsValidAgainstTheSchema) {
    if (!test::shared_data_available("landxml-schema/LandXML-1.2.xsd")) GTEST_SKIP();
    if (!have("command -v xmllint")) GTEST_SKIP() << "xmllint missing (libxml2-utils)";
    test::ScratchDir dir;
    io::write_tin(sample_tin(), dir / "tin.xml", sjtsk_options());
    const std::string command = "xmllint --noout --schema '" +
                                test::shared_data_path("landxml-schema/LandXML-1.2.xsd").string() +
                                "' '" + (dir / "tin.xml").string() + "' 2>'" +
                                (dir / "log").string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << test::read_file(dir / "log");
    const std::string text = test::read_file(dir / "tin.xml");
    EXPECT_NE(text.find("epsgCode=\"5514\""), std::string::npos);
    EXPECT_NE(text.find("<Breakline brkType=\"standard\""), std::string::npos);
    EXPECT_NE(text.find("<Breakline brkType=\"nondestructive\""), std::string::npos);
    EXPECT_NE(text.find("<Boundary bndType=\"outer\" edgeTrim=\"true\""), std::string::npos);
    EXPECT_NE(text.find("date=\"2025-12-02\" time=\"00:00:00\""), std::string::npos);
}

TEST(LandXml, LxmlReadsNorthingBeforeEasting) {
    if (!have("/usr/bin/python3 -c 'import lxml'")) GTEST_SKIP() << "python3-lxml missing";
    test::ScratchDir dir;
    Tin tin = sample_tin();
    tin.vertices[7] = {-745123.25, -1045678.5, 312.125};  // a known point, id 8
    io::write_tin(tin, dir / "tin.xml", sjtsk_options());
    test::write_file(dir / "check.py",
                     "import sys\nfrom lxml import etree\n"
                     "ns = {'l': 'http://www.landxml.org/schema/LandXML-1.2'}\n"
                     "t = etree.parse(sys.argv[1])\n"
                     "p = t.find('.//l:Pnts/l:P[@id=\"8\"]', ns)\n"
                     "n, e, z = map(float, p.text.split())\n"
                     "faces = t.findall('.//l:Faces/l:F', ns)\n"
                     "assert (n, e, z) == (-1045678.5, -745123.25, 312.125), (n, e, z)\n"
                     "assert len(faces) == 32, len(faces)\n"
                     "cs = t.find('.//l:CoordinateSystem', ns)\n"
                     "assert cs.get('epsgCode') == '5514'\n");
    const std::string command = "/usr/bin/python3 '" + (dir / "check.py").string() + "' '" +
                                (dir / "tin.xml").string() + "' 2>'" + (dir / "log").string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << test::read_file(dir / "log");
}

TEST(LandXml, WriteReadWriteIsByteIdentical) {
    test::ScratchDir dir;
    const Tin tin = sample_tin();
    io::write_tin(tin, dir / "a.xml", sjtsk_options());
    io::ReadResult r = read(dir / "a.xml");
    ASSERT_TRUE(r.tin.has_value());
    EXPECT_EQ(r.tin->vertices, tin.vertices);
    ASSERT_EQ(r.tin->triangles.size(), tin.triangles.size());
    for (std::size_t i = 0; i < tin.triangles.size(); ++i) {
        EXPECT_EQ(r.tin->triangles[i].v, tin.triangles[i].v) << i;
    }
    EXPECT_EQ(r.tin->constraints, tin.constraints);
    EXPECT_EQ(io::crs_label(r.crs_wkt), "EPSG:5514");
    EXPECT_EQ(r.summary.triangles, 32U);
    EXPECT_EQ(r.terrain.breaklines.size(), 1U);
    EXPECT_EQ(r.terrain.soft_breaklines.size(), 1U);
    ASSERT_EQ(r.terrain.boundaries.size(), 1U);
    EXPECT_TRUE(r.terrain.boundaries[0].closed);
    EXPECT_EQ(r.terrain.boundaries[0].points.size(), 16U);
    io::TinWriteOptions again = sjtsk_options();
    again.crs_wkt = r.crs_wkt;
    io::write_tin(*r.tin, dir / "b.xml", again);
    EXPECT_EQ(test::read_file(dir / "a.xml"), test::read_file(dir / "b.xml"));
}

TEST(LandXml, RetriangulateGivesPointsAndLines) {
    test::ScratchDir dir;
    io::write_tin(sample_tin(), dir / "a.xml", sjtsk_options());
    io::ReadOptions options;
    options.retriangulate = true;
    const io::ReadResult r = read(dir / "a.xml", options);
    EXPECT_FALSE(r.tin.has_value());
    EXPECT_EQ(r.terrain.points.size(), 25U);
    EXPECT_EQ(r.labels.ids.front(), "1");
    EXPECT_EQ(r.terrain.breaklines.size(), 1U);
    EXPECT_EQ(r.terrain.boundaries.size(), 1U);
}

TEST(LandXml, OtherNamespaceLatin1AndInvisibleFaces) {
    const auto path = test::data_path("landxml/inframodel_latin1.xml");
    EXPECT_EQ(&io::find_reader(path), &io::find_reader(test::data_path("landxml/bad_face.xml")));
    const io::ReadResult r = read(path);
    ASSERT_TRUE(r.tin.has_value());
    EXPECT_EQ(r.summary.format, "LandXML surface 'Maanpinta \xc3\xa4\xc3\xb6'");
    EXPECT_EQ(r.tin->vertices.size(), 5U);
    EXPECT_EQ(r.tin->triangles.size(), 3U);  // the i="1" face is a hole
    EXPECT_EQ(r.tin->vertices[0].x, 400000.0);
    EXPECT_EQ(r.tin->vertices[0].y, 6700000.0);
    EXPECT_EQ(io::crs_label(r.crs_wkt), "EPSG:3067");
    {
        const auto report = dtm::verify_topology(*r.tin);
        EXPECT_TRUE(report.ok()) << report.text();
    }
}

TEST(LandXml, ErrorsNameFileAndLine) {
    const auto path = test::data_path("landxml/bad_face.xml");
    try {
        (void)read(path);
        FAIL() << "expected an InputError";
    } catch (const dtm::InputError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.line(), 11U);
        EXPECT_NE(std::string(e.what()).find("point id '99'"), std::string::npos) << e.what();
    }
    io::ReadOptions options;
    options.surface = "nope";
    EXPECT_THROW((void)read(test::data_path("landxml/inframodel_latin1.xml"), options),
                 dtm::InputError);
}

struct Export {
    const char* file;
    const char* surface;
    std::size_t points;
    std::size_t triangles;
    std::size_t breaklines;
    std::size_t boundaries;
    const char* crs;
};

TEST(LandXml, RealExportsReadWithTheirCounts) {
    const Export exports[] = {
        {"Example_Clean.xml", "", 29, 45, 0, 0, ""},  // invalid only for timeStamp=""
        {"Example_Clean.xml", "B", 92, 138, 0, 0, ""},
        {"Example_Clean.xml", "C", 143, 243 - 64, 0, 0, ""},
        {"3D_modell_underlag_skyfall_20230915.xml", "", 3330, 6609 - 161, 0, 0, "EPSG:3007"},
        {"Combined_Terrain_tin_file.xml", "", 11347, 21838, 2415, 1, ""},  // clockwise faces
        {"DGM_LandXML.xml", "", 169, 322, 2, 0, ""},
    };
    for (const Export& x : exports) {
        const std::string rel = std::string("landxml-surfaces/") + x.file;
        if (!test::shared_data_available(rel)) GTEST_SKIP();
        io::ReadOptions options;
        options.surface = x.surface;
        const io::ReadResult r = read(test::shared_data_path(rel), options);
        SCOPED_TRACE(rel + " " + x.surface);
        ASSERT_TRUE(r.tin.has_value());
        EXPECT_EQ(r.tin->vertices.size(), x.points);
        EXPECT_EQ(r.tin->triangles.size(), x.triangles);
        EXPECT_EQ(r.terrain.breaklines.size() + r.terrain.soft_breaklines.size(), x.breaklines);
        EXPECT_EQ(r.terrain.boundaries.size(), x.boundaries);
        EXPECT_EQ(io::crs_label(r.crs_wkt), x.crs);
        {
            const auto report = dtm::verify_topology(*r.tin);
            EXPECT_TRUE(report.ok()) << report.text();
        }  // counter-clockwise, consistent links
    }
}

}  // namespace
