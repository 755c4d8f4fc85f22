// SPDX-License-Identifier: MIT
// The explicit reader table: every input format dtm reads, visible in one place (no static
// self-registration, so it is safe in a static library). A file goes to the first row whose
// extensions hold its own and whose sniff (if any) accepts its first bytes, so a row that looks
// at the content comes before the plain row of the same extensions: a text file with a WKT
// column goes to OGR before the text reader sees it. A new format is one row (and its
// formats/<name>.hpp/.cpp); a reader may return a TIN (ReadResult::tin) as well as points and
// lines. A file whose extension no row takes goes to the row its content suggests (sniff.hpp),
// and content that contradicts the extension is an input error naming what it appears to be.
#include "dtm/io/reader.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/formats/csv.hpp"
#include "dtm/io/formats/dxf.hpp"
#include "dtm/io/formats/hpgl.hpp"
#include "dtm/io/formats/jvf.hpp"
#include "dtm/io/formats/landxml.hpp"
#include "dtm/io/formats/las.hpp"
#include "dtm/io/formats/ogr.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/formats/raster_dem.hpp"
#include "dtm/io/formats/tin_tiles.hpp"
#include "dtm/io/sniff.hpp"

namespace dtm::io {
namespace {

bool text_has_geometry_column(const FileHead& head) { return csv_has_geometry_column(head.bytes); }

constexpr std::array<std::string_view, 1> ply_ext{"ply"};
constexpr std::array<std::string_view, 1> tiles_ext{"json"};
constexpr std::array<std::string_view, 5> csv_ext{"csv", "txt", "xyz", "pts", "asc"};
constexpr std::array<std::string_view, 5> hpgl_ext{"hpgl", "plt", "hgl", "hpg", "prn"};
constexpr std::array<std::string_view, 1> dxf_ext{"dxf"};
constexpr std::array<std::string_view, 13> ogr_ext{"shp", "gpkg",   "geojson", "json", "kml",
                                                   "gml", "sqlite", "fgb",     "gpx",  "tab",
                                                   "mif", "vfk",    "gdb"};
constexpr std::array<std::string_view, 1> xml_ext{"xml"};
constexpr std::array<std::string_view, 1> grid_asc_ext{"asc"};
constexpr std::array<std::string_view, 8> raster_ext{"tif", "tiff", "vrt", "img",
                                                     "dem", "bil",  "hgt", "nc"};
constexpr std::array<std::string_view, 2> las_ext{"las", "laz"};
constexpr std::array<ReaderInfo, 12> reader_table{{
    {"ply", "dtm PLY TIN (the surface itself: vertices, triangles, constrained edges, CRS)",
     ply_ext, nullptr, &read_ply},
    {"tin-tiles", "dtm tiled TIN: a JSON manifest and one PLY per tile (a distributed run)",
     tiles_ext, &is_tin_manifest, &read_tin_tiles_input},
    {"ascii-grid", "ESRI ASCII grid DEM (.asc starting with ncols ...): cells as points",
     grid_asc_ext, &is_ascii_grid, &read_raster_dem},
    {"csv-wkt", "Delimited text with a WKT or geometry column, read by OGR", csv_ext,
     &text_has_geometry_column, &read_ogr_text},
    {"csv", "Delimited text points or shapeid,x,y[,z] polylines", csv_ext, nullptr, &read_csv},
    {"jvf", "JVF DTM 1.4 (Czech technical map, root JVFDTM): points and terrain edges", xml_ext,
     &is_jvf, &read_jvf},
    {"landxml", "LandXML 1.0-1.2 surface (root LandXML): its TIN, or points and lines", xml_ext,
     &is_landxml, &read_landxml},
    {"hpgl", "HP-GL/HP-GL2 plotter plans: spot heights, breaklines by pen", hpgl_ext, nullptr,
     &read_hpgl},
    {"dxf", "DXF: 3DFACEs as a TIN, else points and lines through OGR", dxf_ext, nullptr,
     &read_dxf},
    {"raster", "Raster DEM read by GDAL (GeoTIFF, ...): cells as points, NoData skipped",
     raster_ext, nullptr, &read_raster_dem},
    {"ogr", "Any OGR vector source: points, lines, polygons", ogr_ext, nullptr, &read_ogr},
    {"las", "LAS 1.0-1.4 point cloud (uncompressed; LAZ refused with the reason)", las_ext, nullptr,
     &read_las},
}};

/// Bytes a sniff may look at.
constexpr std::size_t head_size = std::size_t{64} << 10;

bool takes_extension(const ReaderInfo& r, const std::string& ext) {
    return r.extensions.empty() ||
           std::find(r.extensions.begin(), r.extensions.end(), ext) != r.extensions.end();
}

const ReaderInfo* by_extension(const FileHead& head) {
    for (const ReaderInfo& r : reader_table) {
        if (takes_extension(r, head.extension) && (r.sniff == nullptr || r.sniff(head))) return &r;
    }
    return nullptr;
}

const ReaderInfo& by_name(std::string_view name) {
    for (const ReaderInfo& r : reader_table) {
        if (r.name == name) return r;
    }
    throw Error("no reader named " + std::string(name));
}

/// A file whose extension chose @p row but whose content is another format (or binary data for
/// a text reader): an input error naming what it appears to be. GDAL's rows (ogr, raster) open
/// their files by content and name their own problems; HP-GL may hold binary PCL.
void check_content(const ReaderInfo& row, const ContentGuess& guess, const FileHead& head) {
    using Kind = ContentGuess::Kind;
    if (row.name == "ogr" || row.name == "raster") return;
    const bool other_format = guess.kind == Kind::format && guess.reader != row.name;
    const bool binary = guess.kind == Kind::binary && row.name != "hpgl";
    if (guess.kind != Kind::foreign && !other_format && !binary) return;
    throw InputError(head.path, 0, 0,
                     "this file appears to be " + guess.what + ", not " +
                         std::string(row.description) + " as its extension '." + head.extension +
                         "' says");
}

}  // namespace

std::span<const ReaderInfo> readers() { return reader_table; }

const ReaderInfo& find_reader(const FileHead& head) {
    const ContentGuess guess = guess_content(head.bytes);
    if (const ReaderInfo* row = by_extension(head)) {
        check_content(*row, guess, head);
        return *row;
    }
    using Kind = ContentGuess::Kind;
    if (guess.kind == Kind::text || guess.kind == Kind::format) return by_name(guess.reader);
    if (guess.kind != Kind::unknown) {
        throw InputError(head.path, 0, 0,
                         "this file appears to be " + guess.what + ", which dtm does not read");
    }
    std::vector<std::string_view> known;
    for (const ReaderInfo& r : reader_table) {
        for (std::string_view e : r.extensions) {
            if (std::find(known.begin(), known.end(), e) == known.end()) known.push_back(e);
        }
    }
    std::string list;
    for (std::string_view e : known) list += (list.empty() ? "" : ", ") + std::string(e);
    throw InputError(head.path, 0, 0,
                     "expected a known input extension (" + list +
                         ") or content dtm recognises "
                         "(text points, LAS, PLY, DXF, LandXML, JVF DTM, HP-GL), found '" +
                         head.path.extension().string() + "'");
}

const ReaderInfo& find_reader(const std::filesystem::path& file) {
    FileHead head{file, lower_extension(file), {}};
    std::string bytes;  // an unreadable file reads as empty: its reader then names the problem
    std::error_code ec;
    if (std::filesystem::is_regular_file(file, ec)) {
        std::ifstream in(file, std::ios::binary);
        bytes.resize(head_size);
        in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        bytes.resize(static_cast<std::size_t>(in.gcount()));
        head.bytes = bytes;
    }
    return find_reader(head);
}

}  // namespace dtm::io
