// SPDX-License-Identifier: MIT
/// @file
/// @brief A small OGR vector writer for analysis products: several layers of polygons, 3-D
/// lines or 3-D points with a few attributes, in one GeoPackage (or any OGR vector format chosen
/// by extension), committed atomically.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm::io {

enum class VectorGeometry { polygon, line_3d, point_3d };

struct VectorField {
    enum class Type { real, integer, text };
    std::string name;
    Type type = Type::real;
};

using FieldValue = std::variant<double, long long, std::string>;

class VectorFile {
public:
    /// Format by extension: .gpkg (default), .shp, .geojson, .json, .kml, .fgb.
    /// @throws UsageError for an unknown extension; Error if OGR fails.
    VectorFile(const std::filesystem::path& target, const std::string& crs_wkt);
    VectorFile(const VectorFile&) = delete;
    VectorFile& operator=(const VectorFile&) = delete;
    ~VectorFile();

    /// Creates a layer; returns its number for the add_* calls.
    std::size_t add_layer(const std::string& name,
                          VectorGeometry geometry,
                          const std::vector<VectorField>& fields);
    /// A polygon: rings[0] outer, the rest holes; each ring closed (last point = first).
    void add_polygon(std::size_t layer,
                     const std::vector<std::vector<Point2>>& rings,
                     const std::vector<FieldValue>& values);
    void add_line(std::size_t layer,
                  std::span<const Point3> points,
                  const std::vector<FieldValue>& values);
    void add_point(std::size_t layer, const Point3& point, const std::vector<FieldValue>& values);
    /// Closes and renames onto the target. @throws Error
    void commit();

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace dtm::io
