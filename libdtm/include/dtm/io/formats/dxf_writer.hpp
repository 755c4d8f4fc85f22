// SPDX-License-Identifier: MIT
/// @file
/// @brief A minimal streaming DXF writer (ASCII DXF R12, AC1009: what every CAD program, GDAL's
/// DXF driver, ezdxf and field controllers read): a header, a layer table, and the entities
/// POLYLINE (3-D polylines: flag 8, VERTEX entities with flag 32), 3DFACE and TEXT.
///
/// Layers must be declared before the first entity (R12 keeps its tables before the entities);
/// the file is written to a temporary sibling and renamed onto the target by commit().
#pragma once

#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "dtm/core/point.hpp"

namespace dtm::io {

struct DxfLayer {
    std::string name;  ///< letters, digits, '_', '-' and '$' (other characters become '_')
    int color = 7;     ///< AutoCAD colour index 1..255 (7: white/black)
};

class DxfWriter {
public:
    /// @throws Error if the temporary file cannot be created.
    explicit DxfWriter(const std::filesystem::path& target);
    DxfWriter(const DxfWriter&) = delete;
    DxfWriter& operator=(const DxfWriter&) = delete;
    ~DxfWriter();

    /// Declares a layer. @throws Error after the first entity.
    void add_layer(const DxfLayer& layer);
    /// A 3-D polyline (POLYLINE with flag 8, closed: flag 8 | 1) on @p layer.
    void polyline_3d(const std::string& layer, std::span<const Point3> points, bool closed = false);
    /// A 3DFACE (a triangle: the fourth corner repeats the third).
    void face_3d(const std::string& layer, const Point3& a, const Point3& b, const Point3& c);
    /// Single-line TEXT at @p at (insertion point, left baseline), @p height in drawing units,
    /// @p rotation in degrees counter-clockwise.
    void text(const std::string& layer,
              const Point3& at,
              double height,
              const std::string& value,
              double rotation = 0.0);
    /// Entities written so far.
    [[nodiscard]] std::size_t entity_count() const noexcept;
    /// Writes the end of file, closes and renames onto the target. @throws Error
    void commit();

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace dtm::io
