// SPDX-License-Identifier: MIT
// compare_rasters A B: cell-by-cell comparison of two single-band rasters over the same cells
// (matched by cell-centre coordinates through each raster's geotransform, so north-up and
// south-up rasters compare correctly). Prints the cells where both have data, the largest
// absolute difference there, and the cells where only one of them has data (NoData footprint).
// Built and run by bench/compare_gdal.sh (g++ ... -lgdal); exit 0 always unless a file fails.
#include <gdal.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

struct Raster {
    int cols = 0, rows = 0;
    double gt[6]{};
    double nodata = 0.0;
    int has_nodata = 0;
    std::vector<double> values;

    [[nodiscard]] bool valid(double v) const {
        return !std::isnan(v) && !(has_nodata && v == nodata);
    }
    /// Value at the cell whose centre is nearest (x, y); NaN outside.
    [[nodiscard]] double at(double x, double y) const {
        const double c = std::floor((x - gt[0]) / gt[1]);
        const double r = std::floor((y - gt[3]) / gt[5]);
        if (c < 0 || r < 0 || c >= cols || r >= rows) {
            return std::nan("");
        }
        return values[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) +
                      static_cast<std::size_t>(c)];
    }
};

bool load(const char* path, Raster& out) {
    GDALDatasetH ds = GDALOpen(path, GA_ReadOnly);
    if (ds == nullptr) {
        std::fprintf(stderr, "compare_rasters: cannot open %s\n", path);
        return false;
    }
    out.cols = GDALGetRasterXSize(ds);
    out.rows = GDALGetRasterYSize(ds);
    GDALGetGeoTransform(ds, out.gt);
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    out.nodata = GDALGetRasterNoDataValue(band, &out.has_nodata);
    out.values.resize(static_cast<std::size_t>(out.cols) * static_cast<std::size_t>(out.rows));
    const CPLErr err = GDALRasterIO(band, GF_Read, 0, 0, out.cols, out.rows, out.values.data(),
                                    out.cols, out.rows, GDT_Float64, 0, 0);
    GDALClose(ds);
    return err == CE_None;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: compare_rasters A B\n");
        return 2;
    }
    GDALAllRegister();
    Raster a, b;
    if (!load(argv[1], a) || !load(argv[2], b)) {
        return 1;
    }
    std::size_t both = 0, only_a = 0, only_b = 0, over = 0;
    double max_diff = 0.0;
    for (int r = 0; r < a.rows; ++r) {
        for (int c = 0; c < a.cols; ++c) {
            const double x = a.gt[0] + (c + 0.5) * a.gt[1];
            const double y = a.gt[3] + (r + 0.5) * a.gt[5];
            const double va =
                a.values[static_cast<std::size_t>(r) * static_cast<std::size_t>(a.cols) +
                         static_cast<std::size_t>(c)];
            const double vb = b.at(x, y);
            const bool ha = a.valid(va), hb = b.valid(vb);
            if (ha && hb) {
                ++both;
                const double d = std::abs(va - vb);
                max_diff = std::max(max_diff, d);
                over += d > 1e-4 ? 1 : 0;
            } else if (ha) {
                ++only_a;
            } else if (hb) {
                ++only_b;
            }
        }
    }
    std::printf(
        "cells %d x %d, both with data %zu, max |A-B| %.3g m, cells differing by more than "
        "1e-4 m %zu, data only in A %zu, only in B %zu\n",
        a.cols, a.rows, both, max_diff, over, only_a, only_b);
    return 0;
}
