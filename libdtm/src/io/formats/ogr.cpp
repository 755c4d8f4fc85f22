// SPDX-License-Identifier: MIT
// OGR vector sources as terrain input: every feature's geometry is flattened into points,
// polylines (open or closed rings) and hole seeds according to the role of the input file.
// Curves are linearised with OGR's defaults. Heights come from the vertices, or from one
// attribute per feature (ReadOptions::z_field, e.g. contour lines as input).
#include "dtm/io/formats/ogr.hpp"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/formats/crs.hpp"
#include "io/detail/gdal_drivers.hpp"
#include "io/formats/ogr_range.hpp"

namespace dtm::io {
namespace {

constexpr double no_z = std::numeric_limits<double>::quiet_NaN();

struct DatasetCloser {
    void operator()(GDALDataset* d) const noexcept { GDALClose(d); }
};
using DatasetPtr = std::unique_ptr<GDALDataset, DatasetCloser>;

struct FeatureDeleter {
    void operator()(OGRFeature* f) const noexcept { OGRFeature::DestroyFeature(f); }
};
using FeaturePtr = std::unique_ptr<OGRFeature, FeatureDeleter>;

std::string last_gdal_error() {
    const std::string msg = CPLGetLastErrorMsg();
    return msg.empty() ? std::string("GDAL gave no reason") : msg;
}

DatasetPtr open_vector(const std::filesystem::path& path) {
    detail::register_gdal_drivers();
    const char* const open_options[] = {"GEOM_POSSIBLE_NAMES=WKT,geometry,the_geom,geom,wkt_geom",
                                        "KEEP_GEOM_COLUMNS=NO", nullptr};
    // A .dxf is read by GDAL's DXF driver only: any other driver would take a drawing whose text
    // happens to look like its format (the DXF fuzzer led GDAL's OpenJUMP driver, which leaks on
    // such input, to a drawing with "<JCSDataFile" in it).
    const char* const dxf_only[] = {"DXF", nullptr};
    const char* const* drivers = lower_extension(path) == "dxf" ? dxf_only : nullptr;
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    auto* ds = static_cast<GDALDataset*>(GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY,
                                                    drivers, open_options, nullptr));
    CPLPopErrorHandler();
    if (ds == nullptr) {
        throw InputError(path, 0, 0,
                         "expected a vector file GDAL/OGR can read: " + last_gdal_error());
    }
    return DatasetPtr(ds);
}

/// Collects geometries of one file into a ReadResult according to the role.
class OgrCollector {
public:
    OgrCollector(const InputFile& file, ReadResult& result) : file_(file), result_(result) {}

    void add(const OGRGeometry& g, double z_override, const std::string& source);
    void finish_warnings();

private:
    void add_point(const OGRPoint& p, double z_override, const std::string& source);
    void add_curve(const OGRSimpleCurve& c,
                   double z_override,
                   const std::string& source,
                   bool ring,
                   bool inner);
    void add_polygon(const OGRPolygon& p, double z_override, const std::string& source);
    void push_line(Polyline line, bool ring, bool inner);

    const InputFile& file_;
    ReadResult& result_;
    std::size_t ignored_points_ = 0;
    std::size_t ignored_inner_ = 0;
    std::size_t open_rings_ = 0;
};

void OgrCollector::add_point(const OGRPoint& p, double z_override, const std::string& source) {
    if (p.IsEmpty()) return;
    const double z = !std::isnan(z_override) ? z_override : (p.Is3D() ? p.getZ() : no_z);
    switch (file_.role) {
        case InputRole::points:
            if (std::isnan(z)) {
                throw InputError(file_.path, 0, 0,
                                 source +
                                     ": expected a point with a height (PointZ, or give "
                                     "`z_field` NAME), found a 2-D point");
            }
            result_.terrain.points.push_back({p.getX(), p.getY(), z});
            break;
        case InputRole::holes:
            result_.terrain.hole_seeds.push_back({p.getX(), p.getY()});
            break;
        default:
            ++ignored_points_;
            break;
    }
}

void OgrCollector::push_line(Polyline line, bool ring, bool inner) {
    TerrainInput& t = result_.terrain;
    switch (file_.role) {
        case InputRole::points:
        case InputRole::breaklines:
            t.breaklines.push_back(std::move(line));
            break;
        case InputRole::soft_breaklines:
            t.soft_breaklines.push_back(std::move(line));
            break;
        case InputRole::boundary:
            (inner ? t.holes : t.boundaries).push_back(std::move(line));
            break;
        case InputRole::holes:
            if (inner) {
                ++ignored_inner_;
            } else {
                t.holes.push_back(std::move(line));
            }
            break;
    }
    (void)ring;
}

void OgrCollector::add_curve(
    const OGRSimpleCurve& c, double z_override, const std::string& source, bool ring, bool inner) {
    Polyline line;
    line.source = source;
    const int n = c.getNumPoints();
    line.points.reserve(static_cast<std::size_t>(std::max(n, 0)));
    for (int i = 0; i < n; ++i) {
        const double z = !std::isnan(z_override) ? z_override : (c.Is3D() ? c.getZ(i) : no_z);
        line.points.push_back({c.getX(i), c.getY(i), z});
    }
    const bool wants_ring = file_.role == InputRole::boundary || file_.role == InputRole::holes;
    if (line.points.size() >= 3 && line.points.front().xy() == line.points.back().xy()) {
        line.points.pop_back();
        line.closed = true;
    } else if (ring || wants_ring) {
        if (wants_ring && !ring) ++open_rings_;
        line.closed = true;
    }
    if (line.points.size() < (line.closed ? 3u : 2u)) {
        result_.summary.warnings.push_back(source + ": a geometry with " + std::to_string(n) +
                                           " vertices is too short and was not used");
        return;
    }
    push_line(std::move(line), ring, inner);
}

void OgrCollector::add_polygon(const OGRPolygon& p, double z_override, const std::string& source) {
    if (p.IsEmpty()) return;
    add_curve(*p.getExteriorRing(), z_override, source, true, false);
    for (int i = 0; i < p.getNumInteriorRings(); ++i) {
        add_curve(*p.getInteriorRing(i), z_override,
                  source + " inner ring " + std::to_string(i + 1), true, true);
    }
}

void OgrCollector::add(const OGRGeometry& g, double z_override, const std::string& source) {
    const OGRwkbGeometryType type = wkbFlatten(g.getGeometryType());
    if (type == wkbPoint) {
        add_point(*g.toPoint(), z_override, source);
    } else if (type == wkbLineString || type == wkbLinearRing) {
        add_curve(*g.toSimpleCurve(), z_override, source, false, false);
    } else if (type == wkbPolygon) {
        add_polygon(*g.toPolygon(), z_override, source);
    } else if (OGR_GT_IsSubClassOf(type, wkbGeometryCollection)) {
        const OGRGeometryCollection& c = *g.toGeometryCollection();
        for (int i = 0; i < c.getNumGeometries(); ++i)
            add(*c.getGeometryRef(i), z_override, source);
    } else if (OGR_GT_IsCurve(type) || OGR_GT_IsSurface(type)) {
        std::unique_ptr<OGRGeometry> linear(g.getLinearGeometry());
        if (linear) add(*linear, z_override, source);
    } else {
        result_.summary.warnings.push_back(source + ": geometry type " +
                                           OGRGeometryTypeToName(g.getGeometryType()) +
                                           " is not used");
    }
}

void OgrCollector::finish_warnings() {
    if (ignored_points_ > 0) {
        result_.summary.warnings.push_back(std::to_string(ignored_points_) +
                                           " point geometries are not used in a line input");
    }
    if (ignored_inner_ > 0) {
        result_.summary.warnings.push_back(std::to_string(ignored_inner_) +
                                           " inner rings of hole polygons (islands) are not used");
    }
    if (open_rings_ > 0) {
        result_.summary.warnings.push_back(std::to_string(open_rings_) +
                                           " open lines were closed to make rings");
    }
}

double feature_z(const OGRFeature& f, int z_index, const InputFile& file, const std::string& src) {
    if (z_index < 0) return no_z;
    if (!f.IsFieldSetAndNotNull(z_index)) {
        throw InputError(file.path, 0, 0, src + ": expected a height in the `z_field`, found none");
    }
    return f.GetFieldAsDouble(z_index);
}

int z_field_index(OGRLayer& layer, const ReadOptions& options, const InputFile& file) {
    if (options.z_field.empty()) return -1;
    const int index = layer.GetLayerDefn()->GetFieldIndex(options.z_field.c_str());
    if (index >= 0) return index;
    std::string names;
    for (int i = 0; i < layer.GetLayerDefn()->GetFieldCount(); ++i) {
        names += (i ? ", " : "") + std::string(layer.GetLayerDefn()->GetFieldDefn(i)->GetNameRef());
    }
    throw InputError(file.path, 0, 0,
                     "`z_field`: expected a field named '" + options.z_field + "' in layer '" +
                         layer.GetName() + "', found: " + (names.empty() ? "no fields" : names));
}

void read_layer(OGRLayer& layer,
                const InputFile& file,
                const ReadOptions& options,
                OgrCollector& collector,
                const Progress& progress,
                detail::FeatureRange& range) {
    if (!options.where.empty()) {
        CPLErrorReset();
        CPLPushErrorHandler(CPLQuietErrorHandler);
        const OGRErr err = layer.SetAttributeFilter(options.where.c_str());
        CPLPopErrorHandler();
        if (err != OGRERR_NONE) {
            throw InputError(file.path, 0, 0,
                             "`where`: expected an attribute filter for layer '" +
                                 std::string(layer.GetName()) + "': " + last_gdal_error());
        }
    }
    const int z_index = z_field_index(layer, options, file);
    layer.ResetReading();
    std::size_t count = 0;
    CPLErrorReset();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    struct PopHandler {
        ~PopHandler() { CPLPopErrorHandler(); }
    } pop;
    // A range (a distributed run's share) skips to its first feature of this layer.
    std::uint64_t skip = 0;
    if (range.restricted()) {
        const auto n =
            static_cast<std::uint64_t>(std::max<GIntBig>(0, layer.GetFeatureCount(TRUE)));
        const std::uint64_t at = range.position;
        range.position += n;
        if (at + n <= range.first || at >= range.last) return;
        skip = range.first > at ? range.first - at : 0;
        if (skip > 0 && layer.SetNextByIndex(static_cast<GIntBig>(skip)) == OGRERR_NONE) {
            range.position = at + skip;
            skip = 0;
        } else {
            layer.ResetReading();
            range.position = at;
        }
    }
    while (!range.restricted() || range.position < range.last) {
        FeaturePtr f{layer.GetNextFeature()};
        if (!f) break;
        if ((++count & 1023u) == 0) progress.check();
        const std::uint64_t position = range.position++;
        if (skip > 0) {
            --skip;
            continue;
        }
        const OGRGeometry* g = f->GetGeometryRef();
        if (g == nullptr) continue;
        const std::string source = file.path.string() + ": layer '" + layer.GetName() +
                                   "' feature " + std::to_string(f->GetFID());
        range.failed_at = position;
        collector.add(*g, feature_z(*f, z_index, file, source), source);
        range.failed_at = detail::FeatureRange::none;
    }
    if (CPLGetLastErrorType() >= CE_Failure) {
        throw InputError(file.path, 0, 0,
                         std::string("reading layer '") + layer.GetName() + "' failed" +
                             (options.where.empty() ? "" : " (check `where`)") + ": " +
                             last_gdal_error());
    }
}

}  // namespace

ReadResult read_ogr(const InputFile& file, const ReadOptions& options, const Progress& progress) {
    detail::FeatureRange all;
    return detail::read_ogr_range(file, options, progress, all);
}

ReadResult detail::read_ogr_range(const InputFile& file,
                                  const ReadOptions& options,
                                  const Progress& progress,
                                  FeatureRange& range) {
    DatasetPtr ds = open_vector(file.path);
    ReadResult result;
    result.summary.path = file.path;
    result.summary.format = std::string("OGR ") + ds->GetDriver()->GetDescription();
    std::vector<OGRLayer*> layers;
    if (!options.layer.empty()) {
        OGRLayer* layer = ds->GetLayerByName(options.layer.c_str());
        if (layer == nullptr) {
            std::string names;
            for (OGRLayer* l : ds->GetLayers())
                names += (names.empty() ? "" : ", ") + std::string(l->GetName());
            throw InputError(file.path, 0, 0,
                             "`layer`: expected one of the layers (" + names + "), found '" +
                                 options.layer + "'");
        }
        layers.push_back(layer);
    } else {
        for (OGRLayer* l : ds->GetLayers()) layers.push_back(l);
    }
    OgrCollector collector(file, result);
    for (std::size_t i = 0; i < layers.size(); ++i) {
        const double n = static_cast<double>(layers.size());
        read_layer(*layers[i], file, options, collector,
                   progress.sub(static_cast<double>(i) / n, static_cast<double>(i + 1) / n), range);
        const OGRSpatialReference* srs = layers[i]->GetSpatialRef();
        if (srs != nullptr && result.crs_wkt.empty()) result.crs_wkt = srs_to_wkt(*srs);
    }
    collector.finish_warnings();
    result.summary.crs = crs_label(result.crs_wkt);
    return result;
}

std::uint64_t detail::ogr_feature_count(const InputFile& file, const ReadOptions& options) {
    FeatureRange count;  // a range past every feature: each layer only counted
    count.first = FeatureRange::none - 1;
    count.last = FeatureRange::none - 1;
    (void)read_ogr_range(file, options, {}, count);
    return count.position;
}

ReadResult read_ogr_text(const InputFile& file,
                         const ReadOptions& options,
                         const Progress& progress) {
    ReadResult result = read_ogr(file, options, progress);
    result.summary.format = "text (OGR, geometry column)";
    return result;
}

}  // namespace dtm::io
