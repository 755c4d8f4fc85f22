// SPDX-License-Identifier: MIT
/// @file
/// @brief Survey points of a text file read by all ranks at once, each its byte range (R-D2 of
/// docs/distributed.md).
#pragma once

#include <cstdint>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/dist/comm.hpp"
#include "dtm/dist/duplicates.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {

struct DistributedPoints {
    std::vector<dist::InputPoint> points;  ///< this rank's, in file order
    std::uint64_t first_input = 0;         ///< global index of the first of them
    std::uint64_t total = 0;               ///< points over all ranks
    std::uint64_t skipped_lines = 0;       ///< over all ranks (with skip_bad_lines)
    /// The CRS the file gives as read_csv and load_inputs take it: EPSG:4326 for lat/lon columns
    /// (or the .prj beside the file); empty for planar columns.
    std::string crs_wkt;
};

/// Collective, for the distributed readers: the InputError that comes first in the file over all
/// ranks (@p mine with its @p order, INT64_MAX for none; ties to the lowest rank), rethrown on
/// every rank with its file, line, column and message; returns when no rank has one.
void elect_input_error(dist::Comm& comm,
                       const InputFile& file,
                       const InputError* mine,
                       std::int64_t order);

/// The bytes of a rank's range parsed at a time (whole lines; tests lower it).
extern std::size_t distributed_block_bytes;

/// Collective. Every rank detects the layout from the file's head (the same on every rank),
/// takes the equal share [r S / P, (r + 1) S / P) of the data bytes moved to the next line
/// starts, numbers its lines by an exclusive scan of the ranges' line counts, and parses them as
/// read_csv does. The points, in order over the ranks, are read_csv's. The first bad line of the
/// file is reported on every rank with read_csv's message (the smallest line number wins an
/// integer reduction, its rank broadcasts the text).
/// @throws InputError on every rank; InputError naming the file, on the ranks that meet it,
/// when the file cannot be opened or read.
DistributedPoints read_text_points_distributed(dist::Comm& comm,
                                               const InputFile& file,
                                               const ReadOptions& options);

}  // namespace dtm::io
