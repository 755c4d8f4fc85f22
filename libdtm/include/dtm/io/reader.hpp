// SPDX-License-Identifier: MIT
/// @file
/// @brief The one small reader interface: each input format is a function filling a ReadResult,
/// found in the explicit reader table of src/io/reader.cpp (no static self-registration) by the
/// file's extension and, where a format asks for it, a look at the file's first bytes.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/formats/hpgl_options.hpp"

namespace dtm::io {

/// Which role an input file plays.
enum class InputRole { points, breaklines, soft_breaklines, boundary, holes };

struct InputFile {
    std::filesystem::path path;
    InputRole role = InputRole::points;
};

/// What the readers take; each format reads the options it needs.
struct ReadOptions {
    bool skip_bad_lines =
        false;  ///< count malformed text lines (and HP-GL data) instead of failing
    /// Names of the text columns in order ("id,y,x,z,code"; "-" skips a column). Empty: map by
    /// header names, or guess (x,y,z) when there is no header.
    std::string columns;
    std::string layer;    ///< OGR layer to read; empty = every layer
    std::string where;    ///< OGR attribute filter (SQL WHERE clause)
    std::string z_field;  ///< OGR attribute holding the height (points, contours)
    HpglOptions hpgl;     ///< the HP-GL plan reader's
    /// Surface files (LandXML, DXF 3DFACE): their points and breaklines instead of their TIN.
    bool retriangulate = false;
    std::string surface;  ///< LandXML: the surface of this name; empty = the first
};

/// What one input file held (the fields of `dtm info`).
struct InputSummary {
    std::filesystem::path path;
    std::string format;
    std::string crs;  ///< name or EPSG code as found, empty if none
    /// How the CRS was identified when the file gave no EPSG code (io::identify_crs), e.g.
    /// "EPSG:5514 identified from ESRI WKT ... (GDAL match confidence 90 %)"; empty otherwise.
    std::string crs_note;
    std::size_t points = 0;
    std::size_t triangles = 0;  ///< of a TIN input (kept as given), else 0
    std::size_t breaklines = 0;
    std::size_t breakline_vertices = 0;
    std::size_t boundaries = 0;
    std::size_t holes = 0;
    std::array<double, 4> bbox{};     ///< xmin, ymin, xmax, ymax
    std::array<double, 2> z_range{};  ///< zmin, zmax
    std::size_t duplicates = 0;
    std::size_t skipped_lines = 0;
    std::vector<std::string> warnings;
};

/// Identifiers and codes of survey points, parallel to TerrainInput::points (empty strings
/// where a reader had none; both vectors empty when no input carried any).
struct PointLabels {
    std::vector<std::string> ids;
    std::vector<std::string> codes;
};

/// What one reader produced from one file, before CRS handling and merging.
struct ReadResult {
    TerrainInput terrain;
    std::string crs_wkt;   ///< CRS found in the file (.prj, GeoPackage, ...); empty if none
    InputSummary summary;  ///< filled by the reader (counts, warnings, skipped lines)
    PointLabels labels;    ///< point ids/codes parallel to terrain.points, or empty
    /// A TIN the file holds (dtm PLY; LandXML surfaces, DXF 3DFACE ...): used as the surface
    /// as it is. Its vertices are also in terrain.points (for summaries and CRS handling).
    std::optional<Tin> tin;
};

/// The start of a file, for readers that decide by content (up to 64 KiB; shorter files whole).
struct FileHead {
    std::filesystem::path path;
    std::string extension;  ///< lower case, without the dot
    std::string_view bytes;
};

using ReadFn = ReadResult (*)(const InputFile& file,
                              const ReadOptions& options,
                              const Progress& progress);
/// True if the reader takes a file that starts like @p head.
using SniffFn = bool (*)(const FileHead& head);

/// One row of the reader table. A file goes to the first row whose extensions hold its extension
/// (every extension when the list is empty) and whose sniff, if it has one, accepts its start:
/// content-sniffing rows come before the plain rows of the same extensions.
struct ReaderInfo {
    std::string_view name;  ///< "ply", "csv", "hpgl", "ogr", ...
    std::string_view description;
    std::span<const std::string_view> extensions;  ///< lower case, no dot
    SniffFn sniff;                                 ///< nullptr: the extension decides
    ReadFn read;
};

/// Every reader, in the order they are tried.
[[nodiscard]] std::span<const ReaderInfo> readers();
/// The reader of @p file (whose first bytes are read when a candidate sniffs).
/// @throws InputError if none takes it (the message lists the known extensions).
[[nodiscard]] const ReaderInfo& find_reader(const std::filesystem::path& file);
/// The reader of a file that starts like @p head (no file system access).
/// @throws InputError as find_reader().
[[nodiscard]] const ReaderInfo& find_reader(const FileHead& head);

}  // namespace dtm::io
