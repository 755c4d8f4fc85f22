// SPDX-License-Identifier: MIT
/// @file
/// @brief Writing contour lines through OGR: a ContourSink that streams features to a
/// GeoPackage, shapefile, DXF or GeoJSON file chosen by extension, committed atomically.
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "dtm/algo/contour.hpp"

namespace dtm::io {

struct ContourWriteOptions {
    std::string crs_wkt;             ///< layer CRS when non-empty (shapefile: a .prj)
    std::string layer = "contours";  ///< layer name (GeoPackage, shapefile stem is the file's)
};

/// ContourSink writing LineStringZ features (z = level) with the attributes `elevation` (real),
/// `index` (true every k-th level) and `closed` (true for closed rings). Extensions: .gpkg
/// (GeoPackage), .shp (ESRI Shapefile, with .prj), .dxf (index and intermediate contours on the
/// layers CONTOUR_INDEX and CONTOUR; DXF keeps no attributes other than the z), .geojson/.json.
/// Features go to a temporary file that commit() renames onto the target.
class ContourWriter final : public ContourSink {
public:
    /// @throws UsageError for an unknown extension; Error if OGR fails.
    ContourWriter(const std::filesystem::path& target, const ContourWriteOptions& options);
    ContourWriter(const ContourWriter&) = delete;
    ContourWriter& operator=(const ContourWriter&) = delete;
    ~ContourWriter() override;

    void add(const ContourLevel& level, std::span<const Point3> line, bool closed) override;
    /// Closes the file and renames it onto the target. @throws Error
    void commit();
    /// Features written so far.
    [[nodiscard]] std::size_t feature_count() const noexcept;

private:
    struct State;
    std::unique_ptr<State> state_;
};

/// Lower-case extensions ContourWriter accepts.
[[nodiscard]] std::vector<std::string> contour_extensions();

}  // namespace dtm::io
