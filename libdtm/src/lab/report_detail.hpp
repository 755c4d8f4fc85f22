// SPDX-License-Identifier: MIT
/// @file
/// @brief Shared by the lab's writers: the normalised times of a cell, the markdown report and
/// the plots.
#pragma once

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "dtm/lab/compare.hpp"

namespace dtm::lab::detail {

/// A cell's mean time divided by N, N log2 N, N log10 N (the pseudo-triangulation thesis'
/// tables use base 10) and N^(4/3); resident bytes per point.
struct Rates {
    double per_n = NAN, per_nlogn = NAN, per_nlog10n = NAN, per_n43 = NAN, bytes_per_point = NAN;
};

[[nodiscard]] inline Rates rates(const Measurement& c) {
    Rates r;
    if (c.status != Status::ok || c.n < 2) return r;
    const double n = double(c.n);
    r.per_n = c.mean_seconds / n;
    r.per_nlogn = c.mean_seconds / (n * std::log2(n));
    r.per_nlog10n = c.mean_seconds / (n * std::log10(n));
    r.per_n43 = c.mean_seconds / std::pow(n, 4.0 / 3.0);
    r.bytes_per_point = double(c.peak_rss_bytes) / n;
    return r;
}

/// Writes the plots into @p dir; returns their names relative to the report (plots/...).
[[nodiscard]] std::vector<std::string> write_plots(const CompareResult& result,
                                                   const std::filesystem::path& dir);

/// report.md.
[[nodiscard]] std::string markdown(const CompareResult& result,
                                   const std::vector<std::string>& plots);

}  // namespace dtm::lab::detail
