// SPDX-License-Identifier: MIT
// Reads dtm's own PLY TIN files (layout in docs/formats.md), binary little endian or ASCII. The
// reader is strict on purpose: it accepts exactly the elements and properties dtm writes (any
// comment lines are fine) and names the file and header line of anything else, rather than
// guessing at a PLY written for another purpose. Neighbour links are not stored in the file; they
// are rebuilt from the faces: every directed edge a->b of a counter-clockwise triangle meets the
// edge b->a of its neighbour (dtm::link_neighbours, O(n)).
// Reference: Greg Turk, "The PLY Polygon File Format" (1994).
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/ply.hpp"
#include "io/detail/file_bytes.hpp"
#include "io/formats/tin_checks.hpp"

namespace dtm::io {
namespace {

namespace fs = std::filesystem;

enum class Encoding { ascii, binary_little_endian };

struct Header {
    Encoding encoding = Encoding::binary_little_endian;
    std::string crs_wkt;
    std::size_t vertex_count = 0;
    std::size_t face_count = 0;
    std::size_t edge_count = 0;
    bool edge_has_kind = false;
    std::size_t id_count = 0;     ///< the optional vertex_id element of a tile (tin_tiles.hpp)
    std::size_t body_offset = 0;  ///< byte offset just after "end_header\n"
    std::size_t line_count = 0;   ///< lines up to and including end_header
};

std::vector<std::string_view> split_words(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

/// Type names as PLY spells them, with the sized aliases of later PLY writers.
bool is_type(std::string_view word, std::string_view type) {
    if (word == type) return true;
    if (type == "double") return word == "float64";
    if (type == "int") return word == "int32";
    if (type == "uchar") return word == "uint8";
    if (type == "uint") return word == "uint32";
    return false;
}

/// The properties dtm writes, element by element; `kind` of an edge may be absent.
bool expected_property(std::string_view element,
                       std::size_t index,
                       const std::vector<std::string_view>& w) {
    if (element == "vertex") {
        constexpr std::string_view names[] = {"x", "y", "z"};
        return index < 3 && w.size() == 3 && is_type(w[1], "double") && w[2] == names[index];
    }
    if (element == "face") {
        return index == 0 && w.size() == 5 && w[1] == "list" && is_type(w[2], "uchar") &&
               is_type(w[3], "int") && w[4] == "vertex_indices";
    }
    if (element == "vertex_id") {
        constexpr std::string_view names[] = {"high", "low"};
        return index < 2 && w.size() == 3 && is_type(w[1], "uint") && w[2] == names[index];
    }
    constexpr std::string_view names[] = {"vertex1", "vertex2", "kind"};
    const std::string_view type = index == 2 ? "uchar" : "int";
    return index < 3 && w.size() == 3 && is_type(w[1], type) && w[2] == names[index];
}

struct HeaderParser {
    const fs::path& path;
    Header header;
    std::string current;             ///< element whose properties are being declared
    std::size_t property_count = 0;  ///< properties declared so far for `current`
    int last_element = -1;           ///< 0 vertex, 1 face, 2 edge, 3 vertex_id: enforces the order

    [[noreturn]] void fail(std::size_t line, const std::string& what) const {
        throw InputError(path, line, 0, what);
    }

    void finish_element(std::size_t line) const {
        const std::size_t needed = current == "vertex" ? 3 : current == "face" ? 1 : 2;  // edge, id
        if (!current.empty() && property_count < needed) {
            fail(line,
                 "element '" + current +
                     "' lacks properties (expected the ones dtm writes: " + "see docs/formats.md)");
        }
    }

    void element(std::size_t line, const std::vector<std::string_view>& w) {
        finish_element(line);
        constexpr std::string_view names[] = {"vertex", "face", "edge", "vertex_id"};
        const auto* found =
            w.size() == 3 ? std::find(std::begin(names), std::end(names), w[1]) : std::end(names);
        const int which = static_cast<int>(found - std::begin(names));
        if (found == std::end(names) || which <= last_element) {
            fail(line, "unexpected '" + std::string(w.size() > 1 ? w[1] : "") +
                           "' element (a dtm PLY has vertex, face, edge in that order)");
        }
        std::uint64_t count = 0;
        const auto [end, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), count);
        if (ec != std::errc() || end != w[2].data() + w[2].size() ||
            count > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max())) {
            fail(line, "bad element count '" + std::string(w[2]) + "'");
        }
        if (which == 3 && count != header.vertex_count) {
            fail(line, "element vertex_id has " + std::to_string(count) + " entries for " +
                           std::to_string(header.vertex_count) + " vertices");
        }
        (which == 0   ? header.vertex_count
         : which == 1 ? header.face_count
         : which == 2 ? header.edge_count
                      : header.id_count) = static_cast<std::size_t>(count);
        last_element = which;
        current = std::string(w[1]);
        property_count = 0;
    }

    void property(std::size_t line, std::string_view text, const std::vector<std::string_view>& w) {
        if (current.empty() || !expected_property(current, property_count, w)) {
            fail(line, "unsupported property '" + std::string(text) + "'" +
                           (current.empty() ? "" : " in element '" + current + "'") +
                           " (dtm reads the PLY layout it writes: see docs/formats.md)");
        }
        if (current == "edge" && property_count == 2) header.edge_has_kind = true;
        ++property_count;
    }

    void format(std::size_t line, std::string_view text, const std::vector<std::string_view>& w) {
        if (w.size() == 3 && w[2] == "1.0" && w[1] == "ascii") {
            header.encoding = Encoding::ascii;
        } else if (w.size() == 3 && w[2] == "1.0" && w[1] == "binary_little_endian") {
            header.encoding = Encoding::binary_little_endian;
        } else {
            fail(line, "unsupported '" + std::string(text) +
                           "' (dtm reads ascii and binary_little_endian 1.0)");
        }
    }
};

/// One header line: returns true at end_header.
bool parse_header_line(HeaderParser& parser, std::size_t line, std::string_view text) {
    const std::vector<std::string_view> w = split_words(text);
    const std::string_view keyword = w.empty() ? std::string_view() : w[0];
    if (line == 1) {
        if (text != "ply") parser.fail(1, "not a PLY file (the first line is not 'ply')");
    } else if (line == 2) {
        if (keyword != "format") parser.fail(2, "expected the 'format' line after 'ply'");
        parser.format(2, text, w);
    } else if (keyword == "comment") {
        constexpr std::string_view crs_prefix = "comment crs ";
        if (text.starts_with(crs_prefix))
            parser.header.crs_wkt = std::string(text.substr(crs_prefix.size()));
    } else if (keyword == "obj_info") {
        // informational; ignored like comments
    } else if (keyword == "element") {
        parser.element(line, w);
    } else if (keyword == "property") {
        parser.property(line, text, w);
    } else if (keyword == "end_header" && w.size() == 1) {
        parser.finish_element(line);
        return true;
    } else {
        parser.fail(line, "unexpected header line '" + std::string(text) + "'");
    }
    return false;
}

Header parse_header(const fs::path& path, std::string_view bytes) {
    HeaderParser parser{path, {}, {}, 0, -1};
    std::size_t offset = 0;
    for (std::size_t line = 1;; ++line) {
        const std::size_t newline = bytes.find('\n', offset);
        if (newline == std::string_view::npos) {
            parser.fail(line, line == 1 ? "not a PLY file (empty or no header)"
                                        : "the header has no 'end_header' line (truncated?)");
        }
        std::string_view text = bytes.substr(offset, newline - offset);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        offset = newline + 1;
        if (parse_header_line(parser, line, text)) {
            parser.header.body_offset = offset;
            parser.header.line_count = line;
            return parser.header;
        }
    }
}

// ---- binary body -------------------------------------------------------------------------------

template <class T>
T get_le(const char* in) noexcept {
    T value;
    if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(&value, in, sizeof(T));
    } else {
        char bytes[sizeof(T)];
        for (std::size_t i = 0; i < sizeof(T); ++i) bytes[i] = in[sizeof(T) - 1 - i];
        std::memcpy(&value, bytes, sizeof(T));
    }
    return value;
}

/// Reader state shared by both encodings: the TIN so far and index checks with clear messages.
struct BodyReader {
    const fs::path& path;
    const Header& header;
    Tin tin;
    std::vector<std::uint64_t> ids;  ///< the vertex_id element, if any

    [[noreturn]] void fail(std::size_t line, const std::string& what) const {
        throw InputError(path, line, 0, what);
    }

    VertexIndex vertex_index(std::int64_t value,
                             std::string_view element,
                             std::size_t which,
                             std::size_t line) const {
        if (value < 0 || static_cast<std::size_t>(value) >= header.vertex_count) {
            fail(line, std::string(element) + " " + std::to_string(which) + " refers to vertex " +
                           std::to_string(value) + " but there are " +
                           std::to_string(header.vertex_count) + " vertices");
        }
        return static_cast<VertexIndex>(value);
    }

    void add_face(std::array<std::int64_t, 3> v, std::size_t which, std::size_t line) {
        Triangle& t = tin.triangles.emplace_back();
        for (std::size_t i = 0; i < 3; ++i) t.v[i] = vertex_index(v[i], "face", which, line);
        if (t.v[0] == t.v[1] || t.v[1] == t.v[2] || t.v[0] == t.v[2]) {
            fail(line, "face " + std::to_string(which) + " repeats a vertex");
        }
    }

    void add_edge(
        std::int64_t a, std::int64_t b, unsigned kind, std::size_t which, std::size_t line) {
        if (kind >= constraint_kind_count) {
            std::string known;
            for (unsigned k = 0; k < constraint_kind_count; ++k) {
                known += (k > 0 ? ", " : "") + std::to_string(k) + " " +
                         constraint_kind_name(static_cast<ConstraintKind>(k));
            }
            fail(line, "edge " + std::to_string(which) + " has unknown kind " +
                           std::to_string(kind) + " (" + known + ")");
        }
        ConstrainedEdge& edge = tin.constraints.emplace_back();
        edge.a = vertex_index(a, "edge", which, line);
        edge.b = vertex_index(b, "edge", which, line);
        edge.kind = static_cast<ConstraintKind>(kind);
    }
};

/// Decodes @p count binary faces at @p p into @p out in parallel; false when any is not a
/// triangle of three distinct, existing vertices (the caller then reads them one by one for the
/// message, which so names the first bad face whatever the threads).
bool decode_faces(const char* p,
                  std::size_t count,
                  std::size_t vertex_count,
                  std::vector<Triangle>& out) {
    out.resize(count);
    std::atomic<bool> sound{true};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1 << 15), [&](const auto& r) {
        const auto exists = [&](std::int32_t v) {
            return v >= 0 && static_cast<std::size_t>(v) < vertex_count;
        };
        bool ok = true;
        for (std::size_t f = r.begin(); f < r.end(); ++f) {
            const char* q = p + 13 * f;
            const auto a = get_le<std::int32_t>(q + 1);
            const auto b = get_le<std::int32_t>(q + 5);
            const auto c = get_le<std::int32_t>(q + 9);
            ok = ok && *q == 3 && exists(a) && exists(b) && exists(c) && a != b && b != c && a != c;
            out[f].v = {static_cast<VertexIndex>(a), static_cast<VertexIndex>(b),
                        static_cast<VertexIndex>(c)};
        }
        if (!ok) sound.store(false, std::memory_order_relaxed);
    });
    return sound.load();
}

void read_binary_body(BodyReader& reader, std::string_view body) {
    const Header& h = reader.header;
    const std::size_t edge_size = h.edge_has_kind ? 9 : 8;
    const auto truncated = [&](std::string_view element, std::size_t done, std::size_t count) {
        reader.fail(0, "the file ends inside " + std::string(element) + " " + std::to_string(done) +
                           " of " + std::to_string(count) + " (truncated?)");
    };
    if (body.size() < h.vertex_count * 24) truncated("vertex", body.size() / 24, h.vertex_count);
    reader.tin.vertices.resize(h.vertex_count);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, h.vertex_count, 1 << 15),
                      [&](const auto& r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i) {
                              const char* q = body.data() + 24 * i;
                              reader.tin.vertices[i] = {get_le<double>(q), get_le<double>(q + 8),
                                                        get_le<double>(q + 16)};
                          }
                      });
    const char* p = body.data() + 24 * h.vertex_count;
    const char* const end = body.data() + body.size();
    if (static_cast<std::size_t>(end - p) / 13 >= h.face_count &&
        decode_faces(p, h.face_count, h.vertex_count, reader.tin.triangles)) {
        p += 13 * h.face_count;
    } else {
        reader.tin.triangles.clear();
        reader.tin.triangles.reserve(
            std::min(h.face_count, static_cast<std::size_t>(end - p) / 13));
        for (std::size_t f = 0; f < h.face_count; ++f, p += 13) {
            if (end - p < 13) truncated("face", f, h.face_count);
            if (*p != 3)
                reader.fail(0, "face " + std::to_string(f) + " has " +
                                   std::to_string(static_cast<unsigned char>(*p)) +
                                   " vertices; a TIN has triangles only");
            reader.add_face({get_le<std::int32_t>(p + 1), get_le<std::int32_t>(p + 5),
                             get_le<std::int32_t>(p + 9)},
                            f, 0);
        }
    }
    reader.tin.constraints.reserve(
        std::min(h.edge_count, static_cast<std::size_t>(end - p) / edge_size));
    for (std::size_t e = 0; e < h.edge_count; ++e, p += edge_size) {
        if (static_cast<std::size_t>(end - p) < edge_size) truncated("edge", e, h.edge_count);
        const unsigned kind = h.edge_has_kind ? static_cast<unsigned char>(p[8]) : 0U;
        reader.add_edge(get_le<std::int32_t>(p), get_le<std::int32_t>(p + 4), kind, e, 0);
    }
    if (static_cast<std::size_t>(end - p) / 8 < h.id_count) {
        truncated("vertex_id", static_cast<std::size_t>(end - p) / 8, h.id_count);
    }
    reader.ids.resize(h.id_count);
    for (std::size_t i = 0; i < h.id_count; ++i, p += 8) {
        reader.ids[i] =
            std::uint64_t{get_le<std::uint32_t>(p)} << 32 | get_le<std::uint32_t>(p + 4);
    }
    if (p != end) {
        reader.fail(0, std::to_string(end - p) + " unexpected bytes after the last element");
    }
}

// ---- ASCII body --------------------------------------------------------------------------------

/// Walks the body line by line, keeping the 1-based line number for messages.
struct LineCursor {
    std::string_view rest;
    std::size_t line;

    bool next(std::string_view& text) {
        while (!rest.empty()) {
            const std::size_t newline = rest.find('\n');
            text = rest.substr(0, newline);
            rest =
                newline == std::string_view::npos ? std::string_view() : rest.substr(newline + 1);
            ++line;
            if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
            if (text.find_first_not_of(" \t") != std::string_view::npos) return true;
        }
        return false;
    }
};

template <class T>
void parse_numbers(BodyReader& reader,
                   std::string_view text,
                   std::size_t line,
                   T* out,
                   std::size_t count,
                   std::size_t optional_last = 0) {
    const std::vector<std::string_view> words = split_words(text);
    if (words.size() > count || words.size() + optional_last < count) {
        reader.fail(line, "expected " + std::to_string(count) + " numbers, found " +
                              std::to_string(words.size()));
    }
    for (std::size_t i = 0; i < words.size(); ++i) {
        const char* const last = words[i].data() + words[i].size();
        const auto [end, ec] = std::from_chars(words[i].data(), last, out[i]);
        if (ec != std::errc() || end != last) {
            std::string what = "'";
            what += words[i];
            reader.fail(line, what + "' is not a valid number here");
        }
    }
}

void read_ascii_body(BodyReader& reader, std::string_view body) {
    const Header& h = reader.header;
    LineCursor cursor{body, h.line_count};
    std::string_view text;
    const auto need = [&](std::string_view element, std::size_t done, std::size_t count) {
        if (!cursor.next(text)) {
            reader.fail(cursor.line, "the file ends before " + std::string(element) + " " +
                                         std::to_string(done) + " of " + std::to_string(count) +
                                         " (truncated?)");
        }
    };
    reader.tin.vertices.reserve(std::min(h.vertex_count, body.size() / 6));
    for (std::size_t i = 0; i < h.vertex_count; ++i) {
        need("vertex", i, h.vertex_count);
        double xyz[3];
        parse_numbers(reader, text, cursor.line, xyz, 3);
        reader.tin.vertices.push_back({xyz[0], xyz[1], xyz[2]});
    }
    for (std::size_t f = 0; f < h.face_count; ++f) {
        need("face", f, h.face_count);
        std::int64_t values[4];
        parse_numbers(reader, text, cursor.line, values, 4);
        if (values[0] != 3)
            reader.fail(cursor.line, "face " + std::to_string(f) + " is not a triangle");
        reader.add_face({values[1], values[2], values[3]}, f, cursor.line);
    }
    for (std::size_t e = 0; e < h.edge_count; ++e) {
        need("edge", e, h.edge_count);
        std::int64_t values[3] = {0, 0, 0};
        parse_numbers(reader, text, cursor.line, values, h.edge_has_kind ? 3 : 2);
        if (values[2] < 0) reader.fail(cursor.line, "negative edge kind");
        reader.add_edge(values[0], values[1],
                        static_cast<unsigned>(std::min<std::int64_t>(values[2], 255)), e,
                        cursor.line);
    }
    reader.ids.reserve(h.id_count);
    for (std::size_t i = 0; i < h.id_count; ++i) {
        need("vertex_id", i, h.id_count);
        std::uint32_t values[2];
        parse_numbers(reader, text, cursor.line, values, 2);
        reader.ids.push_back(std::uint64_t{values[0]} << 32 | values[1]);
    }
    if (cursor.next(text)) reader.fail(cursor.line, "unexpected data after the last element");
}

}  // namespace

LoadedTin read_tin_ply(const fs::path& path) {
    const detail::FileBytes file(path);
    const std::string_view bytes = file.view();
    const Header header = parse_header(path, bytes);
    BodyReader reader{path, header, {}, {}};
    const std::string_view body = bytes.substr(header.body_offset);
    if (header.encoding == Encoding::ascii) {
        read_ascii_body(reader, body);
    } else {
        read_binary_body(reader, body);
    }
    try {
        link_neighbours(reader.tin);
        detail::check_tin_from_file(reader.tin);
    } catch (const InputError& e) {
        throw InputError(path, 0, 0, e.what());
    }
    return {std::move(reader.tin), header.crs_wkt, std::move(reader.ids)};
}

ReadResult read_ply(const InputFile& file, const ReadOptions&, const Progress& progress) {
    return detail::read_tin_input(file, progress, "dtm PLY TIN", &read_tin_ply);
}

}  // namespace dtm::io
