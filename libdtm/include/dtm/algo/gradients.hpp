// SPDX-License-Identifier: MIT
/// @file
/// @brief Gradients of a TIN surface at its vertices, for the C1 (Clough-Tocher) interpolation:
/// Nielson's minimum-norm network, with each vertex's star split into sectors by the hard
/// breaklines through it so that the surface can crease along them.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// A gradient (dz/dx, dz/dy).
struct Gradient {
    double dx = 0.0;
    double dy = 0.0;
};

struct GradientOptions {
    /// Jacobi iterations at most. They converge geometrically (about a factor 10 per 3
    /// iterations on survey data), so 10^-9 is usually reached in 20-40.
    unsigned max_iterations = 200;
    /// Stop when no gradient changed by more than tolerance x the largest gradient in the last
    /// iteration.
    double tolerance = 1e-9;
    unsigned threads = 0;  ///< worker threads (0: all cores); never changes the result
};

/// The gradients of the surface, one per sector. A sector is a maximal fan of triangles around a
/// vertex that are connected through edges that are not hard breaklines; a vertex off the hard
/// breaklines has one sector, a vertex inside a hard breakline two (one per side), a crossing
/// of breaklines more. Everything is indexed by triangle, so the data stays valid for any
/// renumbering of the TIN's vertices (the triangles and their corner order must not change).
struct TinGradients {
    /// Per triangle, the sector of each corner (an index into gradient). The first sector of
    /// vertex v is v; further sectors are numbered from the vertex count on.
    std::vector<std::array<std::uint32_t, 3>> corner_sector;
    std::vector<Gradient> gradient;  ///< per sector
    /// Per triangle, bit e set when edge e (opposite v[e]) is a hard breakline.
    std::vector<std::uint8_t> hard_edges;
    unsigned iterations = 0;  ///< Jacobi iterations done
    double change = 0.0;      ///< relative change in the last iteration
};

/// Estimates the gradients of @p tin by Nielson's minimum-norm network: the gradients minimise
/// the sum over all edges of the integral of the squared second derivative of the cubic
/// Hermite curve the edge gets from its end heights and the gradients' components along it
/// (G. M. Nielson, "A method for interpolating scattered data based upon a minimum norm
/// network", Math. Comp. 40, 1983; the estimate of Renka's TOMS 624 and of scipy's
/// CloughTocher2DInterpolator). Vertices on hard breaklines get one gradient per side: each
/// side's network holds that side's edges and the breakline edges. A linear surface gives the
/// exact gradient. The sparse 2 x 2-block system is solved by block Jacobi iterations in
/// parallel (deterministic: the result never depends on the thread count), started from a
/// weighted least-squares plane of each sector's edges.
/// @throws Cancelled
[[nodiscard]] TinGradients estimate_gradients(const Tin& tin,
                                              const GradientOptions& options = {},
                                              const Progress& progress = {});

}  // namespace dtm
