// SPDX-License-Identifier: MIT
/// @file
/// @brief The labels of a contour file for CAD and GIS (`dtm contour -o .dxf/.gpkg`, `dtm build`):
/// elevation numbers on the index contours and, optionally, spot heights with their height
/// labels, placed at a drawing scale with the map's algorithms (place_contour_labels,
/// select_spot_heights, place_point_labels) and text sizes estimated from the character count
/// (no font is measured: the reading program draws the text in its own font).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dtm/algo/contour.hpp"
#include "dtm/algo/contour_labels.hpp"
#include "dtm/algo/label_box.hpp"
#include "dtm/algo/spot_heights.hpp"
#include "dtm/core/contour.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct ContourAnnotationOptions {
    /// CRS units per drawing millimetre: 1:500 in metres is 0.5.
    double units_per_mm = 0.5;
    double text_mm = 2.5;  ///< text height on paper (ISO 3098: 2.5 mm)
    /// Width of one character over the text height (digits, '.', '-' of CAD fonts such as
    /// txt.shx or Arial stay below 0.8), for the label boxes.
    double char_width = 0.8;
    double spacing_mm = 120.0;  ///< between contour labels along a line
    bool spot_heights = false;  ///< select spot heights and label them
    double spot_spacing_mm = 30.0;
    int spot_decimals = 2;  ///< decimals of the spot height texts
};

/// A spot height and its label (none when no position beside the marker was free).
struct SpotAnnotation {
    SpotHeight spot;
    std::string text;
    std::optional<LabelBox> box;  ///< the text's box, horizontal, CRS units
};

struct ContourAnnotation {
    double text_height = 0.0;  ///< CRS units
    /// Contour numbers: text, level, box (centre, baseline direction, up vector uphill) and
    /// ContourLabel::anchor, the point on the line under the label's centre.
    std::vector<ContourLabel> labels;
    std::vector<LabelFailure> failures;  ///< wanted positions without room
    std::size_t lines_too_short = 0;
    std::vector<SpotAnnotation> spots;
    std::size_t spot_labels_failed = 0;
};

/// A ContourSink that keeps every line (for annotate_contours) and passes it on to @p next.
class ContourKeeper final : public ContourSink {
public:
    explicit ContourKeeper(ContourSink& next) : next_(next) {}
    void add(const ContourLevel& level, std::span<const Point3> line, bool closed) override {
        lines_.push_back({level, {line.begin(), line.end()}, closed});
        next_.add(level, line, closed);
    }
    [[nodiscard]] const std::vector<Contour>& lines() const noexcept { return lines_; }

private:
    ContourSink& next_;
    std::vector<Contour> lines_;
};

/// "245", "247.5": the shortest decimal text that equals @p v to 1e-9.
[[nodiscard]] std::string level_text(double v);

/// Labels the index contours of @p contours (lines of @p tin) and, with spot_heights, the
/// selected spot heights; the TIN's breaklines, boundary and holes are never covered by a label.
/// Spot heights are placed first, so contour numbers keep clear of them.
/// @throws UsageError for a non-positive scale, text height or character width; Cancelled
[[nodiscard]] ContourAnnotation annotate_contours(const Tin& tin,
                                                  std::span<const Contour> contours,
                                                  const ContourAnnotationOptions& options,
                                                  const Progress& progress = {});

}  // namespace dtm
