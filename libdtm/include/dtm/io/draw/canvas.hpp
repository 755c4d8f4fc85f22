// SPDX-License-Identifier: MIT
/// @file
/// @brief A page to draw on in millimetres, written as PDF, SVG or PNG (by extension) through
/// cairo: the one drawing surface of dtm's plots, profiles and maps (ADR 0005). Paths stay
/// vectors and text stays text in PDF and SVG. The file is written atomically on finish().
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm::io::draw {

struct Color {
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;
    double a = 1.0;
    /// From 0xRRGGBB.
    [[nodiscard]] static Color rgb(std::uint32_t hex, double alpha = 1.0) noexcept {
        return {static_cast<double>((hex >> 16) & 0xff) / 255.0,
                static_cast<double>((hex >> 8) & 0xff) / 255.0,
                static_cast<double>(hex & 0xff) / 255.0, alpha};
    }
};

struct Stroke {
    Color color;
    double width_mm = 0.25;
    std::vector<double> dash_mm;  ///< on/off lengths; empty: solid
    bool round = false;           ///< round caps and joins (default: butt caps, miter joins)

    /// A solid line of @p color, @p width_mm wide.
    [[nodiscard]] static Stroke solid(Color color, double width_mm, bool round = false) {
        Stroke s;
        s.color = color;
        s.width_mm = width_mm;
        s.round = round;
        return s;
    }
};

enum class HAlign { left, center, right };
enum class VAlign { baseline, middle, top, bottom };

struct TextStyle {
    double size_pt = 8.0;
    Color color;
    bool bold = false;
    bool italic = false;
    std::string family = "DejaVu Sans";
    HAlign h = HAlign::left;
    VAlign v = VAlign::baseline;
    double halo_mm = 0.0;  ///< a white outline this wide behind the glyphs (map labels)
    Color halo = Color::rgb(0xffffff);
};

/// The size of a piece of text as drawn, in mm: advance width, and height above and below the
/// baseline.
struct TextSize {
    double width = 0.0;
    double ascent = 0.0;
    double descent = 0.0;
};

/// Page coordinates: millimetres from the top-left corner, x to the right, y down.
class Canvas {
public:
    /// Opens @p path (.pdf, .svg or .png; anything else is a UsageError) as a page of
    /// @p width_mm x @p height_mm. PNG is rasterised at @p png_dpi on a white background.
    Canvas(std::filesystem::path path, double width_mm, double height_mm, double png_dpi = 150.0);
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;
    /// Without finish() the file is not written (and an existing one is left untouched).
    ~Canvas();

    [[nodiscard]] double width_mm() const noexcept;
    [[nodiscard]] double height_mm() const noexcept;
    [[nodiscard]] const std::filesystem::path& path() const noexcept;

    void polyline(std::span<const Point2> points, const Stroke& stroke, bool closed = false);
    /// Fills the rings (even-odd rule: inner rings are holes), then strokes them if @p outline.
    void polygon(std::span<const std::vector<Point2>> rings,
                 const Color& fill,
                 const Stroke* outline = nullptr);
    void rectangle(
        Point2 top_left, double width, double height, const Color* fill, const Stroke* outline);
    void circle(Point2 centre, double radius_mm, const Color* fill, const Stroke* outline);
    /// UTF-8 @p text at @p at, rotated by @p angle_deg counter-clockwise (as read on the page).
    /// In a PDF, text at angles other than multiples of 90 degrees carries an /ActualText span,
    /// so text extraction (pdftotext) and search read it as one word.
    void text(Point2 at, std::string_view text, const TextStyle& style, double angle_deg = 0.0);
    [[nodiscard]] TextSize measure(std::string_view text, const TextStyle& style) const;
    /// An RGBA image (row-major, 8 bits a channel, not premultiplied) scaled into the rectangle.
    void image(std::span<const std::uint8_t> rgba,
               int columns,
               int rows,
               Point2 top_left,
               double width_mm,
               double height_mm);
    /// Limits drawing to a rectangle until pop_clip().
    void push_clip(Point2 top_left, double width, double height);
    /// Limits drawing to the page minus the given convex polygons (e.g. the boxes of map labels
    /// that interrupt lines) until pop_clip(). The polygons must not overlap each other.
    void push_clip_excluding(std::span<const std::vector<Point2>> polygons);
    void pop_clip();
    /// Starts a new page of the same size (PDF: a second page; SVG and PNG: refused).
    void new_page();
    /// Writes the file (atomically: temporary sibling, then rename). @throws Error on failure.
    void finish();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Text size without a page (same fonts and metrics as Canvas::measure).
[[nodiscard]] TextSize measure_text(std::string_view text, const TextStyle& style);

}  // namespace dtm::io::draw
