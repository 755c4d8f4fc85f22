// SPDX-License-Identifier: MIT
/// @file
/// @brief The surveyor's contour map: a printable sheet at scale drawn from a TIN to the Czech
/// drawing rules (ČSN 01 3411: brown contours, every 5th an index contour with its number along
/// the line reading uphill, spot heights as a dot and the height), with breaklines, boundary and
/// holes, an optional hillshade, grid crosses with coordinate labels (S-JTSK in the Czech
/// manner), scale bar, north arrow, legend and title block. PDF (vector, text searchable,
/// georeferenced for GDAL/QGIS), SVG or PNG by extension, written atomically.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dtm/algo/contour_labels.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/draw/sheet.hpp"
#include "dtm/io/map/map_layout.hpp"

namespace dtm::io::map {

/// How many spot heights the map shows.
enum class SpotMode { automatic, count, all, none };

struct MapOptions {
    double scale = 500.0;  ///< 1 : scale
    std::optional<draw::Paper> paper;
    draw::Orientation orientation = draw::Orientation::automatic;
    std::optional<Box2> extent;  ///< CRS units; none: the surface with a margin
    bool sheets = false;         ///< split into sheets of the paper when it does not fit one
    std::string title;           ///< empty: "Contour map"
    double interval = 0.0;       ///< contour interval; 0: the z range / 20, rounded down
    double base = 0.0;
    std::size_t index_every = 5;  ///< every k-th level is an index contour (ČSN: 5)
    bool hillshade = false;
    SpotMode spots = SpotMode::automatic;
    std::size_t spot_count = 0;        ///< with SpotMode::count
    double spot_spacing_mm = 30.0;     ///< least distance between spot heights on the page
    int spot_decimals = -1;            ///< -1: by scale (2 up to 1:1000, 1 up to 1:5000, else 0)
    double label_spacing_mm = 120.0;   ///< distance between contour labels along a line
    std::string crs_wkt;               ///< CRS of the TIN (empty: unknown; no georeferencing)
    std::string vertical_datum;        ///< e.g. "Bpv" (shown in the title block when given)
    std::vector<std::string> sources;  ///< input file names for the title block
    std::string date;                  ///< empty: today (UTC, YYYY-MM-DD)
    double png_dpi = 200.0;
};

/// One placed contour label as drawn: text, level, page, and its box on the page.
struct LabelRecord {
    std::string page;  ///< sheet name
    std::string text;
    double level = 0.0;
    Point2 centre;              ///< CRS units
    double angle_deg = 0.0;     ///< counter-clockwise as read on the page
    std::array<Point2, 4> box;  ///< the text box on the page, mm from the top-left corner
    bool crosses_lines = false;
};

struct FailureRecord {
    std::string page;
    double level = 0.0;
    Point2 where;
    LabelFailureReason reason = LabelFailureReason::curved;
};

/// Where one page's furniture went (page mm) and what its title block says; with the grid
/// spacing, so that other tools (the QGIS print layout) can rebuild the same sheet.
struct PageFurniture {
    std::string page;
    draw::Rect title;
    draw::Rect legend;
    draw::Rect scale_bar;
    draw::Rect north;
    draw::TitleBlock block;
    double grid_step = 0.0;  ///< grid crosses every this many CRS units
};

struct MapReport {
    std::filesystem::path output;
    MapLayout layout;
    bool index_page = false;  ///< a sheet index precedes the sheets
    double interval = 0.0;
    std::size_t index_every = 0;
    std::size_t contour_lines = 0;
    std::size_t index_lines = 0;
    std::vector<PageFurniture> furniture;  ///< per map sheet
    bool sjtsk = false;                    ///< the CRS is S-JTSK (grid labels as Y, X)
    std::vector<LabelRecord> labels;
    std::vector<FailureRecord> label_failures;
    std::size_t lines_too_short = 0;  ///< index contour pieces too short for a label
    std::size_t spots_selected = 0;
    std::size_t spots_drawn = 0;
    std::size_t spot_labels_failed = 0;  ///< selected spot heights left out for lack of room
    std::size_t summits = 0;
    std::size_t pits = 0;
    std::size_t saddles = 0;
    bool georeferenced = false;
    double seconds = 0.0;
};

/// Draws the map of @p tin with its constrained edges (breaklines by kind, boundary, holes).
/// @throws UsageError for an unknown extension, a scale or extent that fits no paper, SVG/PNG
/// with several sheets; InputError for a TIN without triangles; Error when writing fails;
/// Cancelled
[[nodiscard]] MapReport write_map(const Tin& tin,
                                  const MapOptions& options,
                                  const std::filesystem::path& output,
                                  const Progress& progress = {});

/// The report as JSON (UTF-8): layout, counts, every placed label with its page box, every
/// failure with its reason.
[[nodiscard]] std::string map_report_json(const MapReport& report);

}  // namespace dtm::io::map
