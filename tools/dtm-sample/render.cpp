// SPDX-License-Identifier: MIT
// The README picture, with GDAL's own algorithms only: gdaldem hillshade and color-relief
// (GDALDEMProcessing), the two multiplied (the blending the QGIS project asks QGIS for),
// gdal_rasterize (GDALRasterize) for the contours and lines, gdal_translate (GDALTranslate) to PNG.
#include "render.hpp"

#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>
#include <gdal_utils.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

namespace dtm::sample {
namespace {

struct Closer {
    void operator()(GDALDataset* d) const noexcept { GDALClose(d); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

/// Builds a NULL-terminated argument list for the GDAL utility functions.
class Args {
public:
    Args(std::initializer_list<std::string> items) {
        for (const std::string& item : items) {
            list_.AddString(item.c_str());
        }
    }
    void add(const std::string& item) { list_.AddString(item.c_str()); }
    [[nodiscard]] char** get() { return list_.List(); }

private:
    CPLStringList list_;
};

/// The QGIS project's terrain ramp (qgis_project_layers.cpp) over [z_min, z_max], as a gdaldem
/// colour file in /vsimem.
std::string write_ramp(double z_min, double z_max) {
    constexpr std::array<std::pair<double, std::array<int, 3>>, 6> stops{{{0.0, {59, 141, 70}},
                                                                          {0.2, {141, 187, 92}},
                                                                          {0.45, {226, 217, 143}},
                                                                          {0.7, {199, 154, 91}},
                                                                          {0.88, {156, 107, 74}},
                                                                          {1.0, {244, 239, 233}}}};
    std::string text;
    for (const auto& [at, rgb] : stops) {
        char line[96];
        std::snprintf(line, sizeof line, "%.4f %d %d %d\n", z_min + at * (z_max - z_min), rgb[0],
                      rgb[1], rgb[2]);
        text += line;
    }
    text += "nv 255 255 255\n";
    const std::string path = "/vsimem/dtm_sample_ramp.txt";
    VSILFILE* file = VSIFOpenL(path.c_str(), "wb");
    VSIFWriteL(text.data(), 1, text.size(), file);
    VSIFCloseL(file);
    return path;
}

Dataset dem_processing(
    GDALDataset& dem, const char* mode, const char* ramp, Args args, const char* out) {
    GDALDEMProcessingOptions* options = GDALDEMProcessingOptionsNew(args.get(), nullptr);
    int error = 0;
    Dataset result(GDALDataset::FromHandle(
        GDALDEMProcessing(out, GDALDataset::ToHandle(&dem), mode, ramp, options, &error)));
    GDALDEMProcessingOptionsFree(options);
    if (!result || error != 0) {
        throw std::runtime_error(std::string("gdaldem ") + mode +
                                 " failed: " + CPLGetLastErrorMsg());
    }
    return result;
}

/// Colour x shade, the shade normalised so that flat ground (hillshade about 180) keeps its colour.
void multiply(GDALDataset& color, GDALDataset& shade) {
    const int w = color.GetRasterXSize();
    const int h = color.GetRasterYSize();
    const auto cells = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    std::vector<unsigned char> rgb(3 * cells);
    std::vector<unsigned char> hs(cells);
    if (color.RasterIO(GF_Read, 0, 0, w, h, rgb.data(), w, h, GDT_Byte, 3, nullptr, 0, 0, 0,
                       nullptr) != CE_None ||
        shade.GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, hs.data(), w, h, GDT_Byte, 0, 0) !=
            CE_None) {
        throw std::runtime_error("cannot read the relief rasters");
    }
    for (std::size_t i = 0; i < cells; ++i) {
        const double f = hs[i] == 0 ? 1.0 : std::min(1.25, 0.25 + 0.75 * hs[i] / 185.0);
        for (std::size_t b = 0; b < 3; ++b) {
            unsigned char& c = rgb[b * cells + i];
            c = static_cast<unsigned char>(std::min(255.0, c * f));
        }
    }
    if (color.RasterIO(GF_Write, 0, 0, w, h, rgb.data(), w, h, GDT_Byte, 3, nullptr, 0, 0, 0,
                       nullptr) != CE_None) {
        throw std::runtime_error("cannot write the picture raster");
    }
}

void burn(GDALDataset& target, const std::filesystem::path& source, Args args) {
    Dataset vector(GDALDataset::Open(source.string().c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
    if (!vector) {
        throw std::runtime_error("cannot open " + source.string());
    }
    GDALRasterizeOptions* options = GDALRasterizeOptionsNew(args.get(), nullptr);
    int error = 0;
    GDALRasterize(nullptr, GDALDataset::ToHandle(&target), GDALDataset::ToHandle(vector.get()),
                  options, &error);
    GDALRasterizeOptionsFree(options);
    if (error != 0) {
        throw std::runtime_error("gdal_rasterize of " + source.string() + " failed");
    }
}

Args burn_args(std::initializer_list<int> rgb) {
    Args args{"-b", "1", "-b", "2", "-b", "3"};
    for (const int c : rgb) {
        args.add("-burn");
        args.add(std::to_string(c));
    }
    return args;
}

}  // namespace

void render_picture(const std::filesystem::path& build_dir,
                    const std::filesystem::path& png,
                    const RenderOptions& options) {
    GDALAllRegister();
    Dataset dem(GDALDataset::Open((build_dir / "dem.tif").string().c_str(), GDAL_OF_RASTER));
    if (!dem) {
        throw std::runtime_error("cannot open " + (build_dir / "dem.tif").string());
    }
    double range[2];
    dem->GetRasterBand(1)->ComputeRasterMinMax(FALSE, range);
    const std::string ramp = write_ramp(range[0], range[1]);
    const Dataset shade = dem_processing(
        *dem, "hillshade", nullptr, {"-z", std::to_string(options.z_factor), "-of", "MEM"}, "");
    Dataset color = dem_processing(*dem, "color-relief", ramp.c_str(), {"-of", "MEM"}, "");
    VSIUnlink(ramp.c_str());
    multiply(*color, *shade);

    const auto contours = build_dir / "contours.gpkg";
    Args thin = burn_args({150, 110, 75});
    for (const char* a : {"-l", "contours", "-where", "\"index\" = 0"}) thin.add(a);
    burn(*color, contours, std::move(thin));
    Args thick = burn_args({70, 35, 10});
    for (const char* a : {"-l", "contours", "-where", "\"index\" = 1"}) thick.add(a);
    burn(*color, contours, std::move(thick));
    for (const auto& file : options.breaklines) burn(*color, file, burn_args({30, 60, 170}));

    Args translate{"-of", "PNG"};
    GDALTranslateOptions* topts = GDALTranslateOptionsNew(translate.get(), nullptr);
    int error = 0;
    GDALDatasetH out =
        GDALTranslate(png.string().c_str(), GDALDataset::ToHandle(color.get()), topts, &error);
    GDALTranslateOptionsFree(topts);
    if (out == nullptr || error != 0) {
        throw std::runtime_error("cannot write " + png.string());
    }
    GDALClose(out);
}

}  // namespace dtm::sample
