// SPDX-License-Identifier: MIT
// VTK XML PolyData writer: builds a vtkPolyData from the TIN and hands it to vtkXMLPolyDataWriter
// (binary, appended, zlib-compressed: the VTK default that ParaView reads fastest).
#include "dtm/io/formats/vtk_surface.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstring>
#include <fstream>
#include <string>

#include "dtm/core/error.hpp"

namespace dtm::io {
namespace {

void add_points(const Tin& tin, vtkPolyData& poly) {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(static_cast<vtkIdType>(tin.vertices.size()));
    vtkNew<vtkDoubleArray> elevation;
    elevation->SetName("elevation");
    elevation->SetNumberOfComponents(1);
    elevation->SetNumberOfTuples(static_cast<vtkIdType>(tin.vertices.size()));
    for (std::size_t i = 0; i < tin.vertices.size(); ++i) {
        const Point3& p = tin.vertices[i];
        const auto id = static_cast<vtkIdType>(i);
        points->SetPoint(id, p.x, p.y, p.z);
        elevation->SetValue(id, p.z);
    }
    poly.SetPoints(points);
    poly.GetPointData()->AddArray(elevation);
    poly.GetPointData()->SetActiveScalars("elevation");
}

void add_cells(const Tin& tin, vtkPolyData& poly) {
    vtkNew<vtkCellArray> triangles;
    triangles->AllocateExact(static_cast<vtkIdType>(tin.triangles.size()),
                             static_cast<vtkIdType>(tin.triangles.size() * 3));
    for (const Triangle& t : tin.triangles) {
        const vtkIdType ids[3] = {t.v[0], t.v[1], t.v[2]};
        triangles->InsertNextCell(3, ids);
    }
    vtkNew<vtkCellArray> lines;
    lines->AllocateExact(static_cast<vtkIdType>(tin.constraints.size()),
                         static_cast<vtkIdType>(tin.constraints.size() * 2));
    for (const ConstrainedEdge& e : tin.constraints) {
        const vtkIdType ids[2] = {e.a, e.b};
        lines->InsertNextCell(2, ids);
    }
    poly.SetPolys(triangles);
    poly.SetLines(lines);

    // vtkPolyData numbers cells verts, lines, polys, strips: lines come first in cell order.
    vtkNew<vtkIntArray> kind;
    kind->SetName("constraint_kind");
    kind->SetNumberOfTuples(static_cast<vtkIdType>(tin.constraints.size() + tin.triangles.size()));
    vtkIdType cell = 0;
    for (const ConstrainedEdge& e : tin.constraints) {
        kind->SetValue(cell++, static_cast<int>(e.kind));
    }
    for (std::size_t i = 0; i < tin.triangles.size(); ++i) {
        kind->SetValue(cell++, -1);
    }
    poly.GetCellData()->AddArray(kind);
}

}  // namespace

void write_vtp(const Tin& tin, const std::filesystem::path& path, const TinWriteOptions& options) {
    vtkNew<vtkPolyData> poly;
    add_points(tin, *poly);
    add_cells(tin, *poly);
    if (!options.crs_wkt.empty()) {
        vtkNew<vtkStringArray> crs;
        crs->SetName("crs_wkt");
        crs->InsertNextValue(options.crs_wkt);
        poly->GetFieldData()->AddArray(crs);
    }

    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(path.string().c_str());
    writer->SetInputData(poly);
    writer->SetDataModeToAppended();
    writer->SetCompressorTypeToZLib();
    // A failed write (full disk, file-size limit) becomes one dtm error below instead of VTK's
    // multi-line log on stderr.
    const int display = vtkObject::GetGlobalWarningDisplay();
    vtkObject::GlobalWarningDisplayOff();
    const int written = writer->Write();
    const unsigned long error = writer->GetErrorCode();
    vtkObject::SetGlobalWarningDisplay(display);
    if (written != 1 || error != 0) {
        const std::string why = error == vtkErrorCode::OutOfDiskSpaceError
                                    ? ": no space left (full disk or file-size limit)"
                                : error > 0 && error < 1000
                                    ? std::string(": ") + std::strerror(static_cast<int>(error))
                                : error != 0 ? ": VTK error " + std::to_string(error)
                                             : std::string();
        throw Error("vtp: cannot write " + path.string() + why);
    }
}

void write_pvtp(const std::filesystem::path& path,
                const std::vector<std::filesystem::path>& pieces) {
    // The arrays of write_vtp's pieces: the summary must name each one with its type.
    std::string text =
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n"
        "  <PPolyData GhostLevel=\"0\">\n"
        "    <PPointData Scalars=\"elevation\">\n"
        "      <PDataArray type=\"Float64\" Name=\"elevation\"/>\n"
        "    </PPointData>\n"
        "    <PCellData>\n"
        "      <PDataArray type=\"Int32\" Name=\"constraint_kind\"/>\n"
        "    </PCellData>\n"
        "    <PPoints>\n"
        "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
        "    </PPoints>\n";
    for (const std::filesystem::path& piece : pieces) {
        text += "    <Piece Source=\"" + piece.filename().string() + "\"/>\n";
    }
    text += "  </PPolyData>\n</VTKFile>\n";
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) throw Error("pvtp: cannot write " + path.string());
}

}  // namespace dtm::io
