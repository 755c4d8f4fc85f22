// SPDX-License-Identifier: MIT
// The drawing page on cairo (https://www.cairographics.org/manual/): a PDF, SVG or image surface
// scaled so that one user unit is a millimetre. Text is drawn with cairo's own text API, so a PDF
// keeps it as text (pdftotext finds it; rotated text as one ActualText span per string, so it
// is read as a word); a halo is the glyph outline stroked in the halo colour underneath. The
// surface writes into an AtomicOutput's temporary, renamed on finish().
#include "dtm/io/draw/canvas.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"

namespace dtm::io::draw {
namespace {

constexpr double points_per_mm = 72.0 / 25.4;

enum class Kind { pdf, svg, png };

Kind kind_of(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".pdf") return Kind::pdf;
    if (ext == ".svg") return Kind::svg;
    if (ext == ".png") return Kind::png;
    throw UsageError("cannot draw into '" + path.string() +
                     "': the extension must be .pdf, .svg or .png");
}

void set_source(cairo_t* cr, const Color& c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }

void apply_stroke(cairo_t* cr, const Stroke& s) {
    set_source(cr, s.color);
    cairo_set_line_width(cr, s.width_mm);
    cairo_set_dash(cr, s.dash_mm.empty() ? nullptr : s.dash_mm.data(),
                   static_cast<int>(s.dash_mm.size()), 0.0);
    cairo_set_line_cap(cr, s.round ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
    cairo_set_line_join(cr, s.round ? CAIRO_LINE_JOIN_ROUND : CAIRO_LINE_JOIN_MITER);
}

void set_font(cairo_t* cr, const TextStyle& style) {
    cairo_select_font_face(cr, style.family.c_str(),
                           style.italic ? CAIRO_FONT_SLANT_ITALIC : CAIRO_FONT_SLANT_NORMAL,
                           style.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, style.size_pt / points_per_mm);
    // Unhinted metrics everywhere: text measured for layout (on a tiny image surface) must have
    // the advances the PDF, SVG and PNG pages draw, not widths rounded to whole device units.
    static thread_local std::unique_ptr<cairo_font_options_t, decltype(&cairo_font_options_destroy)>
        options(cairo_font_options_create(), &cairo_font_options_destroy);
    cairo_font_options_set_hint_metrics(options.get(), CAIRO_HINT_METRICS_OFF);
    cairo_font_options_set_hint_style(options.get(), CAIRO_HINT_STYLE_NONE);
    cairo_set_font_options(cr, options.get());
}

TextSize measure_in(cairo_t* cr, std::string_view text, const TextStyle& style) {
    const std::string s(text);
    set_font(cr, style);
    cairo_text_extents_t te;
    cairo_text_extents(cr, s.c_str(), &te);
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    return {te.x_advance, fe.ascent, fe.descent};
}

/// True for angles that are whole multiples of 90 degrees: text extractors read those runs.
bool axis_aligned(double angle_deg) {
    const double r = std::fmod(std::abs(angle_deg), 90.0);
    return r < 1e-9 || 90.0 - r < 1e-9;
}

/// Shows @p text as a single text cluster: cairo's PDF surface then wraps the glyphs in a
/// marked-content span with /ActualText (ISO 32000-1, 14.9.4), so pdftotext and viewers read
/// a rotated label as one word instead of one character per glyph.
void show_as_one_cluster(cairo_t* cr, const std::string& text, double x, double y) {
    cairo_glyph_t* glyphs = nullptr;
    int glyph_count = 0;
    cairo_text_cluster_t* clusters = nullptr;
    int cluster_count = 0;
    cairo_text_cluster_flags_t flags{};
    const int bytes = static_cast<int>(text.size());
    const cairo_status_t status =
        cairo_scaled_font_text_to_glyphs(cairo_get_scaled_font(cr), x, y, text.c_str(), bytes,
                                         &glyphs, &glyph_count, &clusters, &cluster_count, &flags);
    if (status != CAIRO_STATUS_SUCCESS) {
        cairo_show_text(cr, text.c_str());
        return;
    }
    const cairo_text_cluster_t one{bytes, glyph_count};
    cairo_show_text_glyphs(cr, text.c_str(), bytes, glyphs, glyph_count, &one, 1, flags);
    cairo_glyph_free(glyphs);
    cairo_text_cluster_free(clusters);
}

}  // namespace

struct Canvas::Impl {
    std::filesystem::path path;
    Kind kind;
    double width;
    double height;
    AtomicOutput output;
    cairo_surface_t* surface = nullptr;
    cairo_t* cr = nullptr;
    bool finished = false;

    Impl(std::filesystem::path p, double w, double h, double dpi)
        : path(std::move(p)), kind(kind_of(path)), width(w), height(h), output(path) {
        if (!(w > 0.0) || !(h > 0.0) || !std::isfinite(w) || !std::isfinite(h)) {
            throw UsageError("cannot draw a page of " + std::to_string(w) + " x " +
                             std::to_string(h) + " mm");
        }
        const std::string temp = output.temp_path().string();
        double scale = points_per_mm;
        switch (kind) {
            case Kind::pdf:
                surface =
                    cairo_pdf_surface_create(temp.c_str(), w * points_per_mm, h * points_per_mm);
                break;
            case Kind::svg:
                surface =
                    cairo_svg_surface_create(temp.c_str(), w * points_per_mm, h * points_per_mm);
                break;
            case Kind::png: {
                scale = dpi / 25.4;
                const double px = std::ceil(w * scale);
                const double py = std::ceil(h * scale);
                if (px * py > 4e8) {
                    throw UsageError("a PNG of " + std::to_string(px) + " x " + std::to_string(py) +
                                     " pixels is too large; lower the dpi");
                }
                surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(px),
                                                     static_cast<int>(py));
                break;
            }
        }
        if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
            const std::string why = cairo_status_to_string(cairo_surface_status(surface));
            cairo_surface_destroy(surface);
            throw Error("cannot create " + path.string() + ": " + why);
        }
        cr = cairo_create(surface);
        cairo_scale(cr, scale, scale);
        if (kind == Kind::png) {
            cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
            cairo_paint(cr);
        }
    }
    ~Impl() {
        if (cr != nullptr) cairo_destroy(cr);
        if (surface != nullptr) {
            cairo_surface_finish(surface);
            cairo_surface_destroy(surface);
        }
    }
    void path_of(std::span<const Point2> points, bool closed) const {
        cairo_new_path(cr);
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (i == 0) {
                cairo_move_to(cr, points[i].x, points[i].y);
            } else {
                cairo_line_to(cr, points[i].x, points[i].y);
            }
        }
        if (closed) cairo_close_path(cr);
    }
};

Canvas::Canvas(std::filesystem::path path, double width_mm, double height_mm, double png_dpi)
    : impl_(std::make_unique<Impl>(std::move(path), width_mm, height_mm, png_dpi)) {}

Canvas::~Canvas() = default;

double Canvas::width_mm() const noexcept { return impl_->width; }
double Canvas::height_mm() const noexcept { return impl_->height; }
const std::filesystem::path& Canvas::path() const noexcept { return impl_->path; }

void Canvas::polyline(std::span<const Point2> points, const Stroke& stroke, bool closed) {
    if (points.size() < 2) return;
    impl_->path_of(points, closed);
    apply_stroke(impl_->cr, stroke);
    cairo_stroke(impl_->cr);
}

void Canvas::polygon(std::span<const std::vector<Point2>> rings,
                     const Color& fill,
                     const Stroke* outline) {
    cairo_t* cr = impl_->cr;
    cairo_new_path(cr);
    for (const std::vector<Point2>& ring : rings) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
            if (i == 0) {
                cairo_move_to(cr, ring[i].x, ring[i].y);
            } else {
                cairo_line_to(cr, ring[i].x, ring[i].y);
            }
        }
        cairo_close_path(cr);
    }
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    set_source(cr, fill);
    if (outline != nullptr) {
        cairo_fill_preserve(cr);
        apply_stroke(cr, *outline);
        cairo_stroke(cr);
    } else {
        cairo_fill(cr);
    }
}

void Canvas::rectangle(
    Point2 top_left, double width, double height, const Color* fill, const Stroke* outline) {
    cairo_t* cr = impl_->cr;
    cairo_new_path(cr);
    cairo_rectangle(cr, top_left.x, top_left.y, width, height);
    if (fill != nullptr) {
        set_source(cr, *fill);
        cairo_fill_preserve(cr);
    }
    if (outline != nullptr) {
        apply_stroke(cr, *outline);
        cairo_stroke_preserve(cr);
    }
    cairo_new_path(cr);
}

void Canvas::circle(Point2 centre, double radius_mm, const Color* fill, const Stroke* outline) {
    cairo_t* cr = impl_->cr;
    cairo_new_path(cr);
    cairo_arc(cr, centre.x, centre.y, radius_mm, 0.0, 2.0 * std::numbers::pi);
    if (fill != nullptr) {
        set_source(cr, *fill);
        cairo_fill_preserve(cr);
    }
    if (outline != nullptr) {
        apply_stroke(cr, *outline);
        cairo_stroke_preserve(cr);
    }
    cairo_new_path(cr);
}

void Canvas::text(Point2 at, std::string_view text, const TextStyle& style, double angle_deg) {
    if (text.empty()) return;
    cairo_t* cr = impl_->cr;
    const TextSize size = measure_in(cr, text, style);
    double dx = 0.0;
    if (style.h == HAlign::center) dx = -size.width / 2.0;
    if (style.h == HAlign::right) dx = -size.width;
    double dy = 0.0;
    if (style.v == VAlign::middle) dy = (size.ascent - size.descent) / 2.0;
    if (style.v == VAlign::top) dy = size.ascent;
    if (style.v == VAlign::bottom) dy = -size.descent;
    const std::string s(text);
    cairo_save(cr);
    cairo_translate(cr, at.x, at.y);
    cairo_rotate(cr, -angle_deg * std::numbers::pi / 180.0);
    if (style.halo_mm > 0.0) {
        cairo_new_path(cr);
        cairo_move_to(cr, dx, dy);
        cairo_text_path(cr, s.c_str());
        set_source(cr, style.halo);
        cairo_set_line_width(cr, 2.0 * style.halo_mm);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        cairo_set_dash(cr, nullptr, 0, 0.0);
        cairo_stroke(cr);
    }
    cairo_move_to(cr, dx, dy);
    set_source(cr, style.color);
    if (axis_aligned(angle_deg)) {
        cairo_show_text(cr, s.c_str());
    } else {
        show_as_one_cluster(cr, s, dx, dy);
    }
    cairo_new_path(cr);
    cairo_restore(cr);
}

TextSize Canvas::measure(std::string_view text, const TextStyle& style) const {
    return measure_in(impl_->cr, text, style);
}

void Canvas::image(std::span<const std::uint8_t> rgba,
                   int columns,
                   int rows,
                   Point2 top_left,
                   double width_mm,
                   double height_mm) {
    if (columns <= 0 || rows <= 0 ||
        rgba.size() < static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows) * 4) {
        throw Error("draw: the image buffer does not hold columns x rows RGBA pixels");
    }
    cairo_surface_t* img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, columns, rows);
    cairo_surface_flush(img);
    unsigned char* data = cairo_image_surface_get_data(img);
    const int stride = cairo_image_surface_get_stride(img);
    for (int r = 0; r < rows; ++r) {
        auto* row =
            reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(r) * stride);
        for (int c = 0; c < columns; ++c) {
            const std::uint8_t* p =
                rgba.data() + (static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) +
                               static_cast<std::size_t>(c)) *
                                  4;
            const std::uint32_t a = p[3];
            const auto pre = [a](std::uint8_t v) {
                return (static_cast<std::uint32_t>(v) * a + 127) / 255;
            };
            row[c] = (a << 24) | (pre(p[0]) << 16) | (pre(p[1]) << 8) | pre(p[2]);
        }
    }
    cairo_surface_mark_dirty(img);
    cairo_t* cr = impl_->cr;
    cairo_save(cr);
    cairo_translate(cr, top_left.x, top_left.y);
    cairo_scale(cr, width_mm / columns, height_mm / rows);
    cairo_set_source_surface(cr, img, 0.0, 0.0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
    cairo_rectangle(cr, 0.0, 0.0, columns, rows);
    cairo_fill(cr);
    cairo_restore(cr);
    cairo_surface_destroy(img);
}

void Canvas::push_clip(Point2 top_left, double width, double height) {
    cairo_save(impl_->cr);
    cairo_new_path(impl_->cr);
    cairo_rectangle(impl_->cr, top_left.x, top_left.y, width, height);
    cairo_clip(impl_->cr);
}

void Canvas::push_clip_excluding(std::span<const std::vector<Point2>> polygons) {
    cairo_t* cr = impl_->cr;
    cairo_save(cr);
    cairo_new_path(cr);
    cairo_rectangle(cr, 0.0, 0.0, impl_->width, impl_->height);
    for (const std::vector<Point2>& ring : polygons) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
            if (i == 0) {
                cairo_move_to(cr, ring[i].x, ring[i].y);
            } else {
                cairo_line_to(cr, ring[i].x, ring[i].y);
            }
        }
        cairo_close_path(cr);
    }
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    cairo_clip(cr);
}

void Canvas::pop_clip() { cairo_restore(impl_->cr); }

void Canvas::new_page() {
    if (impl_->kind != Kind::pdf) {
        throw UsageError("only a PDF can have several pages (" + impl_->path.string() + ")");
    }
    cairo_show_page(impl_->cr);
}

void Canvas::finish() {
    Impl& d = *impl_;
    if (d.finished) return;
    if (cairo_status(d.cr) != CAIRO_STATUS_SUCCESS) {
        throw Error("cannot draw " + d.path.string() + ": " +
                    cairo_status_to_string(cairo_status(d.cr)));
    }
    cairo_status_t status = CAIRO_STATUS_SUCCESS;
    if (d.kind == Kind::png) {
        cairo_surface_flush(d.surface);
        status = cairo_surface_write_to_png(d.surface, d.output.temp_path().string().c_str());
    } else {
        cairo_surface_finish(d.surface);
        status = cairo_surface_status(d.surface);
    }
    if (status != CAIRO_STATUS_SUCCESS) {
        throw Error("cannot write " + d.path.string() + ": " + cairo_status_to_string(status));
    }
    d.output.commit();
    d.finished = true;
}

TextSize measure_text(std::string_view text, const TextStyle& style) {
    static thread_local std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1), &cairo_surface_destroy);
    static thread_local std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(
        cairo_create(surface.get()), &cairo_destroy);
    return measure_in(cr.get(), text, style);
}

}  // namespace dtm::io::draw
