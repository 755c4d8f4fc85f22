// SPDX-License-Identifier: MIT
/// @file
/// @brief The difference surface top - base as a TIN: the overlay pieces triangulated, every
/// vertex shared by the pieces that meet there, with the top surface's height kept alongside
/// (for 3-D zero lines). It is exact: over each piece the difference is linear, so the TIN's
/// linear interpolation reproduces it everywhere.
#pragma once

#include <vector>

#include "dtm/algo/overlay.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct DifferenceSurface {
    Tin tin;                    ///< x, y, z = top - base; neighbour links set
    std::vector<double> top_z;  ///< height of the top surface at every vertex
};

/// Triangulates every piece of @p overlay (a fan from a corner that gives no flat triangle, or
/// from its centre when no corner does). Vertices are numbered in the order the pieces meet them
/// (deterministic), so the result does not depend on the thread count.
/// Memory: about 100 bytes per piece plus the TIN itself. @throws Cancelled
[[nodiscard]] DifferenceSurface difference_surface(const TinOverlay& overlay,
                                                   const Progress& progress = {});

}  // namespace dtm
