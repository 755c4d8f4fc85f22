// SPDX-License-Identifier: MIT
// CRS handling for inputs. GDAL/PROJ identifies and transforms CRSs (always in the traditional
// GIS axis order, x = easting/longitude); GeographicLib (Karney 2011, "Transverse Mercator with
// an accuracy of a few nanometers", J. Geodesy 85:475-485) projects WGS84 longitude/latitude to
// UTM when no target CRS is given. S-JTSK: surveyors write positive (Y, X) with Y pointing west
// and X south; EPSG:5514 (Krovak East-North) is E = -Y, N = -X.
#include "dtm/io/formats/crs.hpp"

#include <ogr_spatialref.h>

#include <GeographicLib/UTMUPS.hpp>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "dtm/core/error.hpp"

namespace dtm::io {
namespace {

OGRSpatialReference from_wkt(const std::string& wkt) {
    OGRSpatialReference srs;
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (srs.SetFromUserInput(wkt.c_str()) != OGRERR_NONE) {
        throw InputError("expected a coordinate reference system GDAL/PROJ knows, found '" +
                         wkt.substr(0, 80) + "'");
    }
    return srs;
}

template <class F>
void for_each_vertex(TerrainInput& t, F&& f) {
    for (Point3& p : t.points) f(p.x, p.y);
    for (auto* lines : {&t.breaklines, &t.soft_breaklines, &t.boundaries, &t.holes}) {
        for (Polyline& line : *lines) {
            for (Point3& p : line.points) f(p.x, p.y);
        }
    }
    for (Point2& p : t.hole_seeds) f(p.x, p.y);
}

}  // namespace

std::string srs_to_wkt(const OGRSpatialReference& srs) {
    char* text = nullptr;
    const char* const options[] = {"FORMAT=WKT2_2018", nullptr};
    if (srs.exportToWkt(&text, options) != OGRERR_NONE || text == nullptr) {
        CPLFree(text);
        return {};
    }
    std::string wkt(text);
    CPLFree(text);
    return wkt;
}

std::string crs_to_wkt(std::string_view definition) {
    OGRSpatialReference srs;
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const std::string def(definition);
    if (srs.SetFromUserInput(def.c_str()) != OGRERR_NONE) {
        throw UsageError("expected a CRS (EPSG:xxxx, WKT or PROJ), found '" + def + "'");
    }
    return srs_to_wkt(srs);
}

std::string crs_label(const std::string& wkt) {
    if (wkt.empty()) return {};
    OGRSpatialReference srs = from_wkt(wkt);
    const char* node = srs.IsProjected() ? "PROJCS" : (srs.IsGeographic() ? "GEOGCS" : nullptr);
    const char* name = srs.GetAuthorityName(node);
    const char* code = srs.GetAuthorityCode(node);
    if (name != nullptr && code != nullptr) return std::string(name) + ":" + code;
    int count = 0;
    int* confidence = nullptr;
    OGRSpatialReferenceH* matches = srs.FindMatches(nullptr, &count, &confidence);
    std::string label;
    for (int i = 0; i < count && label.empty(); ++i) {
        if (confidence[i] < 70) continue;
        const auto* m = OGRSpatialReference::FromHandle(matches[i]);
        const char* mnode = m->IsProjected() ? "PROJCS" : "GEOGCS";
        if (m->GetAuthorityName(mnode) && m->GetAuthorityCode(mnode))
            label = std::string(m->GetAuthorityName(mnode)) + ":" + m->GetAuthorityCode(mnode);
    }
    OSRFreeSRSArray(matches);
    CPLFree(confidence);
    if (!label.empty()) return label;
    const char* own = srs.GetName();
    return own != nullptr ? own : "unnamed CRS";
}

bool crs_is_geographic(const std::string& wkt) {
    return !wkt.empty() && from_wkt(wkt).IsGeographic();
}

bool crs_is_sjtsk(const std::string& wkt) {
    if (wkt.empty()) return false;
    const OGRSpatialReference srs = from_wkt(wkt);
    if (!srs.IsProjected()) return false;
    const char* method = srs.GetAttrValue("PROJECTION");
    const std::string label = crs_label(wkt);
    return label == "EPSG:5514" || label == "EPSG:5513" ||
           (method != nullptr && std::string(method).find("Krovak") != std::string::npos);
}

bool crs_equivalent(const std::string& a, const std::string& b) {
    if (a == b) return true;
    if (a.empty() || b.empty()) return false;
    const OGRSpatialReference sa = from_wkt(a);
    const OGRSpatialReference sb = from_wkt(b);
    return sa.IsSame(&sb) != 0;
}

bool sjtsk_to_east_north(double& x, double& y) noexcept {
    if (x <= 0.0 || y <= 0.0) return false;
    const double y_west = std::min(x, y);
    const double x_south = std::max(x, y);
    x = -y_west;
    y = -x_south;
    return true;
}

std::size_t sjtsk_to_east_north(TerrainInput& terrain) {
    std::size_t count = 0;
    for_each_vertex(terrain,
                    [&count](double& x, double& y) { count += sjtsk_to_east_north(x, y) ? 1 : 0; });
    return count;
}

UtmZone utm_zone_for(double lon, double lat) {
    int zone = GeographicLib::UTMUPS::StandardZone(lat, lon, GeographicLib::UTMUPS::UTM);
    if (zone < 1)
        zone = std::clamp(static_cast<int>(std::floor((lon + 180.0) / 6.0)) % 60 + 1, 1, 60);
    return {zone, lat >= 0.0};
}

void project_position_to_utm(double& x, double& y, UtmZone zone, const std::string& source_name) {
    const double lon = x;
    const double lat = y;
    if (!(lat >= -90.0 && lat <= 90.0 && lon >= -180.0 && lon <= 360.0)) {
        throw InputError(source_name, 0, 0,
                         "expected longitude/latitude in degrees, found (" + std::to_string(lon) +
                             ", " + std::to_string(lat) + ")");
    }
    int out_zone = 0;
    bool north = true;
    double e = 0, n = 0, gamma = 0, k = 0;
    try {
        GeographicLib::UTMUPS::Forward(lat, lon, out_zone, north, e, n, gamma, k, zone.zone);
    } catch (const GeographicLib::GeographicErr& err) {
        throw InputError(source_name, 0, 0,
                         std::string("cannot project to UTM zone ") + std::to_string(zone.zone) +
                             ": " + err.what());
    }
    if (north && !zone.north) n += 10'000'000.0;
    if (!north && zone.north) n -= 10'000'000.0;
    x = e;
    y = n;
}

void project_to_utm(TerrainInput& terrain, UtmZone zone, const std::string& source_name) {
    for_each_vertex(
        terrain, [&](double& x, double& y) { project_position_to_utm(x, y, zone, source_name); });
}

bool crs_is_wgs84_like(const std::string& wkt) {
    const std::string label = crs_label(wkt);
    return label == "EPSG:4326" || label == "EPSG:4258" || label == "EPSG:4979" ||
           label == "EPSG:4937" || label == "OGC:CRS84";
}

std::string target_crs_wkt(const std::string& definition) {
    std::string wkt;
    try {
        wkt = crs_to_wkt(definition);
    } catch (const UsageError& e) {
        throw OptionError("target_crs", std::string("`target_crs`: ") + e.what());
    }
    if (crs_is_geographic(wkt)) {
        throw OptionError("target_crs",
                          "`target_crs`: expected a projected CRS (metres), found the "
                          "geographic " +
                              crs_label(wkt) + "; triangulating degrees is wrong");
    }
    return wkt;
}

void PositionTransform::Free::operator()(OGRCoordinateTransformation* ct) const noexcept {
    OGRCoordinateTransformation::DestroyCT(ct);
}

PositionTransform::PositionTransform(const std::string& source_wkt,
                                     const std::string& target_wkt,
                                     std::string source_name)
    : source_name_(std::move(source_name)), target_label_(crs_label(target_wkt)) {
    OGRSpatialReference from = from_wkt(source_wkt);
    OGRSpatialReference to = from_wkt(target_wkt);
    ct_.reset(OGRCreateCoordinateTransformation(&from, &to));
    if (!ct_) {
        throw InputError(source_name_, 0, 0,
                         "cannot transform from " + crs_label(source_wkt) + " to " + target_label_);
    }
}

PositionTransform::PositionTransform(PositionTransform&&) noexcept = default;
PositionTransform::~PositionTransform() = default;

void PositionTransform::operator()(double& x, double& y) const {
    double tx = x, ty = y;
    if (!ct_->Transform(1, &tx, &ty) || !std::isfinite(tx) || !std::isfinite(ty)) {
        throw InputError(source_name_, 0, 0,
                         "cannot transform the point (" + std::to_string(x) + ", " +
                             std::to_string(y) + ") to " + target_label_);
    }
    x = tx;
    y = ty;
}

void transform_terrain(TerrainInput& terrain,
                       const std::string& source_wkt,
                       const std::string& target_wkt,
                       const std::string& source_name) {
    const PositionTransform transform(source_wkt, target_wkt, source_name);
    for_each_vertex(terrain, [&](double& x, double& y) { transform(x, y); });
}

}  // namespace dtm::io
