// SPDX-License-Identifier: MIT
/// @file
/// @brief Spot heights for a map: a thinned selection of TIN vertices (summits, pits and saddles
/// found from the TIN's topology, then a spacing rule filling the rest evenly) or all of them,
/// and the placement of their height labels beside the marker without overlaps.
/// Used by the map sheet (`dtm map`), the DXF and GeoPackage spot-height layers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "dtm/algo/contour_labels.hpp"
#include "dtm/algo/label_box.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// What a spot height marks. A summit (pit) is strictly higher (lower) than every other vertex
/// within the spacing radius; a saddle has at least two higher and two lower sectors around it
/// within that radius. Interior vertices only: a local extreme on the TIN border is an artefact of
/// where the survey stopped.
enum class SpotKind : std::uint8_t { summit, pit, saddle, regular };

[[nodiscard]] const char* to_string(SpotKind kind) noexcept;

struct SpotHeight {
    VertexIndex vertex = no_vertex;
    Point3 point;
    SpotKind kind = SpotKind::regular;
};

struct SpotHeightOptions {
    bool all = false;  ///< every vertex of a triangle (inside the extent), classified
    /// Least distance between two selected spot heights (CRS units); also the radius within
    /// which a summit, pit or saddle must hold. 0: four times the mean point spacing.
    double spacing = 0.0;
    /// At most this many (0: no limit): the spacing grows until the selection fits.
    std::size_t max_count = 0;
    std::optional<Box2> extent;  ///< only vertices inside (e.g. the map frame)
};

struct SpotHeightResult {
    /// Summits first (highest first), then pits, saddles, then the evenly spread rest.
    std::vector<SpotHeight> spots;
    std::size_t summits = 0;  ///< selected spots of each kind
    std::size_t pits = 0;
    std::size_t saddles = 0;
    std::size_t regular = 0;
    double spacing = 0.0;  ///< the spacing used (after growing for max_count)
};

/// Selects spot heights on @p tin. Ties in height are broken by vertex index (simulation of
/// simplicity) in the link test, and summits and pits must be strict within the spacing radius,
/// so flat ground yields none. @throws Cancelled
[[nodiscard]] SpotHeightResult select_spot_heights(const Tin& tin,
                                                   const SpotHeightOptions& options = {},
                                                   const Progress& progress = {});

/// A spot height's label request: the marker at @p at and the height text's size (page mm).
struct PointLabelRequest {
    Point2 at;
    double marker_radius_mm = 0.5;
    double width_mm = 0.0;
    double height_mm = 0.0;
};

struct PointLabelOptions {
    double units_per_mm = 1.0;  ///< CRS units per page millimetre (see ContourLabelOptions)
    double offset_mm = 0.6;     ///< gap between the marker and its text
    double padding_mm = 0.4;    ///< free space kept around every text box
    std::optional<Box2> frame;  ///< texts lie wholly inside (CRS units)
};

/// A placed point label: horizontal text box in CRS units.
struct PointLabel {
    std::size_t request = 0;  ///< index into the requests
    LabelBox box;
    /// Where the text sits around the marker: 0 right, 1 upper right, 2 lower right, 3 left,
    /// 4 upper left, 5 lower left, 6 above, 7 below (tried in this order).
    int position = 0;
};

struct PointLabelResult {
    std::vector<PointLabel> labels;
    std::vector<std::size_t> failed;  ///< requests whose text found no free position
    std::vector<LabelBox> markers;    ///< the marker squares (obstacles for other labels)
};

/// Places each request's text beside its marker, in request order, at the first of eight
/// positions whose box (grown by padding) overlaps no marker, no placed text and no obstacle and
/// stays inside the frame; among such positions one that no line of @p lines crosses is preferred,
/// then one crossed only by passable lines (LabelLine::passable).
/// @throws UsageError for a non-positive units_per_mm
[[nodiscard]] PointLabelResult place_point_labels(std::span<const PointLabelRequest> requests,
                                                  std::span<const LabelLine> lines,
                                                  std::span<const LabelBox> obstacles,
                                                  const PointLabelOptions& options);

}  // namespace dtm
