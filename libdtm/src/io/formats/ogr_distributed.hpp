// SPDX-License-Identifier: MIT
/// @file
/// @brief Survey points of an OGR source (shapefile, GeoPackage, FlatGeobuf, GeoJSON, ...) read
/// by all ranks at once, each its range of features (R-D2 of docs/distributed.md).
#pragma once

#include <string>

#include "dtm/dist/comm.hpp"
#include "dtm/io/reader.hpp"
#include "io/formats/csv/csv_distributed.hpp"

namespace dtm::io {

/// Collective. Every rank counts the source's features (ogr_range.hpp: layers in order, after the
/// `where` filter), reads the equal share [r N / P, (r + 1) N / P) as read_ogr does and finds the
/// file's CRS as load_inputs does (@p crs_wkt; empty when the file has none). The points, in
/// order over the ranks, are read_ogr's. The first failing feature of the file is reported on
/// every rank with read_ogr's message.
/// @throws InputError on every rank; UsageError on every rank when the source holds lines or
/// polygons (breaklines in the points input are not taken by a distributed run yet).
DistributedPoints read_ogr_points_distributed(dist::Comm& comm,
                                              const InputFile& file,
                                              const ReadOptions& options,
                                              std::string& crs_wkt);

}  // namespace dtm::io
