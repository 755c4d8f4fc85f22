// SPDX-License-Identifier: MIT
// DEM output through GDAL: a streaming GridSink, the driver chosen by extension, atomic commit,
// and gdaldem derivatives (GDALDEMProcessing, not reimplemented here).
//
// GeoTIFF targets are created directly (Float32, 256 x 256 tiles, DEFLATE with the floating
// point predictor, BIGTIFF when needed, compression on all cores) and receive the rows as the
// rasteriser produces them. Drivers that can only CreateCopy (COG, Arc/Info ASCII, ...) get a
// staging GeoTIFF next to the target, copied at commit() and then removed, so memory stays
// bounded whatever the raster size.
#include "dtm/io/grid_writer.hpp"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal.h>
#include <gdal_utils.h>
#include <gdal_vrt.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <sstream>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/extension.hpp"
#include "io/detail/gdal_drivers.hpp"

namespace dtm::io {
namespace fs = std::filesystem;
namespace {

void register_gdal() {
    static std::once_flag once;
    std::call_once(once, [] {
        detail::register_gdal_drivers();
        CPLSetConfigOption("GDAL_PAM_ENABLED", "NO");  // no .aux.xml side files
    });
}

bool declares_extension(GDALDriverH driver, const std::string& ext) {
    const char* list = GDALGetMetadataItem(driver, GDAL_DMD_EXTENSIONS, nullptr);
    if (list == nullptr) {
        return false;
    }
    std::istringstream words(list);
    std::string word;
    while (words >> word) {
        std::transform(word.begin(), word.end(), word.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (word == ext) {
            return true;
        }
    }
    return false;
}

bool can_write_raster(GDALDriverH driver) {
    const auto yes = [driver](const char* key) {
        const char* v = GDALGetMetadataItem(driver, key, nullptr);
        return v != nullptr && EQUAL(v, "YES");
    };
    return yes(GDAL_DCAP_RASTER) && (yes(GDAL_DCAP_CREATE) || yes(GDAL_DCAP_CREATECOPY));
}

/// Short name of the driver that writes @p target. @throws UsageError
std::string raster_driver_for(const fs::path& target) {
    register_gdal();
    const std::string ext = lower_extension(target);
    if (ext == "tif" || ext == "tiff") {
        return "GTiff";
    }
    for (int i = 0; i < GDALGetDriverCount(); ++i) {
        GDALDriverH d = GDALGetDriver(i);
        if (can_write_raster(d) && declares_extension(d, ext) &&
            !EQUAL(GDALGetDriverShortName(d), "COG")) {
            return GDALGetDriverShortName(d);
        }
    }
    throw UsageError("grid: no GDAL raster driver writes '." + ext + "' (" + target.string() +
                     "); use .tif, .asc, or the extension of another GDAL raster driver that "
                     "writes (gdalinfo lists them)");
}

[[noreturn]] void throw_gdal(const std::string& what) {
    throw Error("grid: " + what + ": " + CPLGetLastErrorMsg());
}

/// CSL option list owned by RAII.
class Options {
public:
    Options() = default;
    Options(const Options&) = delete;
    Options& operator=(const Options&) = delete;
    ~Options() { CSLDestroy(list_); }
    Options& add(const char* key, const char* value) {
        list_ = CSLSetNameValue(list_, key, value);
        return *this;
    }
    Options& arg(const std::string& value) {
        list_ = CSLAddString(list_, value.c_str());
        return *this;
    }
    [[nodiscard]] char** get() const { return list_; }

private:
    char** list_ = nullptr;
};

GDALDatasetH create_geotiff(const fs::path& path,
                            const GridSpec& spec,
                            const GridWriteOptions& options,
                            bool staging) {
    GDALDriverH driver = GDALGetDriverByName("GTiff");
    Options co;
    co.add("TILED", "YES").add("BLOCKXSIZE", "256").add("BLOCKYSIZE", "256");
    co.add("COMPRESS", "DEFLATE").add("PREDICTOR", "3").add("BIGTIFF", "IF_SAFER");
    co.add("NUM_THREADS", "ALL_CPUS").add("ZLEVEL", staging ? "1" : "6");
    GDALDatasetH ds = GDALCreate(driver, path.c_str(), static_cast<int>(spec.cols),
                                 static_cast<int>(spec.rows), 1, GDT_Float32, co.get());
    if (ds == nullptr) {
        throw_gdal("cannot create " + path.string());
    }
    double transform[6] = {spec.xmin, spec.cell, 0.0, spec.ymax, 0.0, -spec.cell};
    GDALSetGeoTransform(ds, transform);
    if (!options.crs_wkt.empty() && GDALSetProjection(ds, options.crs_wkt.c_str()) != CE_None) {
        GDALClose(ds);
        throw_gdal("cannot set the CRS of " + path.string());
    }
    GDALSetRasterNoDataValue(GDALGetRasterBand(ds, 1), static_cast<double>(options.nodata));
    return ds;
}

/// A GeoTIFF GDAL wrote, read back for its block index: GDAL does not report every failed
/// write(2) when it closes a file (full disk, file-size limit), which would leave a block
/// without bytes that reads as empty. @throws Error naming @p target
void check_geotiff_blocks(const fs::path& written, const fs::path& target) {
    GDALDatasetH ds = GDALOpen(written.c_str(), GA_ReadOnly);
    if (ds == nullptr) {
        throw_gdal("cannot write " + target.string() + " (it does not read back)");
    }
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    int bx = 0, by = 0;
    GDALGetBlockSize(band, &bx, &by);
    const int nx = (GDALGetRasterXSize(ds) + bx - 1) / std::max(bx, 1);
    const int ny = (GDALGetRasterYSize(ds) + by - 1) / std::max(by, 1);
    bool whole = true;
    for (int y = 0; y < ny && whole; ++y) {
        for (int x = 0; x < nx && whole; ++x) {
            const std::string key = "BLOCK_SIZE_" + std::to_string(x) + "_" + std::to_string(y);
            const char* size = GDALGetMetadataItem(band, key.c_str(), "TIFF");
            whole = size != nullptr && std::atoll(size) > 0;
        }
    }
    GDALClose(ds);
    if (!whole) {
        throw Error("grid: cannot write " + target.string() +
                    ": the file is incomplete (a write failed: full disk or file-size limit?)");
    }
}

}  // namespace

struct GridWriter::State {
    GridSpec spec;
    GridWriteOptions options;
    std::string driver;
    AtomicOutput out;
    std::optional<AtomicOutput> stage;
    GDALDatasetH ds = nullptr;

    State(const fs::path& target, const GridSpec& s, const GridWriteOptions& o)
        : spec(s), options(o), driver(raster_driver_for(target)), out(target) {}
    ~State() {
        if (ds != nullptr) {
            GDALClose(ds);
        }
    }
    void copy_to_target();
};

GridWriter::GridWriter(const fs::path& target,
                       const GridSpec& spec,
                       const GridWriteOptions& options)
    : state_(std::make_unique<State>(target, spec, options)) {
    if (spec.cols == 0 || spec.rows == 0 || spec.cols > 2'000'000'000 ||
        spec.rows > 2'000'000'000) {
        throw UsageError("grid: raster size " + std::to_string(spec.cols) + " x " +
                         std::to_string(spec.rows) + " is not writable");
    }
    if (options.cog && state_->driver != "GTiff") {
        throw OptionError("cog", "grid: `cog` needs a .tif target, not " + target.string());
    }
    if (state_->driver == "GTiff" && !options.cog) {
        state_->ds = create_geotiff(state_->out.temp_path(), spec, options, false);
        return;
    }
    const fs::path stage_target =
        (target.has_parent_path() ? target.parent_path() : fs::path(".")) /
        (target.stem().string() + ".stage.tif");
    state_->stage.emplace(stage_target);
    state_->ds = create_geotiff(state_->stage->temp_path(), spec, options, true);
}

GridWriter::~GridWriter() = default;

void GridWriter::write_rows(std::size_t first_row,
                            std::size_t row_count,
                            std::span<const float> values) {
    const int cols = static_cast<int>(state_->spec.cols);
    const CPLErr err =
        GDALRasterIO(GDALGetRasterBand(state_->ds, 1), GF_Write, 0, static_cast<int>(first_row),
                     cols, static_cast<int>(row_count), const_cast<float*>(values.data()), cols,
                     static_cast<int>(row_count), GDT_Float32, 0, 0);
    if (err != CE_None) {
        throw_gdal("cannot write rows to " + state_->out.target().string());
    }
}

void GridWriter::State::copy_to_target() {
    GDALDriverH target_driver = GDALGetDriverByName(options.cog ? "COG" : driver.c_str());
    Options co;
    if (options.cog) {
        co.add("COMPRESS", "DEFLATE").add("PREDICTOR", "YES").add("NUM_THREADS", "ALL_CPUS");
        co.add("BIGTIFF", "IF_SAFER");
    }
    GDALDatasetH copy = GDALCreateCopy(target_driver, out.temp_path().c_str(), ds, FALSE, co.get(),
                                       nullptr, nullptr);
    if (copy == nullptr) {
        throw_gdal("cannot write " + out.target().string());
    }
    GDALClose(copy);
}

void GridWriter::commit() {
    CPLErrorReset();
    GDALFlushCache(state_->ds);
    if (CPLGetLastErrorType() >= CE_Failure) {
        throw_gdal("cannot write " + state_->out.target().string());
    }
    if (state_->stage) {
        state_->copy_to_target();
    }
    GDALClose(state_->ds);
    state_->ds = nullptr;
    if (CPLGetLastErrorType() >= CE_Failure) {
        throw_gdal("cannot write " + state_->out.target().string());
    }
    if (state_->driver == "GTiff") {
        check_geotiff_blocks(state_->out.temp_path(), state_->out.target());
    }
    state_->out.commit();
}

void write_grid(const Grid& grid, const fs::path& target, const GridWriteOptions& options) {
    GridWriteOptions o = options;
    o.nodata = grid.nodata;
    GridWriter writer(target, grid.spec, o);
    writer.write_rows(0, grid.spec.rows, grid.values);
    writer.commit();
}

void write_dem_derivative(const fs::path& dem, const fs::path& target, DemDerivative kind) {
    const std::string driver = raster_driver_for(target);
    GDALDatasetH src = GDALOpen(dem.c_str(), GA_ReadOnly);
    if (src == nullptr) {
        throw_gdal("cannot open " + dem.string());
    }
    AtomicOutput out(target);
    Options args;
    args.arg("-of").arg(driver).arg("-compute_edges");
    if (driver == "GTiff") {
        args.arg("-co").arg("TILED=YES").arg("-co").arg("COMPRESS=DEFLATE");
    }
    GDALDEMProcessingOptions* options = GDALDEMProcessingOptionsNew(args.get(), nullptr);
    const char* mode = kind == DemDerivative::hillshade ? "hillshade"
                       : kind == DemDerivative::slope   ? "slope"
                                                        : "aspect";
    int usage_error = FALSE;
    CPLErrorReset();
    GDALDatasetH result =
        GDALDEMProcessing(out.temp_path().c_str(), src, mode, nullptr, options, &usage_error);
    GDALDEMProcessingOptionsFree(options);
    GDALClose(src);
    if (result == nullptr) {
        throw_gdal(std::string("cannot compute the ") + mode + " of " + dem.string());
    }
    // GDAL reports a failed write (full disk, file-size limit) as an error and still returns
    // the dataset: the error, not the pointer, says whether the file is whole.
    GDALClose(result);
    if (CPLGetLastErrorType() >= CE_Failure) {
        throw_gdal(std::string("cannot write the ") + mode + " " + target.string());
    }
    if (driver == "GTiff") check_geotiff_blocks(out.temp_path(), target);
    out.commit();
}

std::vector<std::string> grid_extensions() {
    register_gdal();
    std::vector<std::string> out{"tif", "tiff"};
    for (int i = 0; i < GDALGetDriverCount(); ++i) {
        GDALDriverH d = GDALGetDriver(i);
        const char* list = GDALGetMetadataItem(d, GDAL_DMD_EXTENSIONS, nullptr);
        if (list == nullptr || !can_write_raster(d)) {
            continue;
        }
        std::istringstream words(list);
        std::string word;
        while (words >> word) {
            if (std::find(out.begin(), out.end(), word) == out.end()) {
                out.push_back(word);
            }
        }
    }
    return out;
}

void write_dem_vrt(const fs::path& target,
                   const GridSpec& spec,
                   const std::vector<DemTile>& tiles,
                   const GridWriteOptions& options) {
    register_gdal();
    AtomicOutput out(target);
    GDALDatasetH vrt =
        GDALCreate(GDALGetDriverByName("VRT"), out.temp_path().c_str(), static_cast<int>(spec.cols),
                   static_cast<int>(spec.rows), 0, GDT_Float32, nullptr);
    if (vrt == nullptr) {
        throw_gdal("cannot create " + target.string());
    }
    std::vector<GDALDatasetH> sources;
    const auto close_all = [&] {
        GDALClose(vrt);  // writes the VRT, then lets go of the sources
        for (GDALDatasetH ds : sources) GDALClose(ds);
    };
    try {
        double transform[6] = {spec.xmin, spec.cell, 0.0, spec.ymax, 0.0, -spec.cell};
        GDALSetGeoTransform(vrt, transform);
        if (!options.crs_wkt.empty()) GDALSetProjection(vrt, options.crs_wkt.c_str());
        GDALAddBand(vrt, GDT_Float32, nullptr);
        GDALRasterBandH band = GDALGetRasterBand(vrt, 1);
        GDALSetRasterNoDataValue(band, static_cast<double>(options.nodata));
        for (const DemTile& tile : tiles) {
            // Opened by the path the VRT will name, relative to it when beside it.
            GDALDatasetH ds = GDALOpen(tile.file.c_str(), GA_ReadOnly);
            if (ds == nullptr) throw_gdal("cannot open the DEM tile " + tile.file.string());
            sources.push_back(ds);
            const int cols = static_cast<int>(spec.cols), rows = static_cast<int>(tile.rows);
            if (VRTAddSimpleSource(static_cast<VRTSourcedRasterBandH>(band),
                                   GDALGetRasterBand(ds, 1), 0, 0, cols, rows, 0,
                                   static_cast<int>(tile.first_row), cols, rows, "near",
                                   VRT_NODATA_UNSET) != CE_None) {
                throw_gdal("cannot add " + tile.file.string() + " to " + target.string());
            }
        }
    } catch (...) {
        close_all();
        throw;
    }
    close_all();
    out.commit();
}

}  // namespace dtm::io
