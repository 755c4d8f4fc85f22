// SPDX-License-Identifier: MIT
// SMS 2DM writer and reader. Format: Aquaveo SMS "2D Mesh Files *.2dm" card list, as read by
// MDAL's 2DM driver in QGIS: the first line is MESH2D; `ND id x y z`; `E3T id n1 n2 n3 matid`.
#include "dtm/io/formats/mesh_2dm.hpp"

#include <array>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <unordered_map>

#include "dtm/core/error.hpp"
#include "tin_checks.hpp"

namespace dtm::io {
namespace {

/// Appends the shortest text that reads back as exactly @p value.
void append_number(std::string& out, double value) {
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    out.append(buffer.data(), result.ptr);
}

void append_number(std::string& out, std::size_t value) {
    std::array<char, 24> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    out.append(buffer.data(), result.ptr);
}

}  // namespace

void write_2dm(const Tin& tin, const std::filesystem::path& path, const TinWriteOptions&) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) {
        throw Error("2dm: cannot create " + path.string());
    }
    // Text is built in blocks of about 1 MiB so memory stays flat for large TINs.
    constexpr std::size_t block = std::size_t{1} << 20;
    std::string text = "MESH2D\nMESHNAME \"dtm TIN\"\n";
    text.reserve(block + 256);
    const auto flush_if_full = [&](bool force) {
        if (force || text.size() >= block) {
            file.write(text.data(), static_cast<std::streamsize>(text.size()));
            text.clear();
        }
    };
    for (std::size_t i = 0; i < tin.vertices.size(); ++i) {
        const Point3& p = tin.vertices[i];
        text += "ND ";
        append_number(text, i + 1);
        for (const double c : {p.x, p.y, p.z}) {
            text += ' ';
            append_number(text, c);
        }
        text += '\n';
        flush_if_full(false);
    }
    for (std::size_t i = 0; i < tin.triangles.size(); ++i) {
        text += "E3T ";
        append_number(text, i + 1);
        for (const VertexIndex v : tin.triangles[i].v) {
            text += ' ';
            append_number(text, std::size_t{v} + 1);
        }
        text += " 1\n";
        flush_if_full(false);
    }
    flush_if_full(true);
    file.close();
    if (!file) {
        throw Error("2dm: cannot write " + path.string());
    }
}

namespace {

struct Reader2dm {
    const std::filesystem::path& path;
    std::size_t line_number = 0;
    std::unordered_map<long long, VertexIndex> node_index;

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(path, line_number, 0, "2dm: " + what);
    }

    void read_node(std::istringstream& fields, Tin& tin) {
        long long id = 0;
        Point3 p;
        if (!(fields >> id >> p.x >> p.y >> p.z)) {
            fail("expected `ND id x y z`");
        }
        if (!node_index.emplace(id, static_cast<VertexIndex>(tin.vertices.size())).second) {
            fail("node id " + std::to_string(id) + " defined twice");
        }
        tin.vertices.push_back(p);
    }

    void read_triangle(std::istringstream& fields, Tin& tin) const {
        long long id = 0;
        std::array<long long, 3> nodes{};
        if (!(fields >> id >> nodes[0] >> nodes[1] >> nodes[2])) {
            fail("expected `E3T id n1 n2 n3 [material]`");
        }
        Triangle t;
        for (std::size_t k = 0; k < 3; ++k) {
            const auto it = node_index.find(nodes[k]);
            if (it == node_index.end()) {
                fail("element refers to unknown node " + std::to_string(nodes[k]) +
                     " (nodes must come before elements)");
            }
            t.v[k] = it->second;
        }
        tin.triangles.push_back(t);
    }
};

}  // namespace

Tin read_2dm(const std::filesystem::path& path) {
    std::ifstream file(path);
    if (!file) {
        throw InputError(path, 0, 0, "2dm: cannot open file");
    }
    Tin tin;
    Reader2dm reader{path, 0, {}};
    std::string line;
    while (std::getline(file, line)) {
        ++reader.line_number;
        std::istringstream fields(line);
        std::string card;
        fields >> card;
        if (reader.line_number == 1 && card != "MESH2D") {
            reader.fail("expected MESH2D on the first line");
        }
        if (card == "ND") {
            reader.read_node(fields, tin);
        } else if (card == "E3T") {
            reader.read_triangle(fields, tin);
        }
    }
    if (reader.line_number == 0) {
        throw InputError(path, 0, 0, "2dm: empty file, expected MESH2D");
    }
    try {
        link_neighbours(tin);
        detail::check_tin_from_file(tin);
    } catch (const InputError& e) {
        throw InputError(path, 0, 0, "2dm: " + std::string(e.what()));
    }
    return tin;
}

}  // namespace dtm::io
