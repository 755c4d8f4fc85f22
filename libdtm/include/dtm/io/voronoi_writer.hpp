// SPDX-License-Identifier: MIT
/// @file
/// @brief Thiessen polygons through OGR: one MultiPolygon feature per point with the fields id,
/// index, z and area (GeoPackage, shapefile, GeoJSON by extension), written atomically.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "dtm/algo/thiessen.hpp"

namespace dtm::io {

struct VoronoiWriterOptions {
    std::string crs_wkt;            ///< empty: no CRS
    std::string layer = "voronoi";  ///< layer name (GeoPackage, GeoJSON)
    bool string_ids = false;        ///< id is a text field (the reader's ids), else an integer
};

class VoronoiCellWriter {
public:
    /// @throws UsageError for an extension other than .gpkg, .shp, .geojson, .json; Error.
    VoronoiCellWriter(const std::filesystem::path& target, const VoronoiWriterOptions& options);
    VoronoiCellWriter(const VoronoiCellWriter&) = delete;
    VoronoiCellWriter& operator=(const VoronoiCellWriter&) = delete;
    /// Without commit() the target is left untouched.
    ~VoronoiCellWriter();

    void add(const ThiessenCell& cell, const std::string& id, std::size_t index, double z);
    /// @throws Error when the file cannot be written.
    void commit();
    [[nodiscard]] std::size_t feature_count() const noexcept;

    [[nodiscard]] static std::vector<std::string> extensions();
    /// @throws UsageError when @p target's extension is not one of extensions().
    static void check_extension(const std::filesystem::path& target);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace dtm::io
