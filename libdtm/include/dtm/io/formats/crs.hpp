// SPDX-License-Identifier: MIT
/// @file
/// @brief Coordinate reference systems of inputs: naming them, S-JTSK (Y, X) to Krovak
/// East-North, projecting geographic coordinates to UTM (GeographicLib) and transforming between
/// CRSs (GDAL/PROJ). Axis order is always x = easting/longitude, y = northing/latitude.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "dtm/core/terrain.hpp"

class OGRSpatialReference;
class OGRCoordinateTransformation;

namespace dtm::io {

/// WKT (WKT2) of a CRS given by the user: "EPSG:5514", WKT, PROJ string, ...
/// @throws UsageError if GDAL/PROJ does not know it.
[[nodiscard]] std::string crs_to_wkt(std::string_view definition);

/// WKT2 of an OGR spatial reference.
[[nodiscard]] std::string srs_to_wkt(const OGRSpatialReference& srs);

/// A CRS as read from a file, identified where it carries no EPSG code (issue 17.6).
struct CrsIdentity {
    std::string wkt;   ///< WKT2: the EPSG entry when identified, else the definition as it is
    std::string note;  ///< what was done, for `dtm info`; empty when the file gave an EPSG code
};

/// Minimum GDAL FindMatches confidence (percent) of an identification by name and parameters.
inline constexpr int crs_match_confidence = 90;

/// Identifies @p definition (WKT of any flavour, an ESRI .prj text, ...): kept as it is when it
/// carries an EPSG code; else the EPSG entry of GDAL's FindMatches is used when the best EPSG
/// match is unique and at least crs_match_confidence %, or is the only EPSG match with the very
/// same projection parameters (PROJ string: ESRI names of datums that EPSG renamed); else the
/// definition is kept. @throws InputError if GDAL/PROJ cannot read @p definition.
[[nodiscard]] CrsIdentity identify_crs(const std::string& definition);

/// "EPSG:5514" when the CRS matches an EPSG entry (also for ESRI .prj text), else its name;
/// empty for an empty @p wkt.
[[nodiscard]] std::string crs_label(const std::string& wkt);

[[nodiscard]] bool crs_is_geographic(const std::string& wkt);
/// True for S-JTSK / Krovak (EPSG:5514 and its variants).
[[nodiscard]] bool crs_is_sjtsk(const std::string& wkt);
[[nodiscard]] bool crs_equivalent(const std::string& a, const std::string& b);

/// Rewrites a position with positive x and y, taken as the traditional S-JTSK (Y, X) in either
/// column order (Y < X over the whole Czech Republic), as Krovak East-North: E = -Y, N = -X.
/// @returns whether it was rewritten.
bool sjtsk_to_east_north(double& x, double& y) noexcept;
/// The same for every vertex of @p terrain. @returns how many were rewritten.
std::size_t sjtsk_to_east_north(TerrainInput& terrain);

struct UtmZone {
    int zone = 0;  ///< 1..60
    bool north = true;
    [[nodiscard]] int epsg() const noexcept { return (north ? 32600 : 32700) + zone; }
};

/// Standard UTM zone (GeographicLib rules, incl. Norway/Svalbard) of a longitude/latitude.
[[nodiscard]] UtmZone utm_zone_for(double lon, double lat);

/// Projects one longitude/latitude position (WGS84 degrees, x = lon) to @p zone with
/// GeographicLib, in place. @throws InputError naming @p source_name outside the ranges below.
void project_position_to_utm(double& x, double& y, UtmZone zone, const std::string& source_name);

/// True for the geographic CRSs projected to UTM as they are (WGS 84, ETRS89, CRS84); others
/// are transformed to WGS 84 first.
[[nodiscard]] bool crs_is_wgs84_like(const std::string& wkt);

/// Projects longitude/latitude (WGS84 degrees, x = lon) to @p zone with GeographicLib.
/// @throws InputError if a latitude is outside [-90, 90] or a longitude outside [-180, 360].
void project_to_utm(TerrainInput& terrain, UtmZone zone, const std::string& source_name);

/// The WKT of `target_crs`, the output CRS asked for. @throws OptionError("target_crs") when
/// GDAL does not know it or it is geographic (triangulating degrees is wrong).
[[nodiscard]] std::string target_crs_wkt(const std::string& definition);

/// A GDAL/PROJ transformation applied one position at a time, so a position gets the same
/// numbers wherever it is transformed (the serial load and a rank's share of a distributed one).
class PositionTransform {
public:
    /// @throws InputError naming @p source_name when GDAL has no transformation between them.
    PositionTransform(const std::string& from_wkt,
                      const std::string& to_wkt,
                      std::string source_name);
    PositionTransform(PositionTransform&&) noexcept;
    ~PositionTransform();
    /// @throws InputError naming the source if the position cannot be transformed.
    void operator()(double& x, double& y) const;

private:
    struct Free {
        void operator()(OGRCoordinateTransformation* ct) const noexcept;
    };
    std::unique_ptr<OGRCoordinateTransformation, Free> ct_;
    std::string source_name_;
    std::string target_label_;
};

/// Transforms every vertex and seed from @p from_wkt to @p to_wkt with GDAL/PROJ.
/// @throws InputError naming @p source_name if a point cannot be transformed.
void transform_terrain(TerrainInput& terrain,
                       const std::string& from_wkt,
                       const std::string& to_wkt,
                       const std::string& source_name);

}  // namespace dtm::io
