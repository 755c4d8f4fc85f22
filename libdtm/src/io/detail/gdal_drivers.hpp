// SPDX-License-Identifier: MIT
/// @file
/// @brief GDAL's drivers registered once per process, for every reader and writer that opens
/// a dataset.
#pragma once

namespace dtm::io::detail {

/// GDALAllRegister() on the first call (thread-safe); later calls return at once.
void register_gdal_drivers();

}  // namespace dtm::io::detail
