// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: read_ogr on a range of an OGR source's features (a distributed run's share,
/// R-D2 of docs/distributed.md). Features are numbered in reading order: the layers in order,
/// each layer's features (after the `where` filter) in order, features without geometry counted.
#pragma once

#include <cstdint>

#include "dtm/core/progress.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io::detail {

struct FeatureRange {
    static constexpr std::uint64_t none = ~std::uint64_t{0};
    std::uint64_t first = 0;
    std::uint64_t last = none;       ///< one past the last feature; none: to the end
    std::uint64_t position = 0;      ///< running: the next feature's number
    std::uint64_t failed_at = none;  ///< the feature whose geometry threw, if any
    [[nodiscard]] bool restricted() const noexcept { return first > 0 || last != none; }
};

/// read_ogr on the features [range.first, range.last) (every layer's CRS still read, so every
/// range gets the file's CRS). On an InputError from a feature, range.failed_at names it.
[[nodiscard]] ReadResult read_ogr_range(const InputFile& file,
                                        const ReadOptions& options,
                                        const Progress& progress,
                                        FeatureRange& range);

/// The features read_ogr would read (every layer, or ReadOptions::layer, after `where`).
/// @throws InputError as read_ogr (no such layer, a bad filter)
[[nodiscard]] std::uint64_t ogr_feature_count(const InputFile& file, const ReadOptions& options);

}  // namespace dtm::io::detail
