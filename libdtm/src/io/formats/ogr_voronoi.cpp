// SPDX-License-Identifier: MIT
// Thiessen polygons through OGR (dtm/io/voronoi_writer.hpp): one MultiPolygon feature per point
// (GeoPackage, shapefile, GeoJSON by extension) with id, index, z and area, written inside
// transactions of 50 000 features into a temporary sibling that replaces the target only when
// everything is written.
#include <cpl_error.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/voronoi_writer.hpp"
#include "io/detail/gdal_drivers.hpp"

namespace dtm::io {
namespace fs = std::filesystem;
namespace {

struct Format {
    const char* extension;
    const char* driver;
};
constexpr std::array<Format, 4> formats{
    {{"gpkg", "GPKG"}, {"shp", "ESRI Shapefile"}, {"geojson", "GeoJSON"}, {"json", "GeoJSON"}}};

const Format& format_for(const fs::path& target) {
    std::string ext = target.extension().string();
    ext.erase(0, std::min<std::size_t>(1, ext.size()));
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const Format& f : formats) {
        if (ext == f.extension) return f;
    }
    throw UsageError("voronoi: cannot write '." + ext + "' (" + target.string() +
                     "); use .gpkg, .shp or .geojson");
}

[[noreturn]] void throw_ogr(const std::string& what) {
    throw Error("voronoi: " + what + ": " + CPLGetLastErrorMsg());
}

}  // namespace

struct VoronoiCellWriter::State {
public:
    State(const fs::path& target,
          const std::string& crs_wkt,
          const std::string& layer_name,
          bool string_ids)
        : out_(target) {
        const Format& format = format_for(target);
        detail::register_gdal_drivers();
        GDALDriverH driver = GDALGetDriverByName(format.driver);
        if (driver == nullptr) {
            throw Error(std::string("voronoi: the GDAL driver ") + format.driver +
                        " is not available");
        }
        ds_ = GDALCreate(driver, out_.temp_path().c_str(), 0, 0, 0, GDT_Unknown, nullptr);
        if (ds_ == nullptr) throw_ogr("cannot create " + target.string());
        if (!crs_wkt.empty()) {
            srs_ = OSRNewSpatialReference(crs_wkt.c_str());
            if (srs_ == nullptr) throw_ogr("the CRS is not valid WKT");
            OSRSetAxisMappingStrategy(srs_, OAMS_TRADITIONAL_GIS_ORDER);
        }
        const bool shapefile = std::string_view(format.driver) == "ESRI Shapefile";
        const std::string name = shapefile ? out_.temp_path().stem().string() : layer_name;
        layer_ = GDALDatasetCreateLayer(ds_, name.c_str(), srs_, wkbMultiPolygon, nullptr);
        if (layer_ == nullptr) throw_ogr("cannot create the layer in " + target.string());
        id_ = field("id", string_ids ? OFTString : OFTInteger64);
        index_ = field("index", OFTInteger64);
        z_ = field("z", OFTReal);
        area_ = field("area", OFTReal);
    }
    State(const State&) = delete;
    State& operator=(const State&) = delete;
    ~State() {
        if (ds_ != nullptr) GDALClose(ds_);
        if (srs_ != nullptr) OSRDestroySpatialReference(srs_);
    }

    void add(const ThiessenCell& cell, const std::string& id, std::size_t index, double z) {
        if (!in_transaction_)
            in_transaction_ = GDALDatasetStartTransaction(ds_, FALSE) == OGRERR_NONE;
        OGRFeatureH f = OGR_F_Create(OGR_L_GetLayerDefn(layer_));
        if (OGR_Fld_GetType(OGR_FD_GetFieldDefn(OGR_L_GetLayerDefn(layer_), id_)) == OFTString) {
            OGR_F_SetFieldString(f, id_, id.c_str());
        } else {
            OGR_F_SetFieldInteger64(f, id_, static_cast<GIntBig>(index));
        }
        OGR_F_SetFieldInteger64(f, index_, static_cast<GIntBig>(index));
        OGR_F_SetFieldDouble(f, z_, z);
        OGR_F_SetFieldDouble(f, area_, cell.area);
        OGRGeometryH multi = OGR_G_CreateGeometry(wkbMultiPolygon);
        for (const ThiessenPolygon& polygon : cell.polygons) {
            OGRGeometryH poly = OGR_G_CreateGeometry(wkbPolygon);
            for (const auto& ring : polygon.rings) {
                OGRGeometryH r = OGR_G_CreateGeometry(wkbLinearRing);
                OGR_G_SetPointCount(r, static_cast<int>(ring.size() + 1));
                for (std::size_t i = 0; i <= ring.size(); ++i) {
                    const Point2& p = ring[i % ring.size()];
                    OGR_G_SetPoint_2D(r, static_cast<int>(i), p.x, p.y);
                }
                OGR_G_AddGeometryDirectly(poly, r);
            }
            OGR_G_AddGeometryDirectly(multi, poly);
        }
        OGR_F_SetGeometryDirectly(f, multi);
        const OGRErr err = OGR_L_CreateFeature(layer_, f);
        OGR_F_Destroy(f);
        if (err != OGRERR_NONE)
            throw_ogr("cannot write the cell of point " + std::to_string(index));
        if (in_transaction_ && ++features_ % 50'000 == 0) {
            if (GDALDatasetCommitTransaction(ds_) != OGRERR_NONE) throw_ogr("cannot write");
            in_transaction_ = false;
        }
    }

    void commit() {
        if (in_transaction_ && GDALDatasetCommitTransaction(ds_) != OGRERR_NONE)
            throw_ogr("cannot write");
        CPLErrorReset();
        GDALClose(ds_);
        ds_ = nullptr;
        if (CPLGetLastErrorType() >= CE_Failure)
            throw_ogr("cannot write " + out_.target().string());
        out_.commit();
    }

    AtomicOutput out_;
    GDALDatasetH ds_ = nullptr;
    OGRSpatialReferenceH srs_ = nullptr;
    OGRLayerH layer_ = nullptr;
    int id_ = -1, index_ = -1, z_ = -1, area_ = -1;
    bool in_transaction_ = false;
    std::size_t features_ = 0;

    int field(const char* name, OGRFieldType type) {
        OGRFieldDefnH f = OGR_Fld_Create(name, type);
        const OGRErr err = OGR_L_CreateField(layer_, f, TRUE);
        OGR_Fld_Destroy(f);
        if (err != OGRERR_NONE) throw_ogr(std::string("cannot create the field ") + name);
        return OGR_FD_GetFieldIndex(OGR_L_GetLayerDefn(layer_), name);
    }
};

std::vector<std::string> VoronoiCellWriter::extensions() {
    std::vector<std::string> out;
    for (const Format& f : formats) out.emplace_back(f.extension);
    return out;
}

VoronoiCellWriter::VoronoiCellWriter(const fs::path& target, const VoronoiWriterOptions& options)
    : state_(std::make_unique<State>(target, options.crs_wkt, options.layer, options.string_ids)) {}

VoronoiCellWriter::~VoronoiCellWriter() = default;

void VoronoiCellWriter::add(const ThiessenCell& cell,
                            const std::string& id,
                            std::size_t index,
                            double z) {
    state_->add(cell, id, index, z);
}

void VoronoiCellWriter::commit() { state_->commit(); }

std::size_t VoronoiCellWriter::feature_count() const noexcept { return state_->features_; }

void VoronoiCellWriter::check_extension(const fs::path& target) { (void)format_for(target); }

}  // namespace dtm::io
