// SPDX-License-Identifier: MIT
// `dtm voronoi` (dtm/io/voronoi_cells.hpp): the distinct survey points, their Delaunay
// triangulation (the production kernel), the clip region (the boundary rings minus the holes,
// triangulated by the kernel, or the convex hull), the Thiessen polygons (algo/thiessen), and
// one MultiPolygon feature per point through OGR (GeoPackage, shapefile, GeoJSON by extension),
// written inside transactions of 50 000 features into a temporary sibling that replaces the
// target only when everything is written.
#include <cpl_error.h>
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <mutex>
#include <numeric>
#include <string>

#include "algo/detail/exact_duplicates.hpp"
#include "dtm/algo/thiessen.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/voronoi_cells.hpp"

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

/// The Delaunay triangulation of the distinct sites (vertex i = site i), or no triangles when
/// they are collinear or fewer than three.
Tin delaunay_of(const std::vector<Point3>& sites, unsigned threads, const Progress& progress) {
    if (sites.size() >= 3) {
        TriangulateOptions options;
        options.threads = threads;
        try {
            return triangulate(TerrainInput{sites, {}, {}, {}, {}, {}}, options, progress).tin;
        } catch (const InputError&) {
            // collinear: the Voronoi regions are parallel strips; no triangle
        }
    }
    Tin t;
    t.vertices = sites;
    return t;
}

class Writer {
public:
    Writer(const fs::path& target,
           const std::string& crs_wkt,
           const std::string& layer_name,
           bool string_ids)
        : out_(target) {
        const Format& format = format_for(target);
        static std::once_flag once;
        std::call_once(once, [] { GDALAllRegister(); });
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
    Writer(const Writer&) = delete;
    Writer& operator=(const Writer&) = delete;
    ~Writer() {
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

private:
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

}  // namespace

std::vector<std::string> voronoi_extensions() {
    std::vector<std::string> out;
    for (const Format& f : formats) out.emplace_back(f.extension);
    return out;
}

VoronoiCellsReport write_voronoi_cells(const LoadedInputs& inputs,
                                       const fs::path& output,
                                       const VoronoiCellsOptions& options,
                                       const Progress& progress) {
    (void)format_for(output);  // an unknown extension fails before any work
    const TerrainInput& terrain = inputs.terrain;
    if (!terrain.breaklines.empty() || !terrain.soft_breaklines.empty()) {
        throw UsageError(
            "voronoi: breaklines make no Thiessen polygons (give points, and a boundary or holes)");
    }
    const std::vector<Point3>& points = inputs.tin ? inputs.tin->vertices : terrain.points;
    if (points.empty()) throw InputError("voronoi: the inputs hold no point");
    VoronoiCellsReport report;
    report.points = points.size();
    report.boundary = !terrain.boundaries.empty();
    // Distinct sites in input order; a duplicate's cell is its first point's.
    const std::vector<VertexIndex> first = dtm::detail::first_occurrences(points);
    std::vector<Point3> sites;
    std::vector<std::size_t> site_input;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (first[i] != i) continue;
        sites.push_back(points[i]);
        site_input.push_back(i);
    }
    report.duplicates = points.size() - sites.size();
    progress.report(0.0, "triangulating");
    const Tin delaunay = delaunay_of(sites, options.threads, progress.sub(0.0, 0.3));
    const Tin region = report.boundary ? clip_region_of_rings(terrain.boundaries, terrain.holes)
                                       : clip_region_of_hull(delaunay);
    const ThiessenResult cells = thiessen_cells(sites, delaunay, region, progress.sub(0.3, 0.85));
    report.region_area = cells.region_area;
    report.empty_cells = cells.empty_cells;

    const std::vector<std::string>& ids = inputs.labels.ids;
    const bool string_ids =
        std::any_of(ids.begin(), ids.end(), [](const std::string& s) { return !s.empty(); });
    Writer writer(output, inputs.crs_wkt, options.layer, string_ids);
    for (std::size_t s = 0; s < sites.size(); ++s) {
        if ((s & 0xffffu) == 0)
            progress.report(0.85 + 0.15 * double(s) / double(sites.size()), "writing");
        const ThiessenCell& cell = cells.cells[s];
        if (cell.polygons.empty()) continue;
        const std::size_t i = site_input[s];
        const std::string id = i < ids.size() && !ids[i].empty() ? ids[i] : std::to_string(i);
        writer.add(cell, id, i, sites[s].z);
        ++report.cells;
        report.cells_area += cell.area;
    }
    writer.commit();
    progress.report(1.0, "written");
    return report;
}

}  // namespace dtm::io
