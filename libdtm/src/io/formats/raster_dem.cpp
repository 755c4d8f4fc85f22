// SPDX-License-Identifier: MIT
// Raster DEM reader: GDAL opens the raster, band 1 is read row by row as doubles, and each cell
// with a value is a point at its centre through the geotransform (rotated grids included).
// NoData (the band's value, or NaN) is skipped and counted.
#include "dtm/io/formats/raster_dem.hpp"

#include <gdal_priv.h>

#include <cctype>
#include <cmath>
#include <memory>
#include <string>

#include "dtm/core/error.hpp"
#include "io/detail/gdal_drivers.hpp"

namespace dtm::io {

bool is_ascii_grid(const FileHead& head) {
    std::string word;
    for (const char c : head.bytes.substr(0, 32)) {
        if (std::isspace(static_cast<unsigned char>(c))) {
            if (word.empty()) continue;
            break;
        }
        word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return word == "ncols" || word == "nrows" || word == "xllcorner" || word == "xllcenter" ||
           word == "yllcorner" || word == "yllcenter";
}

ReadResult read_raster_dem(const InputFile& file, const ReadOptions&, const Progress& progress) {
    if (file.role != InputRole::points) {
        throw InputError(file.path, 0, 0,
                         "a raster DEM is a survey input (its cells become points), not a line or "
                         "ring input");
    }
    detail::register_gdal_drivers();
    std::unique_ptr<GDALDataset> ds(static_cast<GDALDataset*>(GDALOpenEx(
        file.path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
    if (!ds) throw InputError(file.path, 0, 0, "GDAL cannot open the file as a raster");
    if (ds->GetRasterCount() < 1) throw InputError(file.path, 0, 0, "the raster has no band");
    double gt[6];
    if (ds->GetGeoTransform(gt) != CE_None) {
        throw InputError(file.path, 0, 0, "the raster has no georeferencing (geotransform)");
    }
    GDALRasterBand* band = ds->GetRasterBand(1);
    int has_nodata = 0;
    const double nodata = band->GetNoDataValue(&has_nodata);
    const int width = ds->GetRasterXSize();
    const int height = ds->GetRasterYSize();
    ReadResult r;
    r.raster_cells = true;
    r.summary.path = file.path;
    r.summary.format = std::string("raster DEM (") + ds->GetDriver()->GetDescription() + ")";
    if (const char* wkt = ds->GetProjectionRef(); wkt != nullptr) r.crs_wkt = wkt;
    r.terrain.points.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    std::vector<double> row(static_cast<std::size_t>(width));
    std::size_t skipped = 0;
    for (int j = 0; j < height; ++j) {
        if (band->RasterIO(GF_Read, 0, j, width, 1, row.data(), width, 1, GDT_Float64, 0, 0,
                           nullptr) != CE_None) {
            throw InputError(file.path, 0, 0,
                             "cannot read row " + std::to_string(j) + " of the raster");
        }
        for (int i = 0; i < width; ++i) {
            const double z = row[static_cast<std::size_t>(i)];
            if (std::isnan(z) || (has_nodata != 0 && z == nodata)) {
                ++skipped;
                continue;
            }
            const double ci = i + 0.5;
            const double cj = j + 0.5;
            r.terrain.points.push_back(
                {gt[0] + ci * gt[1] + cj * gt[2], gt[3] + ci * gt[4] + cj * gt[5], z});
        }
        progress.report(static_cast<double>(j + 1) / height);
    }
    r.summary.warnings.push_back(std::to_string(width) + " x " + std::to_string(height) +
                                 " cells: " + std::to_string(r.terrain.points.size()) +
                                 " points at cell centres, " + std::to_string(skipped) +
                                 " NoData cells skipped");
    return r;
}

}  // namespace dtm::io
