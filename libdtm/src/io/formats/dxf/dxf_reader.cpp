// SPDX-License-Identifier: MIT
// DXF 3DFACE TIN reader: a scan of the ASCII group codes of the ENTITIES section (AutoCAD DXF
// reference: 0 entity type, 10/20/30 .. 13/23/33 the four corners). A drawing with 3DFACEs is a
// TIN drawn in CAD (Civil 3D "explode", BricsCAD, dtm's own writer): equal corners (same x and
// y) become one vertex, triangles are turned counter-clockwise. Drawings without 3DFACEs, and
// binary DXF, are read by OGR as points and lines.
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"
#include "dtm/io/formats/dxf.hpp"
#include "dtm/io/formats/ogr.hpp"

namespace dtm::io {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) {
        s.remove_suffix(1);
    }
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

struct FaceScan {
    std::vector<std::array<Point3, 4>> faces;
    bool binary = false;
};

FaceScan scan_faces(const std::filesystem::path& path) {
    FaceScan scan;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, 0, "cannot open the file");
    std::string code_line;
    std::string value_line;
    std::size_t line = 0;
    bool in_entities = false;
    bool section_name = false;
    bool in_face = false;
    std::array<Point3, 4> corners{};
    while (std::getline(in, code_line)) {
        ++line;
        if (line == 1 && code_line.starts_with("AutoCAD Binary DXF")) {
            scan.binary = true;
            return scan;
        }
        if (!std::getline(in, value_line)) {
            throw InputError(path, line, 0, "expected a value after group code (truncated?)");
        }
        ++line;
        const std::string_view c = trim(code_line);
        const std::string_view v = trim(value_line);
        int group = 0;
        const auto r = std::from_chars(c.data(), c.data() + c.size(), group);
        if (r.ec != std::errc{} || r.ptr != c.data() + c.size()) {
            throw InputError(path, line - 1, 1,
                             "expected a DXF group code, found '" + std::string(c) + "'");
        }
        if (group == 0) {
            if (in_face) scan.faces.push_back(corners);
            in_face = in_entities && v == "3DFACE";
            corners = {};
            if (v == "ENDSEC") in_entities = false;
            section_name = v == "SECTION";
            continue;
        }
        if (section_name && group == 2) {
            in_entities = v == "ENTITIES";
            section_name = false;
        }
        if (!in_face || group < 10 || group > 33 || group % 10 > 3) continue;
        double value = 0;
        const auto n = std::from_chars(v.data(), v.data() + v.size(), value);
        if (n.ec != std::errc{} || n.ptr != v.data() + v.size()) {
            throw InputError(path, line, 1,
                             "expected a number for group code " + std::to_string(group) +
                                 " of a 3DFACE, found '" + std::string(v) + "'");
        }
        Point3& p = corners[static_cast<std::size_t>(group % 10)];
        (group < 20 ? p.x : group < 30 ? p.y : p.z) = value;
    }
    if (in_face) scan.faces.push_back(corners);
    return scan;
}

}  // namespace

ReadResult read_dxf(const InputFile& file, const ReadOptions& options, const Progress& progress) {
    if (file.role != InputRole::points) return read_ogr(file, options, progress);
    progress.report(0.0, "reading the DXF");
    FaceScan scan = scan_faces(file.path);
    if (scan.binary || scan.faces.empty()) return read_ogr(file, options, progress);
    ReadResult r;
    r.summary.path = file.path;
    r.summary.format = "DXF 3DFACE TIN";
    std::map<std::pair<double, double>, VertexIndex> at;
    std::size_t other_z = 0;
    const auto vertex = [&](const Point3& p) {
        const auto [it, added] =
            at.emplace(std::pair{p.x, p.y}, static_cast<VertexIndex>(r.terrain.points.size()));
        if (added) {
            r.terrain.points.push_back(p);
        } else if (r.terrain.points[it->second].z != p.z) {
            ++other_z;
        }
        return it->second;
    };
    Tin tin;
    std::size_t degenerate = 0;
    const auto add = [&](VertexIndex a, VertexIndex b, VertexIndex c) {
        const Point3& pa = r.terrain.points[a];
        const Point3& pb = r.terrain.points[b];
        const Point3& pc = r.terrain.points[c];
        const int o = geom::orient2d(pa.x, pa.y, pb.x, pb.y, pc.x, pc.y);
        if (o == 0) {
            ++degenerate;
            return;
        }
        Triangle t;
        t.v = o > 0 ? std::array{a, b, c} : std::array{a, c, b};
        tin.triangles.push_back(t);
    };
    for (const auto& f : scan.faces) {
        const std::array<VertexIndex, 4> v{vertex(f[0]), vertex(f[1]), vertex(f[2]), vertex(f[3])};
        add(v[0], v[1], v[2]);
        if (v[3] != v[2] && v[3] != v[0] && v[3] != v[1]) add(v[0], v[2], v[3]);
    }
    if (degenerate > 0) {
        r.summary.warnings.push_back(std::to_string(degenerate) +
                                     " 3DFACEs with collinear corners left out");
    }
    if (other_z > 0) {
        r.summary.warnings.push_back(std::to_string(other_z) +
                                     " face corners at a vertex's x, y with another height (the "
                                     "first height kept)");
    }
    if (options.retriangulate) return r;
    tin.vertices = r.terrain.points;
    try {
        link_neighbours(tin);
    } catch (const InputError& e) {
        throw InputError(file.path, 0, 0,
                         std::string("the 3DFACEs do not form a TIN: ") + e.what());
    }
    r.summary.triangles = tin.triangles.size();
    r.tin = std::move(tin);
    return r;
}

}  // namespace dtm::io
