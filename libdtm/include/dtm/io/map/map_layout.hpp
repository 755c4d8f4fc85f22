// SPDX-License-Identifier: MIT
/// @file
/// @brief Map sheets at scale: the page size follows from the scale and the extent (100 m at
/// 1:500 is 200 mm), or the extent from the paper; a site larger than one sheet is split into a
/// grid of sheets (an index page shows them). Each page is georeferenced as a whole: page
/// millimetres and ground coordinates are related by the scale alone, and the page edge is the
/// map's neat line.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/io/draw/sheet.hpp"

namespace dtm::io::map {

/// One page of the map: the ground extent it shows, at 1 : scale.
struct PageFrame {
    Box2 extent;            ///< CRS units; the page edge (neat line)
    double width_mm = 0.0;  ///< page size
    double height_mm = 0.0;
    double scale = 500.0;    ///< 1 : scale
    double unit_m = 1.0;     ///< metres per CRS unit
    std::string name = "1";  ///< sheet name ("1", "2", ... for tiled sheets, "index")
    int row = 0;             ///< position in the sheet grid (row 0 at the top)
    int col = 0;

    /// Page millimetres per CRS unit.
    [[nodiscard]] double mm_per_unit() const noexcept { return 1000.0 * unit_m / scale; }
    /// CRS units per page millimetre (ContourLabelOptions::units_per_mm).
    [[nodiscard]] double units_per_mm() const noexcept { return scale / (1000.0 * unit_m); }
    [[nodiscard]] Point2 to_page(Point2 ground) const noexcept {
        return {(ground.x - extent.xmin) * mm_per_unit(), (extent.ymax - ground.y) * mm_per_unit()};
    }
    [[nodiscard]] Point2 to_ground(Point2 page) const noexcept {
        return {extent.xmin + page.x * units_per_mm(), extent.ymax - page.y * units_per_mm()};
    }
    /// The ground box of a page rectangle.
    [[nodiscard]] Box2 ground_box(const draw::Rect& r) const noexcept;
};

struct LayoutRequest {
    Box2 data;                         ///< extent of the surface (the TIN's triangles)
    std::optional<Box2> extent;        ///< the map extent asked for; none: the data extent
    std::optional<draw::Paper> paper;  ///< none: the page is the extent at scale
    draw::Orientation orientation = draw::Orientation::automatic;
    double scale = 500.0;
    double unit_m = 1.0;
    bool sheets = false;  ///< split into sheets of the paper (A3 when none is given)
};

struct MapLayout {
    std::vector<PageFrame> pages;  ///< the map sheets, row by row from the north-west
    int rows = 1;
    int cols = 1;
    Box2 covered;       ///< union of the pages' extents
    std::string paper;  ///< paper name, or "extent" when the page follows the extent
};

/// Lays out the map. Without a paper the page is the extent at scale and must fit A0 (either
/// way round); with a paper the extent is the paper at scale, centred on the extent asked for (or
/// the data), which must fit it unless sheets are asked for.
/// @throws UsageError for a non-positive scale, an empty extent, an extent that fits no paper
/// (naming the largest standard scale that would fit), or a site larger than the paper without
/// sheets
[[nodiscard]] MapLayout layout_map(const LayoutRequest& request);

/// The largest of the usual survey scales (1:100 ... 1:100 000) whose page for a @p width x
/// @p height ground extent fits within @p max_w x @p max_h mm (either way round); 0 if none.
[[nodiscard]] double largest_fitting_scale(
    double width, double height, double unit_m, double max_w, double max_h);

}  // namespace dtm::io::map
