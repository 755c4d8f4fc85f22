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
#include "dtm/algo/contour_annotation.hpp"

namespace dtm::io {

struct ContourWriteOptions {
    std::string crs_wkt;             ///< layer CRS when non-empty (shapefile: a .prj)
    std::string layer = "contours";  ///< layer name (GeoPackage, shapefile stem is the file's)
};

/// ContourSink writing LineStringZ features (z = level) with the attributes `elevation` (real),
/// `index` (true every k-th level) and `closed` (true for closed rings). Extensions: .gpkg
/// (GeoPackage), .shp (ESRI Shapefile, with .prj), .dxf (dtm's DXF R12 writer, formats/dxf.hpp:
/// 3-D polylines on the layers CONTOUR_INDEX and CONTOUR; DXF keeps no attributes other than the
/// z), .geojson/.json. Labels (add_annotation) go to DXF and GeoPackage files.
/// Features go to a temporary file that commit() renames onto the target.
class ContourWriter final : public ContourSink {
public:
    /// @throws UsageError for an unknown extension; Error if OGR fails.
    ContourWriter(const std::filesystem::path& target, const ContourWriteOptions& options);
    ContourWriter(const ContourWriter&) = delete;
    ContourWriter& operator=(const ContourWriter&) = delete;
    ~ContourWriter() override;

    void add(const ContourLevel& level, std::span<const Point3> line, bool closed) override;
    /// True when the format holds labels and spot heights (DXF, GeoPackage).
    [[nodiscard]] bool holds_annotation() const noexcept;
    /// Adds placed labels and spot heights (after the lines). DXF: contour numbers as TEXT on
    /// CONTOUR_LABELS (centred on ContourLabel::anchor, rotated along the line, the up vector
    /// uphill), spot heights as POINT (z = height) on SPOT_HEIGHTS and their TEXT on SPOT_LABELS.
    /// GeoPackage: point layers `contour_labels` (text, level, angle: degrees counter-clockwise,
    /// height: text height in CRS units) and `spot_heights` (PointZ; height, kind, label,
    /// label_x, label_y: the text's centre, null when it found no room), each with its QGIS
    /// default style (table layer_styles, io::label_layer_qml). @throws UsageError for a format
    /// that holds one layer only; Error if OGR fails
    void add_annotation(const ContourAnnotation& annotation);
    /// Closes the file and renames it onto the target. @throws Error
    void commit();
    /// Features written so far.
    [[nodiscard]] std::size_t feature_count() const noexcept;

private:
    struct State;
    std::unique_ptr<State> state_;
};

/// Writes @p target, an OGR VRT whose layer options.layer is the union, in the given order, of
/// the layers of that name in @p pieces (the contour GeoPackages of a distributed run): QGIS and
/// GDAL read it as one layer. Piece paths beside the VRT are written relative to it. The file is
/// opened through OGR (and so every piece) before it is committed atomically. @throws Error
void write_contour_vrt(const std::filesystem::path& target,
                       const std::vector<std::filesystem::path>& pieces,
                       const ContourWriteOptions& options);

/// True when a contour file of this extension holds labels (ContourWriter::holds_annotation).
[[nodiscard]] bool contour_file_holds_annotation(const std::filesystem::path& target);

/// Lower-case extensions ContourWriter accepts.
[[nodiscard]] std::vector<std::string> contour_extensions();

}  // namespace dtm::io
