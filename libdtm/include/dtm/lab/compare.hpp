// SPDX-License-Identifier: MIT
/// @file
/// @brief The methods lab (`dtm methods compare`): run registry methods on the lab's point
/// distributions at several sizes, measure time, predicate calls, memory and triangle quality,
/// and write results.csv, results.json, report.md and plots (PNG and SVG). Every method of the
/// registry plugs in through its row; quadratic ones are capped where they would take too long.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/methods/method.hpp"
#include "dtm/methods/point_sets.hpp"

namespace dtm::lab {

struct CompareOptions {
    /// Registry names; empty: every method whose result the lab measures (all but enumeration).
    std::vector<std::string> methods;
    std::vector<std::size_t> sizes{1000, 10000, 100000};
    std::vector<methods::Distribution> distributions;  ///< empty: the lab's four
    unsigned sets = 1;    ///< point sets per cell (seeds seed, seed + 1, ...)
    unsigned repeat = 1;  ///< timed runs per set; a cell's time is the mean of sets x repeat
    std::uint64_t seed = 1;
    unsigned threads = 1;  ///< for the parallel methods (dc, dewall)
    /// A quadratic method (registry flag) is not run at a size whose estimated time, from its
    /// time at the previous size scaled by the square of the size ratio, exceeds this.
    double cap_seconds = 10.0;
    /// Angle histograms are drawn at the largest size not above this.
    std::size_t histogram_size = 10000;
    /// With uniform-grid and uniform among the runs: also run it at the sizes of the thesis'
    /// timing table (000 §3.10.9, Fig. 36: 100 ... 4000 points on a 486/DX2).
    bool historical = true;
};

/// Corner-angle statistics of a triangulation or pseudo-triangulation (degrees): for each face
/// the smallest and largest angle at its corners (the vertices with an angle below 180).
struct AngleStats {
    std::size_t faces = 0;
    double min_mean = 0.0;           ///< mean over faces of the face's smallest corner angle
    double max_mean = 0.0;           ///< mean over faces of the face's largest corner angle
    double min_min = 0.0;            ///< the smallest corner angle anywhere
    double max_max = 0.0;            ///< the largest
    static constexpr int bins = 36;  ///< 5-degree bins over [0, 180)
    std::vector<std::uint64_t> min_histogram = std::vector<std::uint64_t>(bins, 0);
    std::vector<std::uint64_t> max_histogram = std::vector<std::uint64_t>(bins, 0);
};

enum class Status { ok, capped, refused, failed };

/// One cell: a method on one distribution at one size.
struct Measurement {
    std::string method;
    std::string family;
    bool quadratic = false;
    std::string distribution;
    std::size_t n = 0;
    Status status = Status::ok;
    std::string note;             ///< why capped / refused / failed
    std::vector<double> seconds;  ///< every timed run
    double mean_seconds = 0.0;
    double min_seconds = 0.0;
    methods::MethodCounters counters;  ///< of the last run
    std::size_t peak_rss_bytes = 0;    ///< largest rise of the resident set during a run
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    std::size_t faces = 0;  ///< polygon faces (pseudo-triangulations)
    AngleStats angles;
    bool historical_only = false;  ///< a run at a Fig. 36 size only
};

struct MachineInfo {
    std::string cpu;     ///< model name
    unsigned cores = 0;  ///< online
    std::string caches;  ///< "L1d 48K, L2 1280K, L3 ..." from sysfs
};

struct CompareResult {
    CompareOptions options;
    MachineInfo machine;
    std::string date;  ///< UTC, ISO 8601
    std::vector<Measurement> cells;
};

/// One row of the thesis' Fig. 36 (000 §3.10.9): the uniform-grid method on a 486/DX2 66 MHz.
struct HistoricalTiming {
    std::size_t n;
    double grid_seconds;
    double triangulation_seconds;
};
[[nodiscard]] const std::vector<HistoricalTiming>& thesis_fig36();

/// Runs every cell. @throws UsageError for an unknown method name; Cancelled. A method that
/// refuses an input (InputError) or fails is recorded as such and the lab goes on.
[[nodiscard]] CompareResult run_compare(const CompareOptions& options,
                                        const Progress& progress = {});

/// The statistics of @p result's triangles (or polygon faces when it has them).
[[nodiscard]] AngleStats angle_stats(const methods::MethodResult& result);

/// Writes results.csv, results.json, report.md and plots/ (PNG and SVG) into @p dir (created
/// if needed; each file atomically). @throws Error when a file cannot be written.
void write_compare(const CompareResult& result, const std::filesystem::path& dir);

/// The column names of results.csv, in order (documented in docs/cli.md).
[[nodiscard]] const std::vector<std::string>& csv_columns();

[[nodiscard]] std::string_view status_name(Status status);

}  // namespace dtm::lab
