// SPDX-License-Identifier: MIT
// HP-GL plotter state machine: executes tokenized instructions and records what a pen plotter
// would draw, in plotter units (40 per mm) in the logical plotter frame.
//
// State follows the HP-GL/2 reference: pen position, pen up/down, absolute (PA) or relative (PR)
// coordinates, selected pen (SP; pen 0 draws nothing), scaling points P1/P2 (IP, IR; PS sets the
// page) and user units (SC types 0 anisotropic, 1 isotropic, 2 point-factor), symbol mode (SM
// plots a symbol at every vertex of PA/PD/PR/PU/PE), label direction and size (DI/DR, SI/SR,
// only used to advance the pen after LB). CI circles are recorded as markers at their centre,
// AA/AR arcs as chords (default 5 degrees). Consecutive pen-down strokes of the same pen that
// start where the previous one ended are joined into one polyline. RO is accepted but
// coordinates stay in the rotated (logical) frame the file was written in, which is the frame
// users read control points from; IW clipping is not applied.
// Reference: HP-GL/2 and HP RTL Reference Guide (Hewlett-Packard, 1997), chapters 4-7.
#include "io/formats/hpgl/hpgl_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "io/formats/hpgl/hpgl_lexer.hpp"

namespace dtm::io::hpgl {
namespace {

constexpr double default_page_width = 10365.0;  // A4 landscape hard-clip limits, plotter units
constexpr double default_page_height = 7962.0;
constexpr double cm = 10.0 * units_per_mm;

constexpr int code(const char (&name)[3]) { return name[0] * 256 + name[1]; }
constexpr int code(char first, char second) { return first * 256 + second; }

/// Instructions understood and deliberately without effect on the recorded geometry.
constexpr std::array<int, 66> ignored = [] {
    std::array<int, 66> list{
        code("AC"), code("AF"), code("AH"), code("AP"), code("BF"), code("BL"), code("BP"),
        code("CA"), code("CC"), code("CM"), code("CO"), code("CP"), code("CR"), code("CS"),
        code("CT"), code("CV"), code("DL"), code("DS"), code("DV"), code("EA"), code("EC"),
        code("EP"), code("ER"), code("ES"), code("EW"), code("FP"), code("FR"), code("FS"),
        code("FT"), code("GM"), code("IM"), code("IV"), code("IW"), code("KY"), code("LA"),
        code("LM"), code("LO"), code("LT"), code("MC"), code("MG"), code("NP"), code("NR"),
        code("OA"), code("OC"), code("OE"), code("OH"), code("OI"), code("OP"), code("OS"),
        code("PB"), code("PC"), code("PG"), code("PM"), code("PP"), code("PT"), code("PW"),
        code("QL"), code("RA"), code("RF"), code("RR"), code("SA"), code("SL"), code("SS"),
        code("TD"), code("TR"), code("UL")};
    std::sort(list.begin(), list.end());
    return list;
}();
constexpr std::array<int, 8> also_ignored{code("SV"), code("TL"), code("VS"), code("WD"),
                                          code("WG"), code("WU"), code("XT"), code("YT")};

bool is_ignored(int name) {
    return std::binary_search(ignored.begin(), ignored.end(), name) ||
           std::find(also_ignored.begin(), also_ignored.end(), name) != also_ignored.end();
}

class Plotter {
public:
    Plotter(Plot& plot, Diagnostics& diag, const PlotOptions& options)
        : plot_(plot), diag_(diag), options_(options) {
        reset(true);
    }

    void execute(const Command& c);
    void finish();

private:
    void reset(bool initialize);
    void select_pen(const Command& c);
    void moves(const Command& c);
    void pe(const Command& c);
    void segment_to(Point2 target, bool symbol);
    void start_line();
    void circle(const Command& c);
    void arc(const Command& c, bool relative);
    void label(const Command& c);
    void scaling_points(const Command& c, bool percent);
    void update_scaling(std::size_t offset);
    void isotropic(double left, double bottom);
    void label_direction(const Command& c, bool relative);
    void label_size(const Command& c, bool relative);
    void unknown(const Command& c);

    [[nodiscard]] Point2 to_plotter(double x, double y) const {
        return {ax_ * x + bx_, ay_ * y + by_};
    }
    [[nodiscard]] Point2 delta(double dx, double dy) const { return {ax_ * dx, ay_ * dy}; }

    Plot& plot_;
    Diagnostics& diag_;
    const PlotOptions& options_;
    Point2 pos_;
    bool pen_down_ = false;
    bool absolute_ = true;
    int pen_ = 1;
    char symbol_ = 0;
    std::size_t offset_ = 0;
    long line_ = -1;  ///< index of the polyline being drawn, -1 when none
    double page_w_ = default_page_width, page_h_ = default_page_height;
    Point2 p1_, p2_;
    std::vector<double> sc_;                            ///< last SC parameters (empty: scaling off)
    double ax_ = 1.0, bx_ = 0.0, ay_ = 1.0, by_ = 0.0;  ///< user units -> plotter units
    double dir_x_ = 1.0, dir_y_ = 0.0;
    double char_w_ = 0.19 * cm, char_h_ = 0.27 * cm;
    std::size_t odd_coordinates_ = 0;
    long rotation_ = 0;  ///< RO angle; 90 and 270 swap the page axes of the logical frame

    [[nodiscard]] Point2 page() const {
        const bool swapped = ((rotation_ % 180) + 180) % 180 == 90;
        return swapped ? Point2{page_h_, page_w_} : Point2{page_w_, page_h_};
    }
};

void Plotter::reset(bool initialize) {
    absolute_ = true;
    symbol_ = 0;
    sc_.clear();
    ax_ = ay_ = 1.0;
    bx_ = by_ = 0.0;
    dir_x_ = 1.0;
    dir_y_ = 0.0;
    char_w_ = 0.19 * cm;
    char_h_ = 0.27 * cm;
    if (!initialize) return;
    pen_down_ = false;
    line_ = -1;
    pos_ = {};
    rotation_ = 0;
    p1_ = {};
    p2_ = page();
}

void Plotter::execute(const Command& c) {
    ++plot_.instructions;
    offset_ = c.offset;
    switch (code(c.name[0], c.name[1])) {
        case code("IN"):
            reset(true);
            break;
        case code("DF"):
            reset(false);
            break;
        case code("SP"):
            select_pen(c);
            break;
        case code("PU"):
            pen_down_ = false;
            line_ = -1;
            moves(c);
            break;
        case code("PD"):
            pen_down_ = true;
            if (c.params.empty()) start_line();
            moves(c);
            break;
        case code("PA"):
            absolute_ = true;
            moves(c);
            break;
        case code("PR"):
            absolute_ = false;
            moves(c);
            break;
        case code("PE"):
            pe(c);
            break;
        case code("CI"):
            circle(c);
            break;
        case code("AA"):
            arc(c, false);
            break;
        case code("AR"):
            arc(c, true);
            break;
        case code("LB"):
            label(c);
            break;
        case code("SM"):
            symbol_ = c.text.empty() ? '\0' : c.text[0];
            break;
        case code("DT"):
            break;  // handled by the tokenizer
        case code("IP"):
            scaling_points(c, false);
            break;
        case code("IR"):
            scaling_points(c, true);
            break;
        case code("SC"):
            sc_ = c.params;
            update_scaling(c.offset);
            break;
        case code("RO"):
            rotation_ = c.params.empty() ? 0 : static_cast<long>(c.params[0]);
            break;
        case code("PS"):
            if (c.params.size() >= 1 && c.params[0] > 0) page_w_ = c.params[0];
            if (c.params.size() >= 2 && c.params[1] > 0) page_h_ = c.params[1];
            p1_ = {};
            p2_ = page();
            update_scaling(c.offset);
            break;
        case code("DI"):
            label_direction(c, false);
            break;
        case code("DR"):
            label_direction(c, true);
            break;
        case code("SI"):
            label_size(c, false);
            break;
        case code("SR"):
            label_size(c, true);
            break;
        default:
            unknown(c);
            break;
    }
}

void Plotter::unknown(const Command& c) {
    const int name = code(c.name[0], c.name[1]);
    if (is_ignored(name)) return;
    ++plot_.unknown_instructions;
    const std::string mnemonic{c.name[0], c.name[1]};
    if (plot_.unknown_names.size() < 60 &&
        plot_.unknown_names.find(mnemonic) == std::string::npos) {
        if (!plot_.unknown_names.empty()) plot_.unknown_names += ' ';
        plot_.unknown_names += mnemonic;
    }
}

void Plotter::select_pen(const Command& c) {
    const double pen = c.params.empty() ? 0.0 : c.params[0];
    pen_ = (pen >= 0.0 && pen < 1e6) ? static_cast<int>(pen) : 0;
    line_ = -1;
}

void Plotter::moves(const Command& c) {
    const auto& p = c.params;
    if (p.size() % 2 != 0) ++odd_coordinates_;
    for (std::size_t i = 0; i + 1 < p.size(); i += 2) {
        const Point2 target =
            absolute_ ? to_plotter(p[i], p[i + 1])
                      : Point2{pos_.x + delta(p[i], p[i + 1]).x, pos_.y + delta(p[i], p[i + 1]).y};
        segment_to(target, true);
    }
}

void Plotter::pe(const Command& c) {
    // Each pair is a pen-down move unless flagged pen-up; the pen stays as the last pair left it.
    for (const PeItem& item : c.pe) {
        if (item.kind == PeItem::Kind::pen) {
            pen_ = std::max(0, item.pen);
            line_ = -1;
            continue;
        }
        const Point2 target = item.absolute ? to_plotter(item.x, item.y)
                                            : Point2{pos_.x + delta(item.x, item.y).x,
                                                     pos_.y + delta(item.x, item.y).y};
        pen_down_ = item.kind == PeItem::Kind::draw;
        if (!pen_down_) line_ = -1;
        segment_to(target, true);
    }
}

void Plotter::start_line() {
    if (pen_ == 0 || line_ >= 0) return;
    auto& lines = plot_.lines;
    if (!lines.empty() && lines.back().pen == pen_ && lines.back().points.back() == pos_) {
        line_ = static_cast<long>(lines.size()) - 1;  // continue the previous stroke
        return;
    }
    lines.push_back({pen_, {pos_}, offset_});
    line_ = static_cast<long>(lines.size()) - 1;
}

void Plotter::segment_to(Point2 target, bool symbol) {
    if (!std::isfinite(target.x) || !std::isfinite(target.y)) {
        diag_.problem(offset_, "coordinate out of range");
        return;
    }
    if (pen_ != 0 && pen_down_) {
        start_line();
        auto& points = plot_.lines[static_cast<std::size_t>(line_)].points;
        if (!(points.back() == target)) points.push_back(target);
    }
    pos_ = target;
    if (symbol && symbol_ != 0 && pen_ != 0) {
        plot_.markers.push_back({pos_, MarkerKind::symbol, pen_, offset_});
    }
}

void Plotter::circle(const Command& c) {
    line_ = -1;
    if (c.params.empty() || pen_ == 0) return;
    const double radius = std::abs(c.params[0] * ax_);
    if (radius <= options_.circle_marker_radius) {
        plot_.markers.push_back({pos_, MarkerKind::circle, pen_, offset_});
    }
}

void Plotter::arc(const Command& c, bool relative) {
    const auto& p = c.params;
    if (p.size() < 3) return;
    const Point2 centre = relative
                              ? Point2{pos_.x + delta(p[0], p[1]).x, pos_.y + delta(p[0], p[1]).y}
                              : to_plotter(p[0], p[1]);
    const double sweep = std::clamp(p[2], -360.0, 360.0) * std::numbers::pi / 180.0;
    const double chord =
        std::clamp(p.size() >= 4 ? std::abs(p[3]) : 5.0, 0.5, 180.0) * std::numbers::pi / 180.0;
    const double radius = std::hypot(pos_.x - centre.x, pos_.y - centre.y);
    const double start = std::atan2(pos_.y - centre.y, pos_.x - centre.x);
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / chord)));
    for (int i = 1; i <= steps; ++i) {
        const double angle = start + sweep * i / steps;
        segment_to({centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)},
                   i == steps);
    }
}

void Plotter::label(const Command& c) {
    if (pen_ != 0) plot_.labels.push_back({pen_, pos_, std::string(c.text), c.offset});
    line_ = -1;
    // Advance the pen as the plotter would (character cell 1.5 x width, line 2 x height).
    const Point2 start = pos_;
    double column = 0.0, row = 0.0;
    for (const char ch : c.text) {
        if (ch == '\r') {
            column = 0.0;
        } else if (ch == '\n') {
            row -= 2.0 * char_h_;
        } else if (static_cast<unsigned char>(ch) >= ' ') {
            column += 1.5 * char_w_;
        }
    }
    pos_ = {start.x + column * dir_x_ - row * dir_y_, start.y + column * dir_y_ + row * dir_x_};
}

void Plotter::scaling_points(const Command& c, bool percent) {
    const auto& p = c.params;
    const Point2 size{p2_.x - p1_.x, p2_.y - p1_.y};
    const Point2 page_size = page();
    if (p.empty()) {
        p1_ = {};
        p2_ = page_size;
    } else if (p.size() >= 2) {
        p1_ = percent ? Point2{p[0] / 100.0 * page_size.x, p[1] / 100.0 * page_size.y}
                      : Point2{p[0], p[1]};
        if (p.size() >= 4) {
            p2_ = percent ? Point2{p[2] / 100.0 * page_size.x, p[3] / 100.0 * page_size.y}
                          : Point2{p[2], p[3]};
        } else {
            p2_ = {p1_.x + size.x, p1_.y + size.y};
        }
    }
    update_scaling(c.offset);
}

void Plotter::update_scaling(std::size_t offset) {
    ax_ = ay_ = 1.0;
    bx_ = by_ = 0.0;
    if (sc_.size() < 4) return;
    const double type = sc_.size() >= 5 ? sc_[4] : 0.0;
    if (type == 2.0) {  // point factor: xmin, xfactor, ymin, yfactor
        ax_ = sc_[1];
        ay_ = sc_[3];
        bx_ = p1_.x - ax_ * sc_[0];
        by_ = p1_.y - ay_ * sc_[2];
        return;
    }
    if (sc_[1] == sc_[0] || sc_[3] == sc_[2]) {
        diag_.problem(offset, "SC with an empty user-unit range ignored");
        sc_.clear();
        return;
    }
    if (type == 1.0) {
        isotropic(sc_.size() >= 6 ? sc_[5] : 50.0, sc_.size() >= 7 ? sc_[6] : 50.0);
        return;
    }
    ax_ = (p2_.x - p1_.x) / (sc_[1] - sc_[0]);
    ay_ = (p2_.y - p1_.y) / (sc_[3] - sc_[2]);
    bx_ = p1_.x - ax_ * sc_[0];
    by_ = p1_.y - ay_ * sc_[2];
}

void Plotter::isotropic(double left, double bottom) {
    const double sx = (p2_.x - p1_.x) / (sc_[1] - sc_[0]);
    const double sy = (p2_.y - p1_.y) / (sc_[3] - sc_[2]);
    const double s = std::min(std::abs(sx), std::abs(sy));
    ax_ = std::copysign(s, sx);
    ay_ = std::copysign(s, sy);
    const double spare_x = std::abs(p2_.x - p1_.x) - s * std::abs(sc_[1] - sc_[0]);
    const double spare_y = std::abs(p2_.y - p1_.y) - s * std::abs(sc_[3] - sc_[2]);
    bx_ = p1_.x + std::copysign(spare_x * left / 100.0, sx) - ax_ * sc_[0];
    by_ = p1_.y + std::copysign(spare_y * bottom / 100.0, sy) - ay_ * sc_[2];
}

void Plotter::label_direction(const Command& c, bool relative) {
    double run = c.params.size() >= 2 ? c.params[0] : 1.0;
    double rise = c.params.size() >= 2 ? c.params[1] : 0.0;
    if (relative) {
        run *= p2_.x - p1_.x;
        rise *= p2_.y - p1_.y;
    }
    const double length = std::hypot(run, rise);
    if (length > 0.0 && std::isfinite(length)) {
        dir_x_ = run / length;
        dir_y_ = rise / length;
    }
}

void Plotter::label_size(const Command& c, bool relative) {
    if (c.params.size() < 2) {
        char_w_ = 0.19 * cm;
        char_h_ = 0.27 * cm;
        return;
    }
    char_w_ = relative ? c.params[0] / 100.0 * std::abs(p2_.x - p1_.x) : c.params[0] * cm;
    char_h_ = relative ? c.params[1] / 100.0 * std::abs(p2_.y - p1_.y) : c.params[1] * cm;
}

void Plotter::finish() {
    if (odd_coordinates_ > 0) {
        diag_.warn(std::to_string(odd_coordinates_) +
                   " instructions had an odd number of coordinates (last one ignored)");
    }
}

}  // namespace

Plot plot_hpgl(std::string_view bytes,
               const std::filesystem::path& file,
               const PlotOptions& options,
               const Progress& progress) {
    Plot plot;
    Diagnostics diag(file, options.strict);
    Lexer lexer(bytes, diag);
    Plotter plotter(plot, diag, options);
    Command command;
    std::size_t count = 0;
    while (lexer.next(command)) {
        plotter.execute(command);
        if ((++count & 0xFFFF) == 0 && !bytes.empty()) {
            progress.report(
                static_cast<double>(lexer.position()) / static_cast<double>(bytes.size()),
                "reading HPGL");
        }
    }
    plotter.finish();
    lexer.finish();
    if (!lexer.saw_hpgl() && !bytes.empty()) diag.warn("no HP-GL instructions found");
    plot.problems = diag.problems();
    plot.warnings = diag.take_warnings();
    return plot;
}

}  // namespace dtm::io::hpgl
