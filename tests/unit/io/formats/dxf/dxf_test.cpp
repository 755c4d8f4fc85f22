// SPDX-License-Identifier: MIT
// DXF: the TIN written as 3DFACEs is read by GDAL's DXF driver with every corner's height equal
// to the TIN vertex's, and by ezdxf with its layers, faces and 3-D polylines; a DXF of 3DFACEs
// reads back as the same TIN; a DXF without faces still goes to OGR.
#include "dtm/io/formats/dxf.hpp"

#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <cstdlib>
#include <map>
#include <string>

#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/reader.hpp"
#include "dtm/io/tin_file.hpp"
#include "support/test_support.hpp"
#include "support/tin_fixture.hpp"

namespace {

namespace io = dtm::io;
namespace test = dtm::test;
using dtm::ConstraintKind;

dtm::Tin sample_tin() {
    dtm::Tin tin = test::grid_tin(5);  // middle row a breakline
    for (dtm::VertexIndex i = 0; i < 4; ++i) {
        tin.constraints.push_back({i, i + 1, ConstraintKind::boundary});
    }
    dtm::link_neighbours(tin);
    return tin;
}

TEST(Dxf, GdalReadsEveryFaceCornerAtItsTinHeight) {
    test::ScratchDir dir;
    const dtm::Tin tin = sample_tin();
    io::write_tin(tin, dir / "tin.dxf", {});
    GDALAllRegister();
    auto* ds = static_cast<GDALDataset*>(
        GDALOpenEx((dir / "tin.dxf").c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr));
    ASSERT_NE(ds, nullptr);
    std::map<std::pair<double, double>, double> height;
    for (const dtm::Point3& p : tin.vertices) height[{p.x, p.y}] = p.z;
    std::map<std::string, int> per_layer;
    std::size_t corners = 0;
    OGRLayer* layer = ds->GetLayer(0);
    for (auto& feature : *layer) {
        const std::string name = feature->GetFieldAsString("Layer");
        ++per_layer[name];
        const OGRGeometry* g = feature->GetGeometryRef();
        ASSERT_NE(g, nullptr);
        if (name != "TIN") continue;
        ASSERT_EQ(wkbFlatten(g->getGeometryType()), wkbPolygon) << g->getGeometryName();
        const OGRLinearRing* ring = g->toPolygon()->getExteriorRing();
        ASSERT_TRUE(ring->Is3D());
        for (int i = 0; i < ring->getNumPoints(); ++i) {
            const auto it = height.find({ring->getX(i), ring->getY(i)});
            ASSERT_NE(it, height.end());
            EXPECT_EQ(ring->getZ(i), it->second);
            ++corners;
        }
    }
    GDALClose(ds);
    EXPECT_EQ(per_layer["TIN"], 32);
    EXPECT_EQ(per_layer["BREAKLINES"], 1);
    EXPECT_EQ(per_layer["BOUNDARY"], 1);
    EXPECT_GE(corners, 32U * 3U);
}

TEST(Dxf, EzdxfReadsLayersFacesAndPolylines) {
    if (std::system("/usr/bin/python3 -c 'import ezdxf' >/dev/null 2>&1") != 0) {
        GTEST_SKIP() << "python3-ezdxf missing";
    }
    test::ScratchDir dir;
    io::write_tin(sample_tin(), dir / "tin.dxf", {});
    test::write_file(dir / "check.py",
                     "import sys, ezdxf\n"
                     "doc = ezdxf.readfile(sys.argv[1])\n"
                     "msp = doc.modelspace()\n"
                     "faces = msp.query('3DFACE[layer==\"TIN\"]')\n"
                     "assert len(faces) == 32, len(faces)\n"
                     "f = faces[0]\n"
                     "assert abs(f.dxf.vtx0.x + 750000.0) < 1e-9, f.dxf.vtx0\n"
                     "lines = msp.query('POLYLINE[layer==\"BREAKLINES\"]')\n"
                     "assert len(lines) == 1 and lines[0].is_3d_polyline\n"
                     "pts = list(lines[0].points())\n"
                     "assert len(pts) == 5, pts\n"
                     "assert all(abs(p.y + 1049995.0) < 1e-9 for p in pts), pts\n"
                     "assert {l.dxf.name for l in doc.layers} >= {'TIN', 'BREAKLINES', "
                     "'BOUNDARY', 'HOLES'}\n");
    const std::string command = "/usr/bin/python3 '" + (dir / "check.py").string() + "' '" +
                                (dir / "tin.dxf").string() + "' 2>'" + (dir / "log").string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << test::read_file(dir / "log");
}

TEST(Dxf, FacesReadBackAsTheSameTin) {
    test::ScratchDir dir;
    const dtm::Tin tin = sample_tin();
    io::write_tin(tin, dir / "tin.dxf", {});
    EXPECT_EQ(io::find_reader(dir / "tin.dxf").name, "dxf");
    const io::ReadResult r = io::read_dxf({dir / "tin.dxf", io::InputRole::points}, {});
    ASSERT_TRUE(r.tin.has_value());
    EXPECT_EQ(r.summary.triangles, tin.triangles.size());
    ASSERT_EQ(r.tin->vertices.size(), tin.vertices.size());
    std::map<std::pair<double, double>, double> height;
    for (const dtm::Point3& p : tin.vertices) height[{p.x, p.y}] = p.z;
    for (const dtm::Point3& p : r.tin->vertices) EXPECT_EQ((height[{p.x, p.y}]), p.z);
    const auto report = dtm::verify_topology(*r.tin);
    EXPECT_TRUE(report.ok()) << report.text();
    io::ReadOptions options;
    options.retriangulate = true;
    const io::ReadResult points = io::read_dxf({dir / "tin.dxf", io::InputRole::points}, options);
    EXPECT_FALSE(points.tin.has_value());
    EXPECT_EQ(points.terrain.points.size(), 25U);
}

TEST(Dxf, DrawingWithoutFacesGoesToOgr) {
    test::ScratchDir dir;
    {
        const io::DxfLayer layers[] = {{"SPOTS", 2}};
        io::DxfWriter dxf(dir / "spots.dxf", layers);
        dxf.point("SPOTS", {1.0, 2.0, 3.5});
        dxf.point("SPOTS", {4.0, 2.0, 3.0});
        dxf.finish();
    }
    const io::ReadResult r = io::read_dxf({dir / "spots.dxf", io::InputRole::points}, {});
    EXPECT_FALSE(r.tin.has_value());
    EXPECT_EQ(r.terrain.points.size(), 2U);
}

TEST(Dxf, BadGroupCodeNamesTheLine) {
    test::ScratchDir dir;
    test::write_file(dir / "bad.dxf", "0\nSECTION\n2\nENTITIES\n0\n3DFACE\nten\n1.0\n");
    try {
        (void)io::read_dxf({dir / "bad.dxf", io::InputRole::points}, {});
        FAIL() << "expected an InputError";
    } catch (const dtm::InputError& e) {
        EXPECT_EQ(e.line(), 7U);
    }
}

}  // namespace
