// SPDX-License-Identifier: MIT
// Contour label placement, in the manner of Imhof's rules for contour numbers (E. Imhof,
// "Cartographic Relief Presentation", 1982, ch. 8: numbers on straight stretches, in gaps of the
// line, reading uphill, spread evenly and not crowded) and of the greedy candidate search of
// point-feature and line-feature labelling (Christensen, Marks, Shieber, "An empirical study of
// algorithms for point-feature label placement", ACM ToG 14(3), 1995; Barrault, "A methodology
// for placement and evaluation of area map labels", 2001):
//   - lines are labelled longest first; on each line the wanted positions are spread evenly,
//     spacing apart, and each wanted position is searched outwards (nearest first) for the first
//     candidate centre that passes, in order: straightness (the line stays within a fraction of
//     the text height of the chord under the label), the frame, no overlap with placed labels and
//     obstacles (separating axes, grid index), no other line crossing the box (grid index);
//   - the text's baseline runs against the line's direction: dtm's contours keep higher ground
//     on the right, so the text's up vector (baseline turned left) points uphill (ČSN 01 3411:
//     contour numbers have their top towards rising ground);
//   - a wanted position with no acceptable candidate is recorded with the furthest test any
//     candidate reached, so nothing is dropped silently.
#include "dtm/algo/contour_labels.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "algo/detail/label_index.hpp"
#include "dtm/core/error.hpp"

namespace dtm {
namespace {

constexpr double pi = 3.14159265358979323846;

/// A line flattened to xy with its cumulative arc length.
struct Path {
    std::vector<Point2> points;
    std::vector<double> at;  ///< at[i]: arc length of points[i]
    bool closed = false;
    [[nodiscard]] double length() const { return at.empty() ? 0.0 : at.back(); }

    [[nodiscard]] double wrap(double s) const {
        if (!closed) return s;
        const double l = length();
        s = std::fmod(s, l);
        return s < 0.0 ? s + l : s;
    }
    /// The point at arc length @p s (wrapped on rings, clamped on open lines).
    [[nodiscard]] Point2 point_at(double s) const {
        s = std::clamp(wrap(s), 0.0, length());
        auto it = std::upper_bound(at.begin(), at.end(), s);
        std::size_t i = it == at.begin() ? 0 : static_cast<std::size_t>(it - at.begin()) - 1;
        i = std::min(i, points.size() - 2);
        const double d = at[i + 1] - at[i];
        const double t = d > 0.0 ? (s - at[i]) / d : 0.0;
        return {points[i].x + t * (points[i + 1].x - points[i].x),
                points[i].y + t * (points[i + 1].y - points[i].y)};
    }
    /// Calls f(point) for every vertex with arc length strictly inside (s0, s1), s0 < s1; on rings
    /// the interval may run past either end.
    template <class F>
    void for_vertices(double s0, double s1, F&& f) const {
        const double l = length();
        if (closed && s0 < 0.0) {
            for_range(s0 + l, l, f);
            for_range(0.0, s1, f);
        } else if (closed && s1 > l) {
            for_range(s0, l, f);
            for_range(0.0, s1 - l, f);
        } else {
            for_range(s0, s1, f);
        }
    }
    /// True when the segment from vertex @p i overlaps the arc interval [s0, s1] (s0 < s1,
    /// possibly past the ends of a ring).
    [[nodiscard]] bool segment_in(std::size_t i, double s0, double s1) const {
        const double a = at[i];
        const double b = at[i + 1];
        const auto hit = [&](double lo, double hi) { return a <= hi && b >= lo; };
        const double l = length();
        if (closed && s0 < 0.0) return hit(s0 + l, l) || hit(0.0, s1);
        if (closed && s1 > l) return hit(s0, l) || hit(0.0, s1 - l);
        return hit(s0, s1);
    }

private:
    template <class F>
    void for_range(double s0, double s1, F& f) const {
        auto it = std::upper_bound(at.begin(), at.end(), s0);
        for (auto i = static_cast<std::size_t>(it - at.begin()); i < at.size() && at[i] < s1; ++i) {
            f(points[i]);
        }
    }
};

Path make_path(const LabelLine& line) {
    Path p;
    p.closed = line.closed;
    p.points.reserve(line.points.size());
    for (const Point3& q : line.points) {
        if (!p.points.empty() && p.points.back().x == q.x && p.points.back().y == q.y) continue;
        p.points.push_back({q.x, q.y});
    }
    if (p.closed && p.points.size() > 1 &&
        (p.points.front().x != p.points.back().x || p.points.front().y != p.points.back().y)) {
        p.points.push_back(p.points.front());
    }
    p.at.resize(p.points.size());
    double s = 0.0;
    for (std::size_t i = 0; i < p.points.size(); ++i) {
        if (i > 0)
            s += std::hypot(p.points[i].x - p.points[i - 1].x, p.points[i].y - p.points[i - 1].y);
        p.at[i] = s;
    }
    if (p.points.size() < 2) p.closed = false;
    return p;
}

/// How far a candidate got through the tests (higher is further).
enum class Stage {
    curved = 0,
    outside = 1,
    crowded = 2,
    crossed = 3,
    crossed_unlabelled = 4,
    ok = 5
};

LabelFailureReason reason_of(Stage s) {
    switch (s) {
        case Stage::curved:
            return LabelFailureReason::curved;
        case Stage::outside:
            return LabelFailureReason::outside;
        case Stage::crowded:
            return LabelFailureReason::crowded;
        default:
            return LabelFailureReason::crossed;
    }
}

class Placer {
public:
    Placer(std::span<const LabelLine> lines,
           std::span<const LabelText> texts,
           std::span<const LabelBox> obstacles,
           const ContourLabelOptions& o)
        : lines_(lines), texts_(texts), o_(o), mm_(o.units_per_mm), placed_(cell_size()) {
        paths_.reserve(lines.size());
        for (const LabelLine& l : lines) paths_.push_back(make_path(l));
        for (const LabelBox& b : obstacles) placed_.insert(b);
        if (o.avoid_lines) {
            flat_.reserve(paths_.size());
            for (const Path& p : paths_) flat_.emplace_back(p.points);
            segments_.emplace(flat_, cell_size());
        }
    }

    void place_line(std::size_t index, ContourLabelResult& out) {
        const LabelLine& line = lines_[index];
        const LabelText& text = texts_[line.text];
        const Path& path = paths_[index];
        const double w = text.width_mm * mm_;
        const double h = text.height_mm * mm_;
        const double l = path.length();
        ++out.lines_labelled;
        if (!(w > 0.0) || !(h > 0.0) || path.points.size() < 2) {
            ++out.lines_too_short;
            return;
        }
        double a = 0.0;
        double b = l;
        std::size_t wanted = 1;
        if (path.closed) {
            if (l < pi * w) {
                ++out.lines_too_short;
                return;
            }
            wanted = std::max<std::size_t>(1, static_cast<std::size_t>(l / (o_.spacing_mm * mm_)));
        } else {
            a = o_.end_margin_mm * mm_ + w / 2.0;
            b = l - a;
            if (b < a) {
                ++out.lines_too_short;
                return;
            }
            wanted = std::max<std::size_t>(
                1, static_cast<std::size_t>(std::lround((b - a) / (o_.spacing_mm * mm_))));
        }
        const double step = (b - a) / static_cast<double>(wanted);
        for (std::size_t k = 0; k < wanted; ++k) {
            const double target = a + (static_cast<double>(k) + 0.5) * step;
            place_near(index, text, target, step / 2.0, a, b, out);
        }
    }

private:
    [[nodiscard]] double cell_size() const {
        double widest = 0.0;
        for (const LabelText& t : texts_) widest = std::max(widest, t.width_mm);
        return std::max(widest, 1.0) * 1.5 * mm_;
    }

    void place_near(std::size_t index,
                    const LabelText& text,
                    double target,
                    double reach,
                    double lo,
                    double hi,
                    ContourLabelResult& out) {
        const Path& path = paths_[index];
        const double step = o_.search_step_mm * mm_;
        Stage best = Stage::curved;
        std::optional<ContourLabel> fallback;
        const auto count = static_cast<long>(std::floor(reach / step));
        for (long i = 0; i <= 2 * count; ++i) {
            // 0, +1, -1, +2, -2, ... steps from the target
            const double offset =
                static_cast<double>((i + 1) / 2) * step * (i % 2 == 1 ? 1.0 : -1.0);
            const double s = target + offset;
            if (!path.closed && (s < lo || s > hi)) continue;
            ContourLabel label;
            const Stage stage = evaluate(index, text, s, label);
            best = std::max(best, stage);
            if (stage == Stage::ok) {
                accept(label, out);
                return;
            }
            if (stage == Stage::crossed_unlabelled && !fallback) fallback = label;
        }
        if (fallback && o_.allow_crossing_unlabelled) {
            fallback->crosses_lines = true;
            accept(*fallback, out);
            return;
        }
        out.failures.push_back(
            {index, lines_[index].level, path.point_at(target), reason_of(best)});
    }

    /// The box that takes part in overlap tests.
    [[nodiscard]] LabelBox footprint(const LabelBox& box) const {
        return o_.axis_aligned_clearance ? LabelBox::of(box.bounds()) : box;
    }

    void accept(const ContourLabel& label, ContourLabelResult& out) {
        placed_.insert(footprint(label.box));
        out.labels.push_back(label);
    }

    Stage evaluate(std::size_t index, const LabelText& text, double s, ContourLabel& label) const {
        const Path& path = paths_[index];
        const double w = text.width_mm * mm_;
        const double h = text.height_mm * mm_;
        const double s0 = s - w / 2.0;
        const double s1 = s + w / 2.0;
        const Point2 p0 = path.point_at(s0);
        const Point2 p1 = path.point_at(s1);
        const double dx = p1.x - p0.x;
        const double dy = p1.y - p0.y;
        const double chord = std::hypot(dx, dy);
        if (chord < 0.9 * w) return Stage::curved;
        const Point2 walk{dx / chord, dy / chord};
        const double tolerance = o_.max_deviation * h;
        bool straight = true;
        path.for_vertices(s0, s1, [&](Point2 q) {
            const double rx = q.x - p0.x;
            const double ry = q.y - p0.y;
            if (std::abs(rx * walk.y - ry * walk.x) > tolerance) straight = false;
        });
        if (!straight) return Stage::curved;
        label.line = index;
        label.level = lines_[index].level;
        label.text = text.text;
        // Baseline against the walking direction: up = right of the walk = uphill.
        label.box = {
            {(p0.x + p1.x) / 2.0, (p0.y + p1.y) / 2.0}, {-walk.x, -walk.y}, w / 2.0, h / 2.0};
        const double gap = o_.gap_mm * mm_;
        label.cut_begin = path.closed ? path.wrap(s0 - gap) : std::max(s0 - gap, 0.0);
        label.cut_end = path.closed ? path.wrap(s1 + gap) : std::min(s1 + gap, path.length());
        const LabelBox padded = label.box.grown(o_.padding_mm * mm_);
        if (o_.frame && !inside(padded, *o_.frame)) return Stage::outside;
        if (placed_.overlaps_any(footprint(label.box).grown(o_.padding_mm * mm_))) {
            return Stage::crowded;
        }
        if (!segments_) return Stage::ok;
        const LabelBox clear = label.box.grown(o_.padding_mm * mm_ / 2.0);
        bool under = false;  // an unlabelled line passes under the label
        const bool crossed = segments_->any_crossing(clear, [&](std::uint32_t l, std::uint32_t i) {
            if (l == index && path.segment_in(i, s0 - gap, s1 + gap)) return false;
            if (lines_[l].text != LabelLine::no_label || !lines_[l].passable) {
                return true;  // out: stop looking
            }
            under = true;
            return false;
        });
        if (crossed) return Stage::crossed;
        return under ? Stage::crossed_unlabelled : Stage::ok;
    }

    std::span<const LabelLine> lines_;
    std::span<const LabelText> texts_;
    const ContourLabelOptions& o_;
    double mm_;
    std::vector<Path> paths_;
    std::vector<detail::LinePoints> flat_;
    std::optional<detail::SegmentIndex> segments_;
    detail::BoxIndex placed_;
};

}  // namespace

double ContourLabel::angle_deg() const noexcept {
    return std::atan2(box.axis.y, box.axis.x) * 180.0 / pi;
}

const char* to_string(LabelFailureReason reason) noexcept {
    switch (reason) {
        case LabelFailureReason::curved:
            return "no straight stretch";
        case LabelFailureReason::crowded:
            return "no room among other labels";
        case LabelFailureReason::crossed:
            return "crossed by other lines";
        case LabelFailureReason::outside:
            return "outside the frame";
    }
    return "unknown";
}

ContourLabelResult place_contour_labels(std::span<const LabelLine> lines,
                                        std::span<const LabelText> texts,
                                        std::span<const LabelBox> obstacles,
                                        const ContourLabelOptions& options,
                                        const Progress& progress) {
    if (!(options.units_per_mm > 0.0) || !(options.spacing_mm > 0.0) ||
        !(options.search_step_mm > 0.0)) {
        throw UsageError(
            "contour labels: the scale, the label spacing and the search step must be positive");
    }
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].text == LabelLine::no_label) continue;
        if (lines[i].text >= texts.size()) {
            throw UsageError("contour labels: line " + std::to_string(i) + " names text " +
                             std::to_string(lines[i].text) + " of " + std::to_string(texts.size()));
        }
        order.push_back(i);
    }
    Placer placer(lines, texts, obstacles, options);
    std::vector<double> length(lines.size(), 0.0);
    for (const std::size_t i : order) {
        for (std::size_t k = 1; k < lines[i].points.size(); ++k) {
            length[i] += std::hypot(lines[i].points[k].x - lines[i].points[k - 1].x,
                                    lines[i].points[k].y - lines[i].points[k - 1].y);
        }
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return length[a] > length[b]; });
    ContourLabelResult out;
    for (std::size_t n = 0; n < order.size(); ++n) {
        if (n % 64 == 0) {
            progress.report(static_cast<double>(n) / static_cast<double>(order.size()),
                            "placing contour labels");
        }
        placer.place_line(order[n], out);
    }
    progress.report(1.0, "placing contour labels");
    return out;
}

}  // namespace dtm
