// SPDX-License-Identifier: MIT
/// @file
/// @brief Printable sheets: paper sizes (ISO 216 A series or W x H mm), orientation, and the
/// sheet furniture drawn on a Canvas: title block (ISO 7200 in spirit: lower right, title, fields,
/// a signature line), scale bar, north arrow, legend. The contour map (`dtm map`) uses the
/// furniture on its full-page map face; profiles and sections use sheet_layout(): a frame inset
/// from the paper edge with the title block in its lower right corner and a content rectangle for
/// a chart (draw_chart) above and beside it.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/io/draw/canvas.hpp"

namespace dtm::io::draw {

/// A page rectangle in millimetres, top-left origin, y down (as Canvas).
struct Rect {
    double x = 0.0;
    double y = 0.0;
    double width = 0.0;
    double height = 0.0;
    [[nodiscard]] double right() const noexcept { return x + width; }
    [[nodiscard]] double bottom() const noexcept { return y + height; }
};

/// A paper size, portrait (width <= height).
struct Paper {
    std::string name;
    double width_mm = 0.0;
    double height_mm = 0.0;
};

/// A4, A3, A2, A1, A0 (ISO 216), smallest first.
[[nodiscard]] std::vector<Paper> standard_papers();

/// "A4".."A0" (any case) or "WxHmm" / "WxH" (millimetres, e.g. "500x700mm").
/// @throws UsageError naming the accepted forms
[[nodiscard]] Paper paper_named(std::string_view name);

enum class Orientation { automatic, portrait, landscape };

/// "auto", "portrait" or "landscape". @throws UsageError
[[nodiscard]] Orientation orientation_named(std::string_view name);

/// The page size of @p paper turned to @p orientation (automatic: as given, portrait).
[[nodiscard]] std::pair<double, double> page_size(const Paper& paper, Orientation orientation);

/// Text styles of the furniture, in one place so every sheet looks the same.
struct SheetStyle {
    std::string family = "DejaVu Sans";
    double title_pt = 11.0;
    double text_pt = 6.5;
    double small_pt = 5.5;
    double frame_mm = 0.5;  ///< the frame (neat line) width
    double rule_mm = 0.18;  ///< inner rules of the title block and legend
    Color ink = Color::rgb(0x000000);
};

/// The title block: a title and labelled fields (e.g. {"Scale", "1 : 500"}), and when
/// @p signature a row "Surveyor" / "Signature" left blank to be filled by hand.
struct TitleBlock {
    std::string title;
    std::vector<std::pair<std::string, std::string>> fields;
    bool signature = true;
};

/// Height the title block needs at @p width (mm).
[[nodiscard]] double title_block_height(const TitleBlock& block,
                                        double width,
                                        const SheetStyle& style = {});
/// Draws the block (white background, frame, rules, text) into @p area.
void draw_title_block(Canvas& canvas,
                      const TitleBlock& block,
                      const Rect& area,
                      const SheetStyle& style = {});

/// A scale bar for 1 : @p scale with @p unit_m metres per CRS unit: alternating black and white
/// segments of a round ground length (1, 2, 2.5 or 5 x 10^k), at most @p max_width_mm long,
/// labelled below, with "1 : scale" above. Draws with its top-left at @p at; returns its area.
Rect draw_scale_bar(Canvas& canvas,
                    Point2 at,
                    double max_width_mm,
                    double scale,
                    double unit_m = 1.0,
                    const SheetStyle& style = {});
/// The area draw_scale_bar would use.
[[nodiscard]] Rect scale_bar_area(Point2 at, double max_width_mm, const SheetStyle& style = {});

/// A north arrow @p height_mm tall centred on @p centre, pointing @p angle_deg counter-clockwise
/// from the top of the page (0: grid north is up), with the letter @p letter above it.
void draw_north_arrow(Canvas& canvas,
                      Point2 centre,
                      double height_mm,
                      double angle_deg = 0.0,
                      std::string_view letter = "N",
                      const SheetStyle& style = {});

/// One legend row: a line sample (stroke), a filled swatch, or a point marker, and its text.
struct LegendEntry {
    enum class Kind { line, fill, marker };
    Kind kind = Kind::line;
    Stroke stroke;
    Color fill = Color::rgb(0xffffff);
    double marker_mm = 0.6;  ///< marker diameter
    std::string text;
};

/// Size of the legend box (title "Legend" and one row per entry).
[[nodiscard]] std::pair<double, double> legend_size(const std::vector<LegendEntry>& entries,
                                                    const SheetStyle& style = {});
void draw_legend(Canvas& canvas,
                 const std::vector<LegendEntry>& entries,
                 Point2 top_left,
                 const SheetStyle& style = {});

/// A framed sheet for charts (profiles, sections): the frame inset by @p margin_mm, the title
/// block in its lower right corner, and the content area above the title block.
struct SheetLayout {
    double width_mm = 0.0;
    double height_mm = 0.0;
    Rect frame;
    Rect title_block;
    Rect content;
};

/// @throws UsageError when the paper is too small for the title block
[[nodiscard]] SheetLayout sheet_layout(const Paper& paper,
                                       Orientation orientation,
                                       const TitleBlock& block,
                                       double margin_mm = 10.0,
                                       double title_width_mm = 120.0,
                                       const SheetStyle& style = {});
/// Draws the frame and the title block of @p layout.
void draw_sheet(Canvas& canvas,
                const SheetLayout& layout,
                const TitleBlock& block,
                const SheetStyle& style = {});

}  // namespace dtm::io::draw
