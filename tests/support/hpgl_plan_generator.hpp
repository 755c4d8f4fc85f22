// SPDX-License-Identifier: MIT
/// @file
/// @brief A synthetic 1:500 height plan with known truth, written as plain HP-GL and as
/// PCL/PJL-wrapped, PE-encoded HP-GL/2 (no separators), for the HPGL reader tests.
///
/// Layout (plotter units, 40 per mm): a grid of spot heights every 20 mm, each marked in turn by
/// an SM symbol, a small CI circle, a small cross or a cross drawn as four arms (pen 1) with its
/// height written 1.5 mm right and 1 mm up ("312.45", some "312,45"); pen 2 breaklines along row 1
/// and column 1 through spot heights with vertices between them, plus one pen 2 line far from any
/// spot height (it must come back soft); pen 3 the boundary through the outer spot heights; pen 4 a
/// building hole on four spot heights with one extra vertex; pen 1 a frame, integer parcel numbers
/// and a title.
#pragma once

#include <string>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm::test {

struct HpglPlanOptions {
    double scale = 500.0;
    double origin_e = -745'000.0;  ///< ground of plotter 0,0 (S-JTSK-like)
    double origin_n = -1'045'000.0;
    double rotation_deg = 0.0;  ///< counter-clockwise, plan x axis from east
    int columns = 6;
    int rows = 5;
};

struct HpglPlan {
    HpglPlanOptions options;
    std::vector<Point3> spot_heights;             ///< ground truth (E, N, height)
    std::vector<std::vector<Point3>> breaklines;  ///< hard breaklines, ground truth
    std::vector<Point2> soft_breakline;           ///< the heightless pen 2 line, ground
    std::vector<Point3> boundary;                 ///< ring, first vertex not repeated
    std::vector<Point3> hole;                     ///< ring, first vertex not repeated
    std::size_t parcel_labels = 0;                ///< integer labels (not heights)
    std::size_t labels = 0;                       ///< every LB
    std::string plain_hpgl;                       ///< HP-GL/1: PU/PD/PA, ';' separators
    std::string pcl_hpgl2;        ///< PJL + PCL wrapper, HP-GL/2 with PE, no separators
    std::string control_csv;      ///< "px,py,E,N" for the 4 frame corners (plotter units)
    std::string control_csv_two;  ///< two of them (similarity)

    /// Ground position of a plotter position under the plan's options.
    [[nodiscard]] Point2 to_ground(Point2 plotter) const;
};

[[nodiscard]] HpglPlan make_hpgl_plan(const HpglPlanOptions& options = {});

/// PE number encoding (sign in the lowest bit, least significant digit first).
[[nodiscard]] std::string encode_pe_number(long long value, bool seven_bit = false);

}  // namespace dtm::test
