// SPDX-License-Identifier: MIT
// The explicit reader table: every input format dtm reads, visible in one place (no static
// self-registration, so it is safe in a static library). A .ply positional input is a dtm TIN
// and is read by io::read_tin_ply in inputs.cpp, not through this table.
#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/csv.hpp"
#include "dtm/io/formats/hpgl.hpp"
#include "dtm/io/formats/ogr.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {
namespace {

constexpr std::array<std::string_view, 5> csv_ext{"csv", "txt", "xyz", "pts", "asc"};
constexpr std::array<std::string_view, 14> ogr_ext{"shp",  "gpkg", "geojson", "json", "dxf",
                                                   "kml",  "gml",  "sqlite",  "fgb",  "gpx",
                                                   "tab",  "mif",  "vfk",     "gdb"};
constexpr std::array<std::string_view, 5> hpgl_ext{"hpgl", "plt", "hgl", "hpg", "prn"};
constexpr std::array<ReaderInfo, 3> reader_table{{
    {"csv", "Delimited text points or shapeid,x,y[,z] polylines", csv_ext, &read_csv},
    {"hpgl", "HP-GL/HP-GL2 plotter plans: spot heights, breaklines by pen", hpgl_ext,
     &read_hpgl},
    {"ogr", "Any OGR vector source: points, lines, polygons", ogr_ext, &read_ogr},
}};

}  // namespace

std::span<const ReaderInfo> readers() { return reader_table; }

const ReaderInfo& find_reader(const std::filesystem::path& file)
{
    std::string ext = file.extension().string();
    if (!ext.empty()) ext.erase(0, 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const ReaderInfo& r : reader_table) {
        if (std::find(r.extensions.begin(), r.extensions.end(), ext) != r.extensions.end()) return r;
    }
    std::string known = "ply";
    for (const ReaderInfo& r : reader_table) {
        for (std::string_view e : r.extensions) known += ", " + std::string(e);
    }
    throw InputError(file, 0, 0,
                     "expected a known input extension (" + known + "), found '" +
                         file.extension().string() + "'");
}

}  // namespace dtm::io
