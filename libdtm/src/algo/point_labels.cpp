// SPDX-License-Identifier: MIT
// Point-feature labels (spot heights) by the eight-position model and a greedy pass in request
// order (Imhof, "Positioning names on maps", The American Cartographer 2(2), 1975: right of the
// point first, then the other corners and sides; Christensen, Marks, Shieber, ACM ToG 14(3),
// 1995, for the candidate model). Every marker is an obstacle from the start, so a text never
// hides another point; a position crossed by no line is preferred, then one crossed only by
// passable lines (contours, drawn under the text's halo). A line that must stay visible
// (breaklines, boundary, holes) is never under a text: without another position the point is
// left out and counted in `failed`.
#include <algorithm>
#include <optional>

#include "algo/detail/label_index.hpp"
#include "dtm/algo/spot_heights.hpp"
#include "dtm/core/error.hpp"

namespace dtm {

PointLabelResult place_point_labels(std::span<const PointLabelRequest> requests,
                                    std::span<const LabelLine> lines,
                                    std::span<const LabelBox> obstacles,
                                    const PointLabelOptions& options) {
    if (!(options.units_per_mm > 0.0)) {
        throw UsageError("spot height labels: the scale must be positive");
    }
    const double mm = options.units_per_mm;
    double widest = 1.0;
    for (const PointLabelRequest& r : requests) widest = std::max(widest, r.width_mm);
    detail::BoxIndex placed(widest * 1.5 * mm);
    for (const LabelBox& b : obstacles) placed.insert(b);
    PointLabelResult out;
    out.markers.reserve(requests.size());
    for (const PointLabelRequest& r : requests) {
        const double half = r.marker_radius_mm * mm;
        out.markers.push_back({r.at, {1.0, 0.0}, half, half});
        placed.insert(out.markers.back());
    }
    std::vector<std::vector<Point2>> flat;
    std::vector<detail::LinePoints> spans;
    std::optional<detail::SegmentIndex> segments;
    if (!lines.empty()) {
        flat.reserve(lines.size());
        for (const LabelLine& l : lines) {
            std::vector<Point2>& f = flat.emplace_back();
            f.reserve(l.points.size());
            for (const Point3& p : l.points) f.push_back(p.xy());
        }
        for (const auto& f : flat) spans.emplace_back(f);
        segments.emplace(spans, widest * 1.5 * mm);
    }
    const double pad = options.padding_mm * mm;
    for (std::size_t i = 0; i < requests.size(); ++i) {
        const PointLabelRequest& r = requests[i];
        const double w = r.width_mm * mm / 2.0;
        const double h = r.height_mm * mm / 2.0;
        const double d = (r.marker_radius_mm + options.offset_mm) * mm;
        const double e = d * 0.7071;
        const Point2 c = r.at;
        const Point2 centres[8] = {{c.x + d + w, c.y},         {c.x + e + w, c.y + e + h},
                                   {c.x + e + w, c.y - e - h}, {c.x - d - w, c.y},
                                   {c.x - e - w, c.y + e + h}, {c.x - e - w, c.y - e - h},
                                   {c.x, c.y + d + h},         {c.x, c.y - d - h}};
        // the first free position; else the first crossed only by passable lines (contours)
        std::optional<PointLabel> chosen;
        int chosen_class = 2;
        for (int k = 0; k < 8 && chosen_class > 0; ++k) {
            const LabelBox box{centres[k], {1.0, 0.0}, w, h};
            const LabelBox padded = box.grown(pad);
            if (options.frame && !inside(padded, *options.frame)) continue;
            if (placed.overlaps_any(padded)) continue;
            int crossing = 0;
            if (segments) {
                segments->any_crossing(box, [&](std::uint32_t line, std::uint32_t) {
                    crossing = std::max(crossing, lines[line].passable ? 1 : 2);
                    return crossing == 2;
                });
            }
            if (crossing < chosen_class) {
                chosen = PointLabel{i, box, k};
                chosen_class = crossing;
            }
        }
        if (!chosen) {
            out.failed.push_back(i);
            continue;
        }
        placed.insert(chosen->box);
        out.labels.push_back(*chosen);
    }
    return out;
}

}  // namespace dtm
