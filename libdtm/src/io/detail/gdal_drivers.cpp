// SPDX-License-Identifier: MIT
#include "gdal_drivers.hpp"

#include <gdal.h>

#include <mutex>

namespace dtm::io::detail {

void register_gdal_drivers() {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
}

}  // namespace dtm::io::detail
