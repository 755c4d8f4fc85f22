// SPDX-License-Identifier: MIT
// Content sniffing: magic numbers at the start of the file (LAS "LASF", PLY "ply", ZIP "PK\3\4",
// PDF "%PDF-", gzip 1F 8B, ...), the root element of XML, the group-code pairs of ASCII DXF, the
// keywords of an ESRI ASCII grid; then text: a Compass plot (.plt: lines "M|D x y z Sstation")
// is told from HP-GL (two-letter mnemonics), and lines of numbers are a point list. Data with NUL
// bytes or many control characters and no signature is binary. Formats: Compass "Plot File
// Format" (Fountainware), PKWARE APPNOTE, RFC 1952 (gzip), ISO 32000 (PDF), ASPRS LAS 1.4.
#include "dtm/io/sniff.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <vector>

#include "dtm/io/formats/raster_dem.hpp"
#include "io/formats/xml/xml_sax.hpp"

namespace dtm::io {
namespace {

using Kind = ContentGuess::Kind;
using namespace std::string_view_literals;

struct Magic {
    std::string_view bytes;
    Kind kind;
    std::string_view reader;
    std::string_view what;
};

constexpr std::array<Magic, 22> magics{{
    {"LASF"sv, Kind::format, "las", "a LAS point cloud"},
    {"ply\n"sv, Kind::format, "ply", "a PLY file"},
    {"ply\r\n"sv, Kind::format, "ply", "a PLY file"},
    {"AutoCAD Binary DXF"sv, Kind::format, "dxf", "a binary DXF drawing"},
    {"SQLite format 3"sv, Kind::format, "ogr", "an SQLite/GeoPackage database"},
    {"II*\0"sv, Kind::format, "raster", "a TIFF image"},
    {"MM\0*"sv, Kind::format, "raster", "a TIFF image"},
    {"II+\0"sv, Kind::format, "raster", "a BigTIFF image"},
    {"PK\x03\x04"sv, Kind::foreign, {}, "a ZIP archive (unpack it first)"},
    {"PK\x05\x06"sv, Kind::foreign, {}, "an empty ZIP archive"},
    {"%PDF-"sv, Kind::foreign, {}, "a PDF document"},
    {"\x1f\x8b"sv, Kind::foreign, {}, "gzip-compressed data (decompress it first, e.g. gunzip)"},
    {"BZh"sv, Kind::foreign, {}, "bzip2-compressed data (decompress it first, e.g. bunzip2)"},
    {"\xFD"
     "7zXZ"sv,
     Kind::foreign,
     {},
     "xz-compressed data (decompress it first, e.g. unxz)"},
    {"7z\xBC\xAF\x27\x1C"sv, Kind::foreign, {}, "a 7-Zip archive (unpack it first)"},
    {"Rar!"sv, Kind::foreign, {}, "a RAR archive (unpack it first)"},
    {"\x89PNG"sv, Kind::foreign, {}, "a PNG image"},
    {"\xFF\xD8\xFF"sv, Kind::foreign, {}, "a JPEG image"},
    {"%!PS"sv, Kind::foreign, {}, "a PostScript document"},
    {"\x7f"
     "ELF"sv,
     Kind::foreign,
     {},
     "an executable program (ELF)"},
    {"\xD0\xCF\x11\xE0"sv, Kind::foreign, {}, "a Microsoft Office document (OLE)"},
    {"{\\rtf"sv, Kind::foreign, {}, "an RTF document"},
}};

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

/// Up to @p max non-blank lines of @p head (the last one dropped if cut by the head's end).
std::vector<std::string_view> lines(std::string_view head, std::size_t max) {
    std::vector<std::string_view> out;
    std::size_t at = 0;
    while (at < head.size() && out.size() < max) {
        const std::size_t end = head.find('\n', at);
        if (end == std::string_view::npos) {
            if (head.size() < (std::size_t{64} << 10)) out.push_back(trim(head.substr(at)));
            break;
        }
        const std::string_view line = trim(head.substr(at, end - at));
        if (!line.empty()) out.push_back(line);
        at = end + 1;
    }
    if (!out.empty() && out.back().empty()) out.pop_back();
    return out;
}

std::vector<std::string_view> tokens(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t at = 0;
    const auto separator = [](char c) {
        return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '|';
    };
    while (at < line.size()) {
        while (at < line.size() && separator(line[at])) ++at;
        std::size_t end = at;
        while (end < line.size() && !separator(line[end])) ++end;
        if (end > at) out.push_back(line.substr(at, end - at));
        at = end;
    }
    return out;
}

bool is_number(std::string_view s) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    double v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return !s.empty() && r.ec == std::errc{} && r.ptr == s.data() + s.size();
}

std::size_t numbers_in(std::string_view line) {
    std::size_t n = 0;
    for (const std::string_view t : tokens(line)) n += is_number(t) ? 1 : 0;
    return n;
}

/// Compass plot lines: "M|D  x y z  S<station> ..." (move/draw), "Z" bounds, "N" survey.
bool is_compass_plot(const std::vector<std::string_view>& text) {
    std::size_t shots = 0;
    for (const std::string_view line : text) {
        if (line.size() < 2 || !(line[0] == 'M' || line[0] == 'D') ||
            !(line[1] == ' ' || line[1] == '\t')) {
            continue;
        }
        const auto t = tokens(line.substr(1));
        if (t.size() >= 4 && is_number(t[0]) && is_number(t[1]) && is_number(t[2]) &&
            t[3].size() > 1 && t[3][0] == 'S') {
            ++shots;
        }
    }
    return shots > 0;
}

/// HP-GL: an escape prefix (PCL, RS-232), or two-letter mnemonics from the start (after
/// control bytes) with pen moves (PU, PD, PA) in the head.
bool is_hpgl(std::string_view head) {
    if (head.starts_with("\x1b")) return true;
    std::size_t at = 0;
    while (at < head.size() && static_cast<unsigned char>(head[at]) <= ' ') ++at;
    const auto upper = [&](std::size_t i) {
        return i < head.size() && std::isupper(static_cast<unsigned char>(head[i]));
    };
    if (!upper(at) || !upper(at + 1)) return false;
    if (at + 2 < head.size() && std::islower(static_cast<unsigned char>(head[at + 2]))) {
        return false;
    }
    return head.find("PU") != std::string_view::npos || head.find("PD") != std::string_view::npos ||
           head.find("PA") != std::string_view::npos;
}

bool is_point_text(const std::vector<std::string_view>& text) {
    std::size_t numeric = 0;
    std::size_t considered = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i].starts_with('#')) continue;
        if (i == 0 && numbers_in(text[i]) < 2) continue;  // a header line
        ++considered;
        if (numbers_in(text[i]) >= 2) ++numeric;
    }
    return numeric >= 1 && numeric * 2 >= considered;
}

bool is_dxf(const std::vector<std::string_view>& text) {
    return text.size() >= 2 && text[0] == "0" && (text[1] == "SECTION" || text[1] == "SECTION\r");
}

bool is_binary(std::string_view head) {
    std::size_t control = 0;
    for (const char ch : head) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == 0) return true;
        if (c < 32 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != 0x1a && c != 0x1b) {
            ++control;
        }
    }
    return control * 20 > head.size();
}

ContentGuess xml_guess(std::string_view root) {
    if (root == "LandXML") return {Kind::format, "landxml", "a LandXML document"};
    if (root == "JVFDTM") return {Kind::format, "jvf", "a JVF DTM document"};
    if (root == "kml" || root == "FeatureCollection" || root == "gpx") {
        return {Kind::format, "ogr", "a " + std::string(root) + " document"};
    }
    return {Kind::foreign,
            {},
            "an XML document with root element <" + std::string(root) +
                "> (neither LandXML nor JVF DTM)"};
}

}  // namespace

ContentGuess guess_content(std::string_view head) {
    if (head.empty()) return {};
    for (const Magic& m : magics) {
        if (head.starts_with(m.bytes)) return {m.kind, m.reader, std::string(m.what)};
    }
    const std::string_view start = trim(head.substr(0, 256));
    if (start.starts_with("<")) {
        const std::string_view root = xml::root_element(head);
        if (!root.empty()) return xml_guess(root);
    }
    if (start.starts_with("{") && start.find("\"dtm-tin-tiles\"") != std::string_view::npos) {
        return {Kind::format, "tin-tiles", "a dtm tiled TIN manifest"};
    }
    if (start.starts_with("{") && head.find("\"type\"") != std::string_view::npos) {
        return {Kind::format, "ogr", "a GeoJSON document"};
    }
    if (head.starts_with("\x1b")) return {Kind::text, "hpgl", "an HP-GL plot (PCL escape)"};
    if (is_binary(head)) return {Kind::binary, {}, "binary data of an unknown format"};
    const auto text = lines(head, 40);
    if (is_dxf(text)) return {Kind::format, "dxf", "a DXF drawing"};
    if (is_ascii_grid(FileHead{{}, {}, head})) {
        return {Kind::format, "ascii-grid", "an ESRI ASCII grid"};
    }
    if (is_compass_plot(text)) {
        return {Kind::foreign,
                {},
                "a Compass cave survey plot (move/draw lines with station names), not HP-GL"};
    }
    if (is_hpgl(head)) return {Kind::text, "hpgl", "an HP-GL plot"};
    if (is_point_text(text)) return {Kind::text, "csv", "a text point list"};
    return {};
}

}  // namespace dtm::io
