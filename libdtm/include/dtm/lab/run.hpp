// SPDX-License-Identifier: MIT
/// @file
/// @brief One registry method on loaded survey inputs (`dtm methods run`): the inputs as the
/// methods take them, the output as the method writes it, and its `--stats` line.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dtm/io/inputs.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/methods/registry.hpp"

namespace dtm::lab {

/// The points and constraint segments of @p terrain as a method takes them: 2-D breakline
/// vertices take the height of the survey points at their position (resolve_line_heights, as
/// in triangulate()), then join the points after them; each breakline segment becomes a
/// constraint. The terrain's points are moved out.
struct MethodPoints {
    std::vector<Point3> points;
    std::vector<methods::Segment> segments;
};
[[nodiscard]] MethodPoints method_points(TerrainInput& terrain);

/// What @p method writes: a folder of TINs (all triangulations), polygon faces (their writer
/// names its extensions) or one TIN, for io::check_output before anything is read.
[[nodiscard]] io::OutputKind method_output_kind(const methods::MethodInfo& method);

/// The result written as the method's output kind, atomically, with @p crs_wkt.
void write_method_output(const methods::MethodInfo& method,
                         const methods::MethodResult& result,
                         const std::filesystem::path& path,
                         const std::string& crs_wkt);

/// The `--stats` line: method, counts, seconds, the counters and the method's own figures.
[[nodiscard]] std::string method_stats_json(const methods::MethodInfo& method,
                                            std::size_t points,
                                            const methods::MethodResult& result,
                                            double seconds);

/// One run of `dtm methods run`: the method, its output and seconds.
struct MethodRun {
    const methods::MethodInfo* method = nullptr;
    std::size_t points = 0;  ///< the points the method took
    methods::MethodResult result;
    double seconds = 0.0;  ///< the method's call alone
};

/// `dtm methods run`'s job: the registry method @p name on the inputs of @p load (checked for a
/// method that takes no breaklines, the output checked before anything is read), timed, its
/// result written to @p output. @throws UsageError, InputError, Error, Cancelled.
[[nodiscard]] MethodRun run_method(const std::string& name,
                                   const io::LoadOptions& load,
                                   const methods::MethodOptions& options,
                                   const std::filesystem::path& output,
                                   const Progress& progress = {});

/// `dtm methods list --json`: every registry field of every method, one JSON array.
[[nodiscard]] std::string registry_json();

}  // namespace dtm::lab
