// SPDX-License-Identifier: MIT
/// @file
/// @brief Placing elevation labels along contour lines: on straight-enough stretches, rotated
/// along the line, reading uphill (the top of the numerals faces higher ground, ČSN 01 3411),
/// spaced along each line, never overlapping each other or given obstacles (spot heights,
/// furniture), not crossed by other lines, and every position that found no room counted.
/// Used by the map sheet (`dtm map`), the DXF contour labels and the GeoPackage label layer.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dtm/algo/label_box.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"

namespace dtm {

/// The text of a label and its size as drawn, in page millimetres (the caller measures it, e.g.
/// with io::draw::measure_text: width = advance, height = ascent + descent).
struct LabelText {
    std::string text;
    double width_mm = 0.0;
    double height_mm = 0.0;
};

/// One line taking part in placement. Every line is an obstacle (labels are not crossed by
/// other lines); only lines with a text get labels.
struct LabelLine {
    /// CRS units. dtm's contour convention: higher ground on the right when walking along the
    /// line (Contour, ContourSink). A closed ring repeats its first point last.
    std::span<const Point3> points;
    bool closed = false;
    double level = 0.0;
    /// Index into the texts; no_label: the line is only an obstacle.
    std::size_t text = no_label;
    /// A line without a text that a label may cover when nothing better is near (the caller
    /// interrupts it under the label, see allow_crossing_unlabelled). false: labels never cover
    /// it (breaklines, boundaries).
    bool passable = true;
    static constexpr std::size_t no_label = static_cast<std::size_t>(-1);
};

struct ContourLabelOptions {
    /// CRS units per page millimetre: the map scale (1:500 with metres: 0.5). Distances below
    /// are in page millimetres and converted with it; with units_per_mm = 1 they are CRS units.
    double units_per_mm = 1.0;
    double spacing_mm = 120.0;  ///< distance along a line between neighbouring labels
    double padding_mm = 0.8;    ///< free space kept around every label box
    double gap_mm = 0.6;        ///< the line is cut this much beyond each end of its label
    /// Straightness: the line may leave the label's baseline chord by at most this fraction of
    /// the text height over the label's length.
    double max_deviation = 0.25;
    double end_margin_mm = 4.0;   ///< keep labels this far from the ends of open lines
    double search_step_mm = 1.0;  ///< candidate positions are tried this far apart
    bool avoid_lines = true;      ///< prefer positions that no other line crosses
    /// When no position near a wanted one is free of lines, accept one crossed only by lines
    /// without a text (intermediate contours), to be interrupted under the label by the caller
    /// (the practice of steep slopes). false: such positions fail as `crossed`.
    bool allow_crossing_unlabelled = true;
    std::optional<Box2> frame;  ///< labels lie wholly inside (CRS units)
    /// Keep the axis-aligned bounds of rotated labels apart too (not just the rotated boxes):
    /// tools that report text boxes axis-aligned (pdftotext -bbox) then see no overlap either.
    bool axis_aligned_clearance = false;
};

/// A placed label. Positions and sizes in CRS units; page units are these / units_per_mm.
struct ContourLabel {
    std::size_t line = 0;  ///< index into the input lines
    double level = 0.0;
    std::string text;
    /// The text's rectangle: centre, baseline direction (box.axis) and half sizes. The up
    /// vector box.up() points uphill.
    LabelBox box;
    double cut_begin = 0.0;  ///< arc length along the line (CRS units) where its gap starts
    double cut_end = 0.0;    ///< ... and ends (cut_end < cut_begin: the gap wraps a ring's start)
    bool crosses_lines = false;  ///< lines without a text pass under it (see options)

    /// Baseline direction as an angle, degrees counter-clockwise from +x (east). On a north-up
    /// page this is also the counter-clockwise angle of the text as read.
    [[nodiscard]] double angle_deg() const noexcept;
};

/// Why a wanted label position found no place.
enum class LabelFailureReason {
    curved,   ///< no stretch straight enough near the position
    crowded,  ///< every straight stretch overlaps another label or an obstacle
    crossed,  ///< every free stretch is crossed by another line
    outside,  ///< the only straight stretches leave the frame
};

struct LabelFailure {
    std::size_t line = 0;
    double level = 0.0;
    Point2 where;  ///< the wanted position on the line (CRS units)
    LabelFailureReason reason = LabelFailureReason::curved;
};

struct ContourLabelResult {
    std::vector<ContourLabel> labels;
    std::vector<LabelFailure> failures;  ///< wanted positions left without a label
    std::size_t lines_labelled = 0;      ///< lines with a text offered for labelling
    std::size_t lines_too_short = 0;     ///< ... shorter than one label with its margins
};

[[nodiscard]] const char* to_string(LabelFailureReason reason) noexcept;

/// Places labels on every line with a text. Lines are handled longest first; on each line the
/// wanted positions are spread evenly, spacing_mm apart (at least one per line long enough), and
/// each is moved to the nearest acceptable stretch within half the distance to its
/// neighbours. Accepted boxes (grown by padding) overlap neither each other nor @p obstacles.
/// @throws UsageError for non-positive units_per_mm, spacing or search step, or a text index
/// out of range; Cancelled
[[nodiscard]] ContourLabelResult place_contour_labels(std::span<const LabelLine> lines,
                                                      std::span<const LabelText> texts,
                                                      std::span<const LabelBox> obstacles,
                                                      const ContourLabelOptions& options,
                                                      const Progress& progress = {});

}  // namespace dtm
