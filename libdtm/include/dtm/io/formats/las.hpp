// SPDX-License-Identifier: MIT
/// @file
/// @brief LAS 1.0-1.4 point clouds read by dtm itself (the public ASPRS layout, uncompressed,
/// point data record formats 0-10; docs/formats.md "LAS point clouds"): scale and offset applied,
/// the CRS from the OGC WKT or GeoTIFF-key record, withheld points dropped, the
/// ReadOptions::classes filter and ReadOptions::thin thinning, and every record counted
/// (InputSummary::cloud). LAZ is refused with the reason. Source: src/io/formats/las/.
#pragma once

#include <string_view>

#include "dtm/core/progress.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {

/// The reader table's entry. @throws InputError naming the file and the byte offset of what is
/// wrong (a LAZ file: why it is not read and how to decompress it); OptionError for a bad
/// `classes` or `thin`.
[[nodiscard]] ReadResult read_las(const InputFile& file,
                                  const ReadOptions& options,
                                  const Progress& progress = {});

/// The same on bytes already in memory (@p name is the file named in errors).
[[nodiscard]] ReadResult read_las_bytes(std::string_view bytes,
                                        const InputFile& file,
                                        const ReadOptions& options,
                                        const Progress& progress = {});

/// True for a file starting with the LAS signature "LASF".
[[nodiscard]] bool is_las(const FileHead& head);

}  // namespace dtm::io
