// SPDX-License-Identifier: MIT
/// @file
/// @brief Any OGR vector source (shapefile, GeoPackage, GeoJSON, DXF, GDAL CSV with a WKT
/// column, ...) as terrain input. See docs/formats.md "Inputs" for what each geometry becomes.
#pragma once

#include "dtm/core/progress.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {

/// Reads the layers of one OGR source (ReadOptions::layer selects one, ::where filters features,
/// ::z_field gives heights). By role:
/// - points (positional input): points and multipoints are points; lines and polygon rings are
///   hard breaklines (a mixed DXF layer gives both);
/// - breaklines / soft_breaklines: lines and polygon rings are lines;
/// - boundary: a polygon's outer ring is a boundary, its inner rings are holes; closed lines are
///   boundaries;
/// - holes: polygon outer rings and closed lines are holes, points are hole seeds.
/// Vertices without a height get NaN z (the loader fills them or reports them).
/// @throws InputError naming the file (and feature) on unreadable data, a missing layer or
///         field, a bad filter, or points without heights; Cancelled.
[[nodiscard]] ReadResult read_ogr(const InputFile& file,
                                  const ReadOptions& options,
                                  const Progress& progress = {});

/// A delimited text file with a WKT or geometry column, read by OGR's CSV driver (as read_ogr;
/// the summary's format says so).
[[nodiscard]] ReadResult read_ogr_text(const InputFile& file,
                                       const ReadOptions& options,
                                       const Progress& progress = {});

}  // namespace dtm::io
