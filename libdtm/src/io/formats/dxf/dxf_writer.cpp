// SPDX-License-Identifier: MIT
// ASCII DXF R12 writer: group code / value lines, a HEADER with $ACADVER AC1009, LTYPE and LAYER
// tables, then the entities streamed through a buffer. Reference: AutoCAD R12 DXF reference
// (group codes 0 entity, 8 layer, 10/20/30 .. 13/23/33 points, 40 height, 50 rotation, 66
// vertices follow, 70 flags, 62 colour, 6 line type).
#include <charconv>
#include <string>

#include "dtm/algo/constraint_chains.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/formats/dxf.hpp"

namespace dtm::io {

DxfWriter::DxfWriter(const std::filesystem::path& path, std::span<const DxfLayer> layers)
    : path_(path), out_(path, std::ios::binary) {
    if (!out_) throw Error("cannot write " + path.string());
    code(0, "SECTION");
    code(2, "HEADER");
    code(9, "$ACADVER");
    code(1, "AC1009");
    code(0, "ENDSEC");
    code(0, "SECTION");
    code(2, "TABLES");
    code(0, "TABLE");
    code(2, "LTYPE");
    code(70, "1");
    code(0, "LTYPE");
    code(2, "CONTINUOUS");
    code(70, "0");
    code(3, "Solid line");
    code(72, "65");
    code(73, "0");
    code(40, 0.0);
    code(0, "ENDTAB");
    code(0, "TABLE");
    code(2, "LAYER");
    code(70, std::to_string(layers.size() + 1));
    code(0, "LAYER");
    code(2, "0");
    code(70, "0");
    code(62, "7");
    code(6, "CONTINUOUS");
    for (const DxfLayer& l : layers) {
        code(0, "LAYER");
        code(2, l.name);
        code(70, "0");
        code(62, std::to_string(l.color));
        code(6, "CONTINUOUS");
    }
    code(0, "ENDTAB");
    code(0, "ENDSEC");
    code(0, "SECTION");
    code(2, "ENTITIES");
}

void DxfWriter::code(int group, std::string_view value) {
    char text[16];
    const char* end = std::to_chars(text, text + sizeof text, group).ptr;
    buffer_.append(text, static_cast<std::size_t>(end - text));
    buffer_ += '\n';
    buffer_.append(value);
    buffer_ += '\n';
    if (buffer_.size() >= (std::size_t{1} << 20)) {
        out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
        buffer_.clear();
    }
}

void DxfWriter::code(int group, double value) {
    char text[32];
    const char* end = std::to_chars(text, text + sizeof text, value).ptr;
    code(group, std::string_view(text, static_cast<std::size_t>(end - text)));
}

void DxfWriter::xyz(int first, const Point3& p) {
    code(first, p.x);
    code(first + 10, p.y);
    code(first + 20, p.z);
}

void DxfWriter::face(std::string_view layer, const Point3& a, const Point3& b, const Point3& c) {
    code(0, "3DFACE");
    code(8, layer);
    xyz(10, a);
    xyz(11, b);
    xyz(12, c);
    xyz(13, c);
}

void DxfWriter::polyline(std::string_view layer, std::span<const Point3> points, bool closed) {
    code(0, "POLYLINE");
    code(8, layer);
    code(66, "1");
    xyz(10, {0.0, 0.0, 0.0});
    code(70, closed ? "9" : "8");
    for (const Point3& p : points) {
        code(0, "VERTEX");
        code(8, layer);
        xyz(10, p);
        code(70, "32");
    }
    code(0, "SEQEND");
    code(8, layer);
}

void DxfWriter::point(std::string_view layer, const Point3& p) {
    code(0, "POINT");
    code(8, layer);
    xyz(10, p);
}

void DxfWriter::text(std::string_view layer,
                     const Point3& at,
                     double height,
                     double rotation_deg,
                     std::string_view text) {
    code(0, "TEXT");
    code(8, layer);
    xyz(10, at);
    code(40, height);
    code(1, text);
    if (rotation_deg != 0.0) code(50, rotation_deg);
}

void DxfWriter::finish() {
    code(0, "ENDSEC");
    code(0, "EOF");
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
    out_.close();
    if (!out_) throw Error("cannot write " + path_.string());
}

void write_tin_dxf(const Tin& tin, const std::filesystem::path& path, const TinWriteOptions&) {
    struct KindLayer {
        ConstraintKind kind;
        DxfLayer layer;
    };
    const KindLayer lines[] = {{ConstraintKind::breakline, {"BREAKLINES", 1}},
                               {ConstraintKind::soft_breakline, {"SOFT_BREAKLINES", 6}},
                               {ConstraintKind::boundary, {"BOUNDARY", 3}},
                               {ConstraintKind::hole, {"HOLES", 4}}};
    std::vector<DxfLayer> layers{{"TIN", 8}};
    for (const KindLayer& k : lines) layers.push_back(k.layer);
    DxfWriter dxf(path, layers);
    for (const Triangle& t : tin.triangles) {
        dxf.face("TIN", tin.vertex(t.v[0]), tin.vertex(t.v[1]), tin.vertex(t.v[2]));
    }
    std::vector<Point3> points;
    for (const KindLayer& k : lines) {
        for (const ConstraintChain& chain : constraint_chains(tin, k.kind)) {
            points.clear();
            for (VertexIndex v : chain.vertices) points.push_back(tin.vertex(v));
            dxf.polyline(k.layer.name, points, chain.closed);
        }
    }
    dxf.finish();
}

}  // namespace dtm::io
