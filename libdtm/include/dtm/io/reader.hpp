// SPDX-License-Identifier: MIT
/// @file
/// @brief The one small reader interface: each format is a function filling a ReadResult; the
/// explicit list of formats is in src/io/reader.cpp (no static self-registration).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/io/inputs.hpp"

namespace dtm::io {

/// What one reader produced from one file, before CRS handling and merging.
struct ReadResult {
    TerrainInput terrain;
    std::string crs_wkt;   ///< CRS found in the file (.prj, GeoPackage, ...); empty if none
    InputSummary summary;  ///< filled by the reader (counts, warnings, skipped lines)
    PointLabels labels;    ///< point ids/codes parallel to terrain.points, or empty
};

using ReadFn = ReadResult (*)(const InputFile& file, const LoadOptions& options,
                              const Progress& progress);

struct ReaderInfo {
    std::string_view name;                         ///< "csv", "hpgl", "ogr", ...
    std::string_view description;
    std::span<const std::string_view> extensions;  ///< lower case, no dot
    ReadFn read;
};

/// Every reader, in the order they are tried.
[[nodiscard]] std::span<const ReaderInfo> readers();
/// @throws InputError if no reader matches (the message lists the known extensions).
[[nodiscard]] const ReaderInfo& find_reader(const std::filesystem::path& file);

}  // namespace dtm::io
