// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: the CRS a reader found, identified (io::identify_crs) from the file's .prj
/// text when it has one (what ArcGIS wrote, before GDAL's own interpretation), else from the
/// reader's WKT; shared by load_inputs and the distributed readers.
#pragma once

#include "dtm/io/reader.hpp"

namespace dtm::io::detail {

/// Replaces result.crs_wkt by its identified WKT and sets result.summary.crs_note.
void identify_file_crs(const InputFile& file, ReadResult& result);

}  // namespace dtm::io::detail
