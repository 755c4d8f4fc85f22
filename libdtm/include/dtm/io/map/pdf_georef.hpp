// SPDX-License-Identifier: MIT
/// @file
/// @brief Georeferencing a PDF drawn by cairo, page by page, through GDAL's PDF driver in update
/// mode: it appends an incremental update with the ISO 32000 geospatial viewport (/VP with a
/// /Measure: /GPTS, /LPTS, /GCS with the EPSG code and WKT) that gdalinfo, QGIS and Acrobat
/// read. The neat line is reported by GDAL as NEATLINE.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dtm/io/map/map_layout.hpp"

namespace dtm::io::map {

/// Georeferences page i + 1 of the PDF at @p path with pages[i] (the whole page at scale; the
/// neat line is the page's extent) in the CRS @p crs_wkt. The file is modified in place (call
/// it on a temporary before it is committed).
/// @throws Error when GDAL cannot open or update the PDF, or the CRS is not understood
void georeference_pdf(const std::filesystem::path& path,
                      const std::vector<PageFrame>& pages,
                      const std::string& crs_wkt);

}  // namespace dtm::io::map
