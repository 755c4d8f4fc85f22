// SPDX-License-Identifier: MIT
/// @file
/// @brief DXF for CAD (docs/formats.md "DXF"): a small streaming writer of ASCII DXF R12 entities
/// (3DFACE, 3-D POLYLINE, POINT, TEXT on named layers), the TIN writer on it (3DFACE triangles,
/// breaklines and boundaries as 3-D polylines on their own layers), and the reader of a DXF
/// whose entities are 3DFACEs as a TIN (other DXF files go to OGR). Sources: src/io/formats/dxf/.
#pragma once

#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/reader.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::io {

struct DxfLayer {
    std::string name;  ///< letters, digits, '_', '-', '$' (R12 names)
    int color = 7;     ///< AutoCAD colour index 1..255
};

/// Writes one ASCII DXF R12 file (AC1009, read by AutoCAD, BricsCAD, GDAL, ezdxf, QGIS),
/// entities streamed in order. Numbers are the shortest text of the exact double. Writes exactly
/// the path it is given (wrap in AtomicOutput for atomicity).
class DxfWriter {
public:
    /// Opens @p path and writes the header and the layer table. @throws Error if it cannot.
    DxfWriter(const std::filesystem::path& path, std::span<const DxfLayer> layers);
    DxfWriter(const DxfWriter&) = delete;
    DxfWriter& operator=(const DxfWriter&) = delete;
    ~DxfWriter() = default;

    void face(std::string_view layer, const Point3& a, const Point3& b, const Point3& c);
    /// A 3-D polyline (POLYLINE flag 8 with VERTEX flag 32); @p closed adds flag 1.
    void polyline(std::string_view layer, std::span<const Point3> points, bool closed);
    void point(std::string_view layer, const Point3& p);
    /// Text with its insertion point (left, baseline), height and rotation in degrees
    /// counter-clockwise from the x axis.
    void text(std::string_view layer,
              const Point3& at,
              double height,
              double rotation_deg,
              std::string_view text);
    /// Ends the ENTITIES section and the file. @throws Error if writing failed.
    void finish();

private:
    void code(int group, std::string_view value);
    void code(int group, double value);
    void xyz(int first, const Point3& p);
    std::filesystem::path path_;
    std::ofstream out_;
    std::string buffer_;
};

/// The TIN writer table's `.dxf`: layer TIN (3DFACE per triangle, the third vertex repeated as
/// the fourth), BREAKLINES, SOFT_BREAKLINES, BOUNDARY, HOLES (3-D polylines of the constrained
/// edges, joined into chains). DXF carries no CRS.
void write_tin_dxf(const Tin& tin,
                   const std::filesystem::path& path,
                   const TinWriteOptions& options);

/// The reader table's `.dxf`: a file with 3DFACE entities gives their TIN (equal corners are one
/// vertex; a face with four distinct corners is two triangles; faces turned counter-clockwise;
/// with ReadOptions::retriangulate its vertices as points); any other DXF is read by OGR
/// (read_ogr). @throws InputError naming the file and line.
[[nodiscard]] ReadResult read_dxf(const InputFile& file,
                                  const ReadOptions& options,
                                  const Progress& progress = {});

}  // namespace dtm::io
