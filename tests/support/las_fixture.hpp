// SPDX-License-Identifier: MIT
/// @file
/// @brief Writes small LAS files byte by byte (ASPRS LAS 1.4 R15 layout) for the LAS reader's
/// tests and the fuzzer's seeds; tests/support/las_oracle.py reads them back independently.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dtm::test {

struct LasRecord {
    std::int32_t x = 0;
    std::int32_t y = 0;
    std::int32_t z = 0;
    unsigned classification = 2;
    bool withheld = false;
};

struct LasSpec {
    unsigned minor = 2;   ///< LAS 1.minor (2, 3 or 4)
    unsigned format = 0;  ///< point data record format 0-10
    unsigned extra_bytes = 0;
    double scale[3] = {0.01, 0.01, 0.001};
    double offset[3] = {0, 0, 0};
    std::string wkt;    ///< an OGC WKT VLR (2112) when not empty
    unsigned epsg = 0;  ///< a GeoKeyDirectory VLR (34735) with ProjectedCSTypeGeoKey when not 0
    bool wkt_as_evlr = false;  ///< LAS 1.4: the WKT in an extended VLR after the points
    bool legacy_count = true;  ///< LAS 1.4: fill the legacy 32-bit count too
    bool compressed = false;   ///< set bit 7 of the point data format (as LASzip does)
    std::vector<LasRecord> records;
};

/// The LAS file's bytes.
[[nodiscard]] std::string las_bytes(const LasSpec& spec);

}  // namespace dtm::test
