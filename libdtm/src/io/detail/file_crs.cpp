// SPDX-License-Identifier: MIT
// The CRS of an input file as every reader's caller settles it (file_crs.hpp).
#include "io/detail/file_crs.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"

namespace dtm::io::detail {

/// The CRS a reader found, identified (io::identify_crs) from the file's .prj text when it has
/// one (what ArcGIS wrote, before GDAL's own interpretation), else from the reader's WKT.
void identify_file_crs(const InputFile& file, ReadResult& result) {
    if (result.crs_wkt.empty()) return;
    std::filesystem::path prj = file.path;
    prj.replace_extension(".prj");
    std::string source = result.crs_wkt;
    std::error_code ec;
    if (prj != file.path && std::filesystem::is_regular_file(prj, ec)) {
        std::ifstream in(prj, std::ios::binary);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!text.empty()) source = std::move(text);
    }
    CrsIdentity id;
    try {
        id = identify_crs(source);
    } catch (const InputError&) {
        id = identify_crs(result.crs_wkt);  // a .prj GDAL cannot read: the reader's CRS
    }
    result.crs_wkt = std::move(id.wkt);
    result.summary.crs_note = std::move(id.note);
}

}  // namespace dtm::io::detail
