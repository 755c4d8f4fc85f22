// SPDX-License-Identifier: MIT
/// @file
/// @brief What `dtm tin` reports about one triangulation: the `--report` file (every merged
/// duplicate, every breakline height conflict, the optimisation) and the `--stats` line (counts,
/// phase times, contour flats, the optimisation), both JSON through io::JsonWriter.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "dtm/algo/optimize.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/io/json_writer.hpp"
#include "dtm/products/distributed_tin.hpp"
#include "dtm/products/surface.hpp"

namespace dtm::products {

/// The optimisation's figures (criterion, flips, improvable edges and quality before and after)
/// as the member "optimize" of the object open in @p json; nothing for Criterion::delaunay.
void optimize_json(io::JsonWriter& json, const OptimizeStats& stats);

/// The `--report` document of @p result.
[[nodiscard]] std::string tin_report_json(const TriangulateResult& result);

/// tin_report_json() written to @p path atomically. @throws Error when it cannot be written.
void write_tin_report(const std::filesystem::path& path, const TriangulateResult& result);

/// Wall-clock seconds of the phases the caller timed (the triangulation's own are in its stats).
struct TinTimes {
    double read = 0.0;
    double write = 0.0;
    double total = 0.0;
};

/// The `--stats` line of @p surface: one inline JSON object.
[[nodiscard]] std::string tin_stats_json(const Surface& surface,
                                         std::size_t skipped_lines,
                                         const TinTimes& seconds);

/// The `--stats` line of a distributed `dtm tin` (the serial fields it has, the ranks and what
/// they exchanged).
[[nodiscard]] std::string distributed_tin_stats_json(const DistributedTinResult& result,
                                                     double total_seconds);

}  // namespace dtm::products
