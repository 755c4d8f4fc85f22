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
#include <memory>
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

namespace {

struct CloseDataset {
    void operator()(void* ds) const { GDALClose(ds); }
};
using DatasetPtr = std::unique_ptr<void, CloseDataset>;

/// GDALDEMProcessing of @p src into @p path with @p driver (MEM: in memory, no path), edges
/// computed; GeoTIFFs tiled and DEFLATE-compressed. @throws Error naming @p dem
DatasetPtr dem_processing(const std::string& path,
                          GDALDatasetH src,
                          DemDerivative kind,
                          const std::string& driver,
                          const fs::path& dem) {
    Options args;
    args.arg("-of").arg(driver).arg("-compute_edges");
    if (driver == "GTiff") {
        args.arg("-co").arg("TILED=YES").arg("-co").arg("COMPRESS=DEFLATE");
    }
    GDALDEMProcessingOptions* options = GDALDEMProcessingOptionsNew(args.get(), nullptr);
    int usage_error = FALSE;
    CPLErrorReset();
    DatasetPtr result(GDALDEMProcessing(path.c_str(), src, dem_derivative_name(kind), nullptr,
                                        options, &usage_error));
    GDALDEMProcessingOptionsFree(options);
    if (!result) {
        throw_gdal(std::string("cannot compute the ") + dem_derivative_name(kind) + " of " +
                   dem.string());
    }
    return result;
}

/// gdal_translate of the whole columns, rows [first, first + rows) of @p src into @p path.
DatasetPtr row_window(const std::string& path,
                      GDALDatasetH src,
                      const char* driver,
                      std::size_t first,
                      std::size_t rows) {
    Options args;
    args.arg("-of").arg(driver).arg("-srcwin").arg("0").arg(std::to_string(first));
    args.arg(std::to_string(GDALGetRasterXSize(src))).arg(std::to_string(rows));
    if (std::string(driver) == "GTiff") {
        args.arg("-co").arg("TILED=YES").arg("-co").arg("COMPRESS=DEFLATE");
    }
    GDALTranslateOptions* options = GDALTranslateOptionsNew(args.get(), nullptr);
    CPLErrorReset();
    DatasetPtr window(GDALTranslate(path.c_str(), src, options, nullptr));
    GDALTranslateOptionsFree(options);
    return window;
}

}  // namespace

const char* dem_derivative_name(DemDerivative kind) noexcept {
    return kind == DemDerivative::hillshade ? "hillshade"
           : kind == DemDerivative::slope   ? "slope"
                                            : "aspect";
}

void write_dem_derivative(const fs::path& dem, const fs::path& target, DemDerivative kind) {
    const std::string driver = raster_driver_for(target);
    DatasetPtr src(GDALOpen(dem.c_str(), GA_ReadOnly));
    if (!src) {
        throw_gdal("cannot open " + dem.string());
    }
    AtomicOutput out(target);
    DatasetPtr result = dem_processing(out.temp_path().string(), src.get(), kind, driver, dem);
    src.reset();
    // GDAL reports a failed write (full disk, file-size limit) as an error and still returns
    // the dataset: the error, not the pointer, says whether the file is whole.
    result.reset();
    if (CPLGetLastErrorType() >= CE_Failure) {
        throw_gdal(std::string("cannot write the ") + dem_derivative_name(kind) + " " +
                   target.string());
    }
    if (driver == "GTiff") check_geotiff_blocks(out.temp_path(), target);
    out.commit();
}

void write_dem_derivative_rows(const fs::path& dem,
                               const fs::path& target,
                               DemDerivative kind,
                               std::size_t first_row,
                               std::size_t rows) {
    register_gdal();
    DatasetPtr src(GDALOpen(dem.c_str(), GA_ReadOnly));
    if (!src) {
        throw_gdal("cannot open " + dem.string());
    }
    const auto height = static_cast<std::size_t>(GDALGetRasterYSize(src.get()));
    if (rows == 0 || first_row > height || rows > height - first_row) {
        throw Error("grid: rows " + std::to_string(first_row) + " + " + std::to_string(rows) +
                    " are not within the " + std::to_string(height) + " rows of " + dem.string());
    }
    // Each cell of a derivative is a function of its 3 x 3 neighbourhood (the raster's edge
    // rows extrapolated, -compute_edges): the rows and one more on each side that exists give
    // the whole raster's cells.
    const std::size_t lo = first_row > 0 ? first_row - 1 : 0;
    const std::size_t hi = std::min(height, first_row + rows + 1);
    const DatasetPtr window = row_window("", src.get(), "VRT", lo, hi - lo);
    if (!window) throw_gdal("cannot read rows of " + dem.string());
    const DatasetPtr derived = dem_processing("", window.get(), kind, "MEM", dem);
    AtomicOutput out(target);
    DatasetPtr tile =
        row_window(out.temp_path().string(), derived.get(), "GTiff", first_row - lo, rows);
    const bool failed = !tile || CPLGetLastErrorType() >= CE_Failure;
    tile.reset();  // a failed write shows as an error once the file is closed, too
    if (failed || CPLGetLastErrorType() >= CE_Failure) {
        throw_gdal(std::string("cannot write the ") + dem_derivative_name(kind) + " " +
                   target.string());
    }
    check_geotiff_blocks(out.temp_path(), target);
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

namespace {

/// A VRT of @p spec mosaicking @p tiles at their rows (integer offsets: no resampling); the
/// band's type, and its NoData unless @p nodata is given, are the first tile's.
void write_mosaic_vrt(const fs::path& target,
                      const GridSpec& spec,
                      const std::vector<DemTile>& tiles,
                      const std::string& crs_wkt,
                      std::optional<double> nodata) {
    register_gdal();
    std::vector<DatasetPtr> sources;
    for (const DemTile& tile : tiles) {
        // Opened by the path the VRT will name, relative to it when beside it.
        sources.emplace_back(GDALOpen(tile.file.c_str(), GA_ReadOnly));
        if (!sources.back()) throw_gdal("cannot open the tile " + tile.file.string());
    }
    GDALDataType type = GDT_Float32;
    if (!sources.empty()) {
        GDALRasterBandH first = GDALGetRasterBand(sources.front().get(), 1);
        type = GDALGetRasterDataType(first);
        int has = FALSE;
        const double value = GDALGetRasterNoDataValue(first, &has);
        if (!nodata && has) nodata = value;
    }
    AtomicOutput out(target);
    DatasetPtr vrt(GDALCreate(GDALGetDriverByName("VRT"), out.temp_path().c_str(),
                              static_cast<int>(spec.cols), static_cast<int>(spec.rows), 0, type,
                              nullptr));
    if (!vrt) throw_gdal("cannot create " + target.string());
    double transform[6] = {spec.xmin, spec.cell, 0.0, spec.ymax, 0.0, -spec.cell};
    GDALSetGeoTransform(vrt.get(), transform);
    if (!crs_wkt.empty()) GDALSetProjection(vrt.get(), crs_wkt.c_str());
    GDALAddBand(vrt.get(), type, nullptr);
    GDALRasterBandH band = GDALGetRasterBand(vrt.get(), 1);
    if (nodata) GDALSetRasterNoDataValue(band, *nodata);
    for (std::size_t i = 0; i < tiles.size(); ++i) {
        const int cols = static_cast<int>(spec.cols), rows = static_cast<int>(tiles[i].rows);
        if (VRTAddSimpleSource(static_cast<VRTSourcedRasterBandH>(band),
                               GDALGetRasterBand(sources[i].get(), 1), 0, 0, cols, rows, 0,
                               static_cast<int>(tiles[i].first_row), cols, rows, "near",
                               VRT_NODATA_UNSET) != CE_None) {
            throw_gdal("cannot add " + tiles[i].file.string() + " to " + target.string());
        }
    }
    vrt.reset();  // writes the VRT, before the sources are let go
    out.commit();
}

}  // namespace

void write_dem_vrt(const fs::path& target,
                   const GridSpec& spec,
                   const std::vector<DemTile>& tiles,
                   const GridWriteOptions& options) {
    write_mosaic_vrt(target, spec, tiles, options.crs_wkt, static_cast<double>(options.nodata));
}

void write_derivative_vrt(const fs::path& target,
                          const GridSpec& spec,
                          const std::vector<DemTile>& tiles,
                          const std::string& crs_wkt) {
    write_mosaic_vrt(target, spec, tiles, crs_wkt, std::nullopt);
}

}  // namespace dtm::io
