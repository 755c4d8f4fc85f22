// SPDX-License-Identifier: MIT
/// @file
/// @brief The inputs of the analyses: a surface (a dtm TIN, or points and lines triangulated
/// with the usual options), lines (profiles, alignments), polygons (areas) and control points,
/// each read through io::load_inputs with the reader options of the command.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/terrain.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/inputs.hpp"

namespace dtm::products {

/// Where a surface comes from: its files (with roles) and how to triangulate them.
struct SurfaceSource {
    std::string name;  ///< "top", "base", "surface 2", for messages and reports
    io::LoadOptions load;
    TriangulateOptions triangulation;
};

struct LoadedSurface {
    std::string name;
    Tin tin;
    std::string crs_wkt;
    std::vector<io::InputSummary> inputs;
    bool from_tin = false;  ///< read as a dtm TIN (else triangulated from the inputs)
    /// Set when the inputs were reprojected into another surface's CRS: their own CRS label.
    std::string transformed_from;
    /// The files, for reports: "a.csv + breaklines b.shp".
    [[nodiscard]] std::string description() const;
};

/// Reads and, unless it is a single dtm TIN, triangulates @p source. When @p crs_wkt is given
/// and the inputs carry another CRS, they are reprojected into it (and transformed_from says
/// so). @throws InputError (file, line, feature) for unreadable inputs or an empty surface.
[[nodiscard]] LoadedSurface load_surface(const SurfaceSource& source,
                                         const std::string& crs_wkt = {},
                                         const Progress& progress = {});

/// Loads every surface of @p sources, all in the first one's CRS, concurrently (a surface in
/// another CRS is read again, reprojected). The first error in the order of @p sources is the
/// one thrown. @p notes receives a line for each reprojected surface.
[[nodiscard]] std::vector<LoadedSurface> load_surfaces(const std::vector<SurfaceSource>& sources,
                                                       std::vector<std::string>& notes,
                                                       const Progress& progress = {});

/// Lines of a vector or text file (LineStrings, polygon rings, or HP-GL lines), each with its
/// source ("file:feature N") for messages; heights may be NaN. Reprojected into @p crs_wkt when
/// the file carries another CRS. @throws InputError when the file has no line.
[[nodiscard]] std::vector<Polyline> load_lines(const std::filesystem::path& path,
                                               const io::LoadOptions& reader,
                                               const std::string& crs_wkt);

/// Polygons of a file as boundaries (outer rings) and holes (inner rings), in @p crs_wkt.
/// @throws InputError naming the file and feature for a ring that does not close, or when the
/// file has no polygon.
[[nodiscard]] TerrainInput load_area(const std::filesystem::path& path,
                                     const io::LoadOptions& reader,
                                     const std::string& crs_wkt);

/// Survey points (with ids where the file has them), in @p crs_wkt.
struct ControlPoints {
    std::vector<Point3> points;
    std::vector<std::string> ids;  ///< parallel to points ("" where none; "N" by line otherwise)
    std::string crs_wkt;
};
[[nodiscard]] ControlPoints load_points(const std::filesystem::path& path,
                                        const io::LoadOptions& reader,
                                        const std::string& crs_wkt);

}  // namespace dtm::products
