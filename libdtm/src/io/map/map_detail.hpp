// SPDX-License-Identifier: MIT
// The map's private pieces: the drawing style (ČSN 01 3411 colours and weights), the content
// shared by every sheet, the per-page drawing, the furniture plan, the coordinate grid and the
// hillshade underlay.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dtm/algo/constraint_lines.hpp"
#include "dtm/algo/spot_heights.hpp"
#include "dtm/core/contour.hpp"
#include "dtm/core/grid.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/draw/canvas.hpp"
#include "dtm/io/draw/sheet.hpp"
#include "dtm/io/map/map.hpp"

namespace dtm::io::map::detail {

/// Colours, line weights and text sizes. Contours follow Czech practice for large-scale maps
/// (ČSN 01 3411): brown, basic contours thin, index contours (every 5th) heavier, their numbers
/// in brown along the line; spot heights a black dot with the height beside it.
struct MapStyle {
    draw::Color contour = draw::Color::rgb(0x9a5a28);
    double contour_mm = 0.18;
    double index_mm = 0.35;
    double label_pt = 7.0;
    double spot_pt = 6.0;
    double spot_dot_mm = 0.6;
    draw::Color ink = draw::Color::rgb(0x000000);
    draw::Color breakline = draw::Color::rgb(0x3a3a3a);
    double breakline_mm = 0.3;
    double soft_breakline_mm = 0.22;
    double boundary_mm = 0.35;
    double hole_mm = 0.25;
    draw::Color hole_fill = draw::Color::rgb(0xe3e6ea);
    double grid_mm = 0.18;
    double grid_arm_mm = 3.0;
    double grid_label_pt = 6.0;
    double edge_band_mm = 7.0;  ///< labels keep this far from the page edge (grid labels there)
    double furniture_inset_mm = 6.0;
    std::string family = "DejaVu Sans";

    [[nodiscard]] draw::TextStyle label_text() const;
    [[nodiscard]] draw::TextStyle spot_text() const;
    [[nodiscard]] draw::Stroke stroke_of(ConstraintKind kind) const;
};

/// Everything the pages share, in CRS units.
struct MapData {
    const Tin* tin = nullptr;
    MapOptions options;
    std::vector<Contour> contours;
    std::vector<ConstraintLine> constraints;
    std::vector<SpotHeight> spots;
    Box2 surface;
    std::shared_ptr<const Grid> mask;  ///< see surface_mask
    double interval = 1.0;
    std::size_t index_every = 5;
    int spot_decimals = 2;
    bool sjtsk = false;
    std::string crs_name;    ///< e.g. "S-JTSK / Krovak East North (EPSG:5514)"
    double north_deg = 0.0;  ///< true north, counter-clockwise from the page's up
    bool north_known = false;
    std::string date;
    std::string unit = " m";  ///< suffix of heights and distances (" m", or " units")
    MapStyle style;
};

/// What one page placed.
struct PageResult {
    PageFurniture furniture;
    std::vector<LabelRecord> labels;
    std::vector<FailureRecord> failures;
    std::size_t lines_too_short = 0;
    std::size_t spots_drawn = 0;
    std::size_t spot_labels_failed = 0;
};

/// Fraction of a page rectangle that the surface covers (0..1).
using CoverageFn = std::function<double(const draw::Rect&)>;

/// The furniture of one page, in page millimetres.
struct Furniture {
    draw::Rect north;
    draw::Rect scale_bar;
    draw::Rect legend;
    draw::Rect title;
    double cover = 0.0;  ///< fraction of the furniture's area over the surface
    [[nodiscard]] std::vector<draw::Rect> panels() const {
        return {north, scale_bar, legend, title};
    }
    [[nodiscard]] draw::Rect bounds() const;
};

/// Sizes of the furniture pieces and of its two arrangements, in page mm.
struct FurnitureSize {
    double gap = 2.0;
    double arrow = 12.0;
    double title_w = 0.0;
    double title_h = 0.0;
    double legend_w = 0.0;
    double legend_h = 0.0;
    double bar_h = 0.0;
    double top_h = 0.0;     ///< the row of north arrow and scale bar
    double column_w = 0.0;  ///< arrow and scale bar, legend, title block stacked
    double column_h = 0.0;
    double row_w = 0.0;  ///< legend beside the title block (with arrow and scale bar above it)
    double row_h = 0.0;
};

[[nodiscard]] FurnitureSize furniture_size(const MapData& data,
                                           const PageFrame& page,
                                           const draw::TitleBlock& block);

[[nodiscard]] draw::TitleBlock title_block(const MapData& data,
                                           const PageFrame& page,
                                           const std::string& sheet_text);
[[nodiscard]] std::vector<draw::LegendEntry> legend_entries(const MapData& data);
/// Places the furniture in the page corner the surface covers least (lower right on ties).
/// @throws UsageError when the page is too small for it
[[nodiscard]] Furniture plan_furniture(const MapData& data,
                                       const PageFrame& page,
                                       const draw::TitleBlock& block,
                                       const CoverageFn& coverage);
void draw_furniture(draw::Canvas& canvas,
                    const MapData& data,
                    const PageFrame& page,
                    const Furniture& f,
                    const draw::TitleBlock& block);

/// A coordinate label at the page edge.
struct GridLabel {
    Point2 at;  ///< page mm, centre of the text
    std::string text;
    double angle_deg = 0.0;
    draw::Rect box;
};

/// Ground spacing of the grid crosses: 100 mm on paper rounded to 1, 2, 2.5 or 5 x 10^k (50 m at
/// 1:500), halved until at least two lines cross the page each way.
[[nodiscard]] double grid_step(const PageFrame& page);
/// Coordinate labels along the four edges; S-JTSK in the Czech manner (Y = -E, X = -N, positive,
/// digits grouped by thousands). Labels under a furniture panel are left out.
[[nodiscard]] std::vector<GridLabel> grid_labels(const MapData& data,
                                                 const PageFrame& page,
                                                 const Furniture& f);
void draw_grid(draw::Canvas& canvas,
               const MapData& data,
               const PageFrame& page,
               const std::vector<GridLabel>& labels);

/// Where the surface is: the TIN rasterized over its extent in about 800 x 800 cells (NoData
/// outside), computed once and shared by every page.
[[nodiscard]] std::shared_ptr<const Grid> surface_mask(const Tin& tin, const Box2& surface);
/// Fraction of a page rectangle the surface covers, from data.mask.
[[nodiscard]] CoverageFn surface_coverage(const MapData& data, const PageFrame& page);

/// A hillshade of the surface over the page (Horn's gradient, sun from the north-west at 45
/// degrees, as gdaldem), as RGBA: black with an alpha growing with the shade; transparent
/// outside the surface. @p columns x @p rows pixels.
[[nodiscard]] std::vector<std::uint8_t> hillshade_rgba(
    const Tin& tin, const PageFrame& page, int columns, int rows, const Progress& progress);

/// Places and draws one page. @p sheet_text names the sheet in the title block ("2 of 6").
[[nodiscard]] PageResult draw_page(draw::Canvas& canvas,
                                   const MapData& data,
                                   const PageFrame& page,
                                   const std::string& sheet_text,
                                   const Progress& progress);

/// The sheet index: the site, the sheet outlines and their numbers, at its own scale.
void draw_index_page(draw::Canvas& canvas,
                     const MapData& data,
                     const MapLayout& layout,
                     const PageFrame& index);

/// "245", "247.5": the shortest decimal text that equals @p v to 1e-9.
[[nodiscard]] std::string level_text(double v);
/// A coordinate with thousands grouped by a narrow no-break space ("1 045 300").
[[nodiscard]] std::string grouped(double v);

}  // namespace dtm::io::map::detail
