// SPDX-License-Identifier: MIT
// Analysis layers through OGR (GDAL's C++ vector API): one dataset, several layers, features in
// transactions of 50 000 (a GeoPackage is SQLite: a transaction per feature would be slow).
#include "dtm/io/formats/vector_file.hpp"

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <array>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/extension.hpp"
#include "io/detail/gdal_drivers.hpp"

namespace dtm::io {
namespace fs = std::filesystem;
namespace {

struct Format {
    const char* extension;
    const char* driver;
};
constexpr std::array<Format, 6> formats{{{"gpkg", "GPKG"},
                                         {"shp", "ESRI Shapefile"},
                                         {"geojson", "GeoJSON"},
                                         {"json", "GeoJSON"},
                                         {"kml", "KML"},
                                         {"fgb", "FlatGeobuf"}}};

[[noreturn]] void fail(const std::string& what) {
    throw Error("vector output: " + what + ": " + CPLGetLastErrorMsg());
}

}  // namespace

struct VectorFile::State {
    AtomicOutput out;
    GDALDataset* ds = nullptr;
    OGRSpatialReference* srs = nullptr;
    std::vector<OGRLayer*> layers;
    long long pending = 0;
    bool in_transaction = false;

    explicit State(const fs::path& target) : out(target) {}
    ~State() {
        if (ds != nullptr) {
            GDALClose(ds);
        }
        if (srs != nullptr) {
            srs->Release();
        }
    }
    void begin() {
        if (!in_transaction) {
            in_transaction = ds->StartTransaction() == OGRERR_NONE;
        }
    }
    void add(std::size_t layer, OGRGeometry* geometry, const std::vector<FieldValue>& values) {
        begin();
        OGRLayer* l = layers.at(layer);
        OGRFeature* f = OGRFeature::CreateFeature(l->GetLayerDefn());
        for (std::size_t i = 0; i < values.size(); ++i) {
            const int k = static_cast<int>(i);
            if (const auto* d = std::get_if<double>(&values[i])) {
                f->SetField(k, *d);
            } else if (const auto* n = std::get_if<long long>(&values[i])) {
                f->SetField(k, static_cast<GIntBig>(*n));
            } else {
                f->SetField(k, std::get<std::string>(values[i]).c_str());
            }
        }
        f->SetGeometryDirectly(geometry);
        const OGRErr err = l->CreateFeature(f);
        OGRFeature::DestroyFeature(f);
        if (err != OGRERR_NONE) {
            fail("cannot write a feature to " + out.target().string());
        }
        if (++pending >= 50'000 && in_transaction) {
            ds->CommitTransaction();
            in_transaction = false;
            pending = 0;
        }
    }
};

VectorFile::VectorFile(const fs::path& target, const std::string& crs_wkt) {
    detail::register_gdal_drivers();
    const std::string ext = lower_extension(target);
    const Format* format = nullptr;
    for (const Format& f : formats) {
        if (ext == f.extension) {
            format = &f;
        }
    }
    if (format == nullptr) {
        throw UsageError("cannot write vectors to '." + ext + "' (" + target.string() +
                         "); use .gpkg, .shp, .geojson, .kml or .fgb");
    }
    state_ = std::make_unique<State>(target);
    GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(format->driver);
    if (driver == nullptr) {
        throw Error(std::string("vector output: the GDAL driver ") + format->driver +
                    " is not available");
    }
    state_->ds = driver->Create(state_->out.temp_path().c_str(), 0, 0, 0, GDT_Unknown, nullptr);
    if (state_->ds == nullptr) {
        fail("cannot create " + target.string());
    }
    if (!crs_wkt.empty()) {
        state_->srs = new OGRSpatialReference();
        state_->srs->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
        if (state_->srs->importFromWkt(crs_wkt.c_str()) != OGRERR_NONE) {
            fail("the CRS is not valid WKT");
        }
    }
}

VectorFile::~VectorFile() = default;

std::size_t VectorFile::add_layer(const std::string& name,
                                  VectorGeometry geometry,
                                  const std::vector<VectorField>& fields) {
    State& s = *state_;
    const OGRwkbGeometryType type = geometry == VectorGeometry::polygon   ? wkbPolygon
                                    : geometry == VectorGeometry::line_3d ? wkbLineString25D
                                                                          : wkbPoint25D;
    OGRLayer* layer = s.ds->CreateLayer(name.c_str(), s.srs, type, nullptr);
    if (layer == nullptr) {
        fail("cannot create the layer " + name);
    }
    for (const VectorField& f : fields) {
        OGRFieldDefn defn(f.name.c_str(), f.type == VectorField::Type::real      ? OFTReal
                                          : f.type == VectorField::Type::integer ? OFTInteger64
                                                                                 : OFTString);
        if (layer->CreateField(&defn) != OGRERR_NONE) {
            fail("cannot create the field " + f.name);
        }
    }
    s.layers.push_back(layer);
    return s.layers.size() - 1;
}

void VectorFile::add_polygon(std::size_t layer,
                             const std::vector<std::vector<Point2>>& rings,
                             const std::vector<FieldValue>& values) {
    auto* polygon = new OGRPolygon();
    for (const std::vector<Point2>& ring : rings) {
        auto* r = new OGRLinearRing();
        r->setNumPoints(static_cast<int>(ring.size()));
        for (std::size_t i = 0; i < ring.size(); ++i) {
            r->setPoint(static_cast<int>(i), ring[i].x, ring[i].y);
        }
        polygon->addRingDirectly(r);
    }
    state_->add(layer, polygon, values);
}

void VectorFile::add_line(std::size_t layer,
                          std::span<const Point3> points,
                          const std::vector<FieldValue>& values) {
    auto* line = new OGRLineString();
    line->setNumPoints(static_cast<int>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        line->setPoint(static_cast<int>(i), points[i].x, points[i].y, points[i].z);
    }
    state_->add(layer, line, values);
}

void VectorFile::add_point(std::size_t layer,
                           const Point3& point,
                           const std::vector<FieldValue>& values) {
    state_->add(layer, new OGRPoint(point.x, point.y, point.z), values);
}

void VectorFile::commit() {
    State& s = *state_;
    if (s.in_transaction && s.ds->CommitTransaction() != OGRERR_NONE) {
        fail("cannot finish " + s.out.target().string());
    }
    s.in_transaction = false;
    GDALClose(s.ds);
    s.ds = nullptr;
    s.out.commit();
}

}  // namespace dtm::io
