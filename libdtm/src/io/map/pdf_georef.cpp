// SPDX-License-Identifier: MIT
// Geospatial PDF through GDAL's PDF driver (https://gdal.org/drivers/raster/pdf.html, "Update
// of existing files"): each page is opened as the subdataset PDF:<n>:<file> in update mode with
// DPI=72, so one raster pixel is one PDF point and the geotransform maps points exactly; the CRS,
// the geotransform and the NEATLINE polygon are set, and GDAL appends an incremental update
// holding the ISO 32000 viewport (/VP /Measure /GEO with /GPTS and /GCS) on closing. The content
// streams cairo wrote stay untouched.
#include "dtm/io/map/pdf_georef.hpp"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <cstdio>
#include <memory>

#include "dtm/core/error.hpp"
#include "io/detail/gdal_drivers.hpp"

namespace dtm::io::map {
namespace {

struct QuietErrors {
    QuietErrors() {
        CPLPushErrorHandler(CPLQuietErrorHandler);
        CPLErrorReset();
    }
    ~QuietErrors() { CPLPopErrorHandler(); }
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;
};

std::string last_error() {
    const char* msg = CPLGetLastErrorMsg();
    return msg != nullptr && *msg != '\0' ? std::string(": ") + msg : std::string();
}

std::string neatline_wkt(const Box2& e) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "POLYGON ((%.17g %.17g,%.17g %.17g,%.17g %.17g,%.17g %.17g,%.17g %.17g))", e.xmin,
                  e.ymin, e.xmin, e.ymax, e.xmax, e.ymax, e.xmax, e.ymin, e.xmin, e.ymin);
    return buf;
}

}  // namespace

void georeference_pdf(const std::filesystem::path& path,
                      const std::vector<PageFrame>& pages,
                      const std::string& crs_wkt) {
    io::detail::register_gdal_drivers();
    const QuietErrors quiet;
    OGRSpatialReference srs;
    if (!crs_wkt.empty() && srs.SetFromUserInput(crs_wkt.c_str()) != OGRERR_NONE) {
        throw Error("map: cannot georeference " + path.string() + ": the CRS is not understood");
    }
    const char* open_options[] = {"DPI=72", nullptr};
    for (std::size_t i = 0; i < pages.size(); ++i) {
        const PageFrame& page = pages[i];
        const std::string name = "PDF:" + std::to_string(i + 1) + ":" + path.string();
        std::unique_ptr<GDALDataset> ds(GDALDataset::Open(
            name.c_str(), GDAL_OF_RASTER | GDAL_OF_UPDATE, nullptr, open_options, nullptr));
        if (!ds) {
            throw Error("map: GDAL cannot open " + path.string() + " page " +
                        std::to_string(i + 1) + " for georeferencing" + last_error());
        }
        // one pixel = one point = 25.4 / 72 mm of paper
        const double ground_per_pixel = page.units_per_mm() * 25.4 / 72.0;
        double gt[6] = {page.extent.xmin, ground_per_pixel, 0.0, page.extent.ymax, 0.0,
                        -ground_per_pixel};
        const bool ok =
            (crs_wkt.empty() || ds->SetSpatialRef(&srs) == CE_None) &&
            ds->SetGeoTransform(gt) == CE_None &&
            ds->SetMetadataItem("NEATLINE", neatline_wkt(page.extent).c_str()) == CE_None;
        if (!ok) {
            throw Error("map: GDAL cannot georeference " + path.string() + last_error());
        }
        ds.reset();  // closing writes the incremental update
        if (CPLGetLastErrorType() == CE_Failure) {
            throw Error("map: GDAL failed to write the georeferencing of " + path.string() +
                        last_error());
        }
    }
    // GDAL does not report a short write of the update (a full disk): read every page back.
    for (std::size_t i = 0; i < pages.size(); ++i) {
        const std::string name = "PDF:" + std::to_string(i + 1) + ":" + path.string();
        std::unique_ptr<GDALDataset> ds(
            GDALDataset::Open(name.c_str(), GDAL_OF_RASTER, nullptr, open_options, nullptr));
        double gt[6] = {};
        if (!ds || ds->GetGeoTransform(gt) != CE_None ||
            ds->GetMetadataItem("NEATLINE") == nullptr) {
            throw Error("map: cannot write " + path.string() + ": the georeferencing of page " +
                        std::to_string(i + 1) + " did not reach the file (disk full?)");
        }
    }
}

}  // namespace dtm::io::map
