// SPDX-License-Identifier: MIT
// Shared by the fuzzers of the table readers (landxml, dxf, jvf, las): run one reader on the
// bytes as a file, let only InputError escape, and check what it returns: a TIN with valid
// topology (tin_fuzz_support.hpp), finite survey points, lines of at least two vertices.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "dtm/core/error.hpp"
#include "dtm/io/reader.hpp"
#include "tin_fuzz_support.hpp"

namespace dtm::fuzz {

/// Traps unless @p r is a result a reader may return.
inline void check_result(const io::ReadResult& r) {
    if (r.tin) check_tin(*r.tin);
    for (const Point3& p : r.terrain.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) __builtin_trap();
    }
    if (!r.labels.ids.empty() && r.labels.ids.size() != r.terrain.points.size()) __builtin_trap();
    if (r.summary.cloud) {
        const io::PointCloudCounts& c = *r.summary.cloud;
        if (c.records != c.withheld + c.class_filtered + c.thinned + r.terrain.points.size()) {
            __builtin_trap();
        }
    }
}

/// Writes the bytes to a file with @p extension and reads it with @p read.
inline void read_bytes(const std::uint8_t* data,
                       std::size_t size,
                       const char* extension,
                       io::ReadFn read,
                       const io::ReadOptions& options = {}) {
    const auto path = bytes_to_file(data, size, extension);
    try {
        check_result(read({path, io::InputRole::points}, options, {}));
    } catch (const InputError&) {
    }
}

}  // namespace dtm::fuzz
