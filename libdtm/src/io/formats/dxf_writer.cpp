// SPDX-License-Identifier: MIT
// DXF R12 (AC1009) ASCII output: group code / value pairs, one per line.
//
//   0 SECTION 2 HEADER  ($ACADVER AC1009, $EXTMIN/$EXTMAX written as the file's extent would
//                        need a second pass, so they are left out: readers compute them)
//   0 SECTION 2 TABLES  (LTYPE CONTINUOUS, LAYER table)
//   0 SECTION 2 ENTITIES
//   0 ENDSEC 0 EOF
// Entities are buffered until the layer table is known (the first entity closes the tables), then
// streamed. Coordinates are written with 17 significant digits (round-trip exact).
// Reference: Autodesk, "DXF Reference" (AutoCAD R12 DXF, group codes of POLYLINE, VERTEX, SEQEND,
// 3DFACE, TEXT, LAYER).
#include "dtm/io/formats/dxf_writer.hpp"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"

namespace dtm::io {
namespace {

std::string clean_name(const std::string& name) {
    std::string out = name.empty() ? std::string("0") : name;
    for (char& c : out) {
        const auto u = static_cast<unsigned char>(c);
        if (!(std::isalnum(u) || c == '_' || c == '-' || c == '$')) {
            c = '_';
        }
    }
    return out;
}

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

}  // namespace

struct DxfWriter::State {
    AtomicOutput out;
    std::ofstream file;
    std::vector<DxfLayer> layers;
    bool entities_started = false;
    std::size_t entities = 0;

    explicit State(const std::filesystem::path& target) : out(target) {
        file.open(out.temp_path(), std::ios::binary);
        if (!file) {
            throw Error("dxf: cannot create " + out.temp_path().string());
        }
    }
    void pair(int code, const std::string& value) { file << code << '\n' << value << '\n'; }
    void pair(int code, int value) { file << code << '\n' << value << '\n'; }
    void point(int base, const Point3& p) {
        pair(base, number(p.x));
        pair(base + 10, number(p.y));
        pair(base + 20, number(p.z));
    }
    void start_entities() {
        if (entities_started) {
            return;
        }
        entities_started = true;
        pair(0, "SECTION");
        pair(2, "HEADER");
        pair(9, "$ACADVER");
        pair(1, "AC1009");
        pair(0, "ENDSEC");
        pair(0, "SECTION");
        pair(2, "TABLES");
        pair(0, "TABLE");
        pair(2, "LTYPE");
        pair(70, 1);
        pair(0, "LTYPE");
        pair(2, "CONTINUOUS");
        pair(70, 0);
        pair(3, "Solid line");
        pair(72, 65);
        pair(73, 0);
        pair(40, "0.0");
        pair(0, "ENDTAB");
        pair(0, "TABLE");
        pair(2, "LAYER");
        pair(70, static_cast<int>(layers.size() + 1));
        pair(0, "LAYER");
        pair(2, "0");
        pair(70, 0);
        pair(62, 7);
        pair(6, "CONTINUOUS");
        for (const DxfLayer& l : layers) {
            pair(0, "LAYER");
            pair(2, l.name);
            pair(70, 0);
            pair(62, l.color);
            pair(6, "CONTINUOUS");
        }
        pair(0, "ENDTAB");
        pair(0, "ENDSEC");
        pair(0, "SECTION");
        pair(2, "ENTITIES");
    }
};

DxfWriter::DxfWriter(const std::filesystem::path& target)
    : state_(std::make_unique<State>(target)) {}

DxfWriter::~DxfWriter() = default;

void DxfWriter::add_layer(const DxfLayer& layer) {
    if (state_->entities_started) {
        throw Error("dxf: layer " + layer.name + " declared after the first entity");
    }
    state_->layers.push_back({clean_name(layer.name), layer.color});
}

void DxfWriter::polyline_3d(const std::string& layer, std::span<const Point3> points, bool closed) {
    State& s = *state_;
    s.start_entities();
    const std::string name = clean_name(layer);
    s.pair(0, "POLYLINE");
    s.pair(8, name);
    s.pair(66, 1);
    s.point(10, {0.0, 0.0, 0.0});
    s.pair(70, closed ? 9 : 8);
    for (const Point3& p : points) {
        s.pair(0, "VERTEX");
        s.pair(8, name);
        s.point(10, p);
        s.pair(70, 32);
    }
    s.pair(0, "SEQEND");
    s.pair(8, name);
    ++s.entities;
}

void DxfWriter::face_3d(const std::string& layer,
                        const Point3& a,
                        const Point3& b,
                        const Point3& c) {
    State& s = *state_;
    s.start_entities();
    s.pair(0, "3DFACE");
    s.pair(8, clean_name(layer));
    s.point(10, a);
    s.point(11, b);
    s.point(12, c);
    s.point(13, c);
    ++s.entities;
}

void DxfWriter::text(const std::string& layer,
                     const Point3& at,
                     double height,
                     const std::string& value,
                     double rotation) {
    State& s = *state_;
    s.start_entities();
    s.pair(0, "TEXT");
    s.pair(8, clean_name(layer));
    s.point(10, at);
    s.pair(40, number(height));
    s.pair(1, value);
    if (rotation != 0.0) {
        s.pair(50, number(rotation));
    }
    ++s.entities;
}

std::size_t DxfWriter::entity_count() const noexcept { return state_->entities; }

void DxfWriter::commit() {
    State& s = *state_;
    s.start_entities();
    s.pair(0, "ENDSEC");
    s.pair(0, "EOF");
    s.file.close();
    if (!s.file) {
        throw Error("dxf: cannot write " + s.out.target().string());
    }
    s.out.commit();
}

}  // namespace dtm::io
