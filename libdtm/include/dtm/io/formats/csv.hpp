// SPDX-License-Identifier: MIT
/// @file
/// @brief Delimited text inputs (CSV, TXT, XYZ, PTS): survey point lists and polyline lists.
/// The layout (delimiter, decimal comma, header, point-count line, column roles) is detected, or
/// given with ReadOptions::columns. See docs/formats.md "Inputs".
#pragma once

#include <string_view>

#include "dtm/core/progress.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {

/// Reads one delimited text file. Points for InputRole::points; for the line roles, rows are
/// grouped into polylines by a line-id column (shapeid, id, line, line_id), consecutive rows with
/// the same id forming one line (no id column: the whole file, or blank-line separated blocks, is
/// one line each); for InputRole::holes without a line-id column the rows are hole seed points.
/// (A text file with a WKT or geometry column is read by OGR: the reader table sends it to
/// read_ogr_text, by csv_has_geometry_column.)
/// @throws InputError "file:line:column: expected ..., found '...'" unless
///         options.skip_bad_lines; Cancelled.
[[nodiscard]] ReadResult read_csv(const InputFile& file,
                                  const ReadOptions& options,
                                  const Progress& progress = {});

/// Same as read_csv() on text already in memory (@p file names it in messages). Used by the
/// fuzz target and the tests; never touches the file system.
[[nodiscard]] ReadResult parse_csv_text(std::string_view text,
                                        const InputFile& file,
                                        const ReadOptions& options,
                                        const Progress& progress = {});

/// True if the header of @p text names a geometry column (WKT, geometry, the_geom, geom).
[[nodiscard]] bool csv_has_geometry_column(std::string_view text);

}  // namespace dtm::io
