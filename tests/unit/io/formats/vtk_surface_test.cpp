// SPDX-License-Identifier: MIT
#include "dtm/io/formats/vtk_surface.hpp"

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include "dtm/core/error.hpp"
#include "support/test_support.hpp"
#include "support/tin_fixture.hpp"

namespace {

vtkSmartPointer<vtkPolyData> read_back(const std::filesystem::path& path) {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.string().c_str());
    reader->Update();
    return reader->GetOutput();
}

TEST(VtkSurface, ReadBackByVtkHasTinCountsAndElevationArray) {
    const dtm::Tin tin = dtm::test::grid_tin(7);
    dtm::test::ScratchDir dir;
    dtm::io::write_vtp(tin, dir / "surface.vtp", {});
    const auto poly = read_back(dir / "surface.vtp");
    ASSERT_NE(poly, nullptr);
    EXPECT_EQ(poly->GetNumberOfPoints(), static_cast<vtkIdType>(tin.vertices.size()));
    EXPECT_EQ(poly->GetNumberOfPolys(), static_cast<vtkIdType>(tin.triangles.size()));
    EXPECT_EQ(poly->GetNumberOfLines(), static_cast<vtkIdType>(tin.constraints.size()));

    vtkDataArray* elevation = poly->GetPointData()->GetArray("elevation");
    ASSERT_NE(elevation, nullptr);
    ASSERT_EQ(elevation->GetNumberOfTuples(), poly->GetNumberOfPoints());
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
        double p[3];
        poly->GetPoint(i, p);
        const dtm::Point3& v = tin.vertices[static_cast<std::size_t>(i)];
        EXPECT_EQ(p[0], v.x);  // double precision survives the large S-JTSK offsets
        EXPECT_EQ(p[1], v.y);
        EXPECT_EQ(p[2], v.z);
        EXPECT_EQ(elevation->GetTuple1(i), v.z);
    }
}

TEST(VtkSurface, TrianglesAndBreaklineCellsKeepTheirVertices) {
    const dtm::Tin tin = dtm::test::grid_tin(4);
    dtm::test::ScratchDir dir;
    dtm::io::write_vtp(tin, dir / "surface.vtp", {});
    const auto poly = read_back(dir / "surface.vtp");

    vtkNew<vtkIdList> ids;
    vtkCellArray* polys = poly->GetPolys();
    polys->InitTraversal();
    for (const dtm::Triangle& t : tin.triangles) {
        ASSERT_TRUE(polys->GetNextCell(ids));
        ASSERT_EQ(ids->GetNumberOfIds(), 3);
        for (vtkIdType k = 0; k < 3; ++k) {
            EXPECT_EQ(ids->GetId(k), static_cast<vtkIdType>(t.v[static_cast<std::size_t>(k)]));
        }
    }
    vtkCellArray* lines = poly->GetLines();
    lines->InitTraversal();
    for (const dtm::ConstrainedEdge& e : tin.constraints) {
        ASSERT_TRUE(lines->GetNextCell(ids));
        ASSERT_EQ(ids->GetNumberOfIds(), 2);
        EXPECT_EQ(ids->GetId(0), static_cast<vtkIdType>(e.a));
        EXPECT_EQ(ids->GetId(1), static_cast<vtkIdType>(e.b));
    }
    vtkDataArray* kind = poly->GetCellData()->GetArray("constraint_kind");
    ASSERT_NE(kind, nullptr);
    EXPECT_EQ(kind->GetNumberOfTuples(), poly->GetNumberOfCells());
    EXPECT_EQ(kind->GetTuple1(0), 0.0);                              // first line: a breakline
    EXPECT_EQ(kind->GetTuple1(poly->GetNumberOfCells() - 1), -1.0);  // last cell: a triangle
}

TEST(VtkSurface, CrsIsKeptInFieldData) {
    dtm::test::ScratchDir dir;
    dtm::io::TinWriteOptions options;
    options.crs_wkt = "PROJCS[\"S-JTSK / Krovak East North\"]";
    dtm::io::write_vtp(dtm::test::grid_tin(3), dir / "surface.vtp", options);
    const auto poly = read_back(dir / "surface.vtp");
    auto* crs = vtkStringArray::SafeDownCast(poly->GetFieldData()->GetAbstractArray("crs_wkt"));
    ASSERT_NE(crs, nullptr);
    EXPECT_EQ(crs->GetValue(0), options.crs_wkt);
}

TEST(VtkSurface, UnwritablePathThrowsError) {
    EXPECT_THROW(dtm::io::write_vtp(dtm::test::grid_tin(3), "/nonexistent/dir/surface.vtp", {}),
                 dtm::Error);
}

}  // namespace
