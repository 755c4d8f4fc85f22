// SPDX-License-Identifier: MIT
// Labels of a contour file: the map's placement (contour_labels.cpp, spot_heights.cpp,
// point_labels.cpp; docs/algorithms/map_labels.md) at a drawing scale, with text boxes from the
// character count instead of a measured font. Spot heights go first and are obstacles for the
// contour numbers; breaklines, boundary and holes are lines no label may cover; unlabelled
// contours may pass under a number as in the map (CAD users mask or break them there).
#include "dtm/algo/contour_annotation.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "dtm/algo/constraint_lines.hpp"
#include "dtm/core/error.hpp"

namespace dtm {

std::string level_text(double v) {
    for (int d = 0; d <= 6; ++d) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*f", d, v);
        if (std::abs(std::strtod(buf, nullptr) - v) < 1e-9) {
            std::string s = buf;
            return s == "-0" ? "0" : s;
        }
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

ContourAnnotation annotate_contours(const Tin& tin,
                                    std::span<const Contour> contours,
                                    const ContourAnnotationOptions& o,
                                    const Progress& progress) {
    if (!(o.units_per_mm > 0.0) || !(o.text_mm > 0.0) || !(o.char_width > 0.0)) {
        throw UsageError(
            "contour labels: the scale, the text height and the character width must be positive");
    }
    ContourAnnotation out;
    out.text_height = o.text_mm * o.units_per_mm;
    const auto text_of = [&](const std::string& t) {
        return LabelText{t, o.char_width * o.text_mm * static_cast<double>(t.size()), o.text_mm};
    };
    std::vector<LabelLine> lines;
    std::vector<LabelText> texts;
    std::map<double, std::size_t> text_index;
    for (const Contour& c : contours) {
        LabelLine line{c.line, c.closed, c.level.value, LabelLine::no_label};
        if (c.level.index) {
            const auto [it, fresh] = text_index.try_emplace(c.level.value, texts.size());
            if (fresh) texts.push_back(text_of(level_text(c.level.value)));
            line.text = it->second;
        }
        lines.push_back(line);
    }
    const std::vector<ConstraintLine> constraints = constraint_lines(tin);
    for (const ConstraintLine& l : constraints) {
        LabelLine line{l.points, l.closed, 0.0, LabelLine::no_label};
        line.passable = false;
        lines.push_back(line);
    }
    std::vector<LabelBox> obstacles;
    if (o.spot_heights) {
        SpotHeightOptions so;
        so.spacing = o.spot_spacing_mm * o.units_per_mm;
        const SpotHeightResult selected = select_spot_heights(tin, so, progress.sub(0.0, 0.3));
        std::vector<PointLabelRequest> requests;
        for (const SpotHeight& s : selected.spots) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "%.*f", o.spot_decimals, s.point.z);
            const LabelText t = text_of(buf);
            requests.push_back({s.point.xy(), 0.5, t.width_mm, t.height_mm});
            out.spots.push_back({s, buf, std::nullopt});
        }
        PointLabelOptions po;
        po.units_per_mm = o.units_per_mm;
        const PointLabelResult placed = place_point_labels(requests, lines, {}, po);
        for (const PointLabel& l : placed.labels) {
            out.spots[l.request].box = l.box;
            obstacles.push_back(l.box);
        }
        obstacles.insert(obstacles.end(), placed.markers.begin(), placed.markers.end());
        out.spot_labels_failed = placed.failed.size();
    }
    ContourLabelOptions co;
    co.units_per_mm = o.units_per_mm;
    co.spacing_mm = o.spacing_mm;
    // the text stands on the line (ContourLabel::anchor), up to max_deviation x height off the
    // box centre: the padding covers that shift for both neighbours
    co.padding_mm = 1.5;
    ContourLabelResult placed = place_contour_labels(lines, texts, obstacles, co,
                                                     progress.sub(o.spot_heights ? 0.3 : 0.0, 1.0));
    out.labels = std::move(placed.labels);
    out.failures = std::move(placed.failures);
    out.lines_too_short = placed.lines_too_short;
    return out;
}

}  // namespace dtm
