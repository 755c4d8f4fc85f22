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
    /// Sweeps at most. They converge geometrically (a factor 3-5 per sweep on survey data), so
    /// the default tolerance is usually reached in under 10.
    unsigned max_iterations = 200;
    /// Stop when no gradient changed by more than tolerance x the largest gradient in the last
    /// iteration. At 10^-6 the interpolated heights no longer change measurably (errors
    /// against the truth agree to four digits with a fully converged solve).
    double tolerance = 1e-6;
    unsigned threads = 0;  ///< worker threads (0: all cores); never changes the result
    /// Split the stars at hard breaklines, so that the surface creases along them. false: the
    /// surface is smooth across them too (right for contour lines given as breaklines: the
    /// terrain does not kink at a contour).
    bool crease_at_breaklines = true;
};

/// The gradients of the surface, one per sector. A sector is a maximal fan of triangles around a
/// vertex that are connected through edges that are not hard breaklines; a vertex off the hard
/// breaklines has one sector, a vertex inside a hard breakline two (one per side), a crossing
/// of breaklines more. Everything is indexed by triangle, so the data stays valid for any
/// renumbering of the TIN's vertices (the triangles and their corner order must not change).
struct TinGradients {
    /// Per triangle, the sector of each corner (an index into gradient). Sectors are numbered in
    /// the order the triangles first use their vertices; the further sectors of vertices on
    /// hard breaklines come after all first sectors.
    std::vector<std::array<std::uint32_t, 3>> corner_sector;
    std::vector<Gradient> gradient;          ///< per sector
    std::vector<VertexIndex> sector_vertex;  ///< per sector, its vertex
    /// Per sector, the largest height difference along its edges: it bounds the corner
    /// derivatives of the cubic (CubicSurface) against data defects, such as two points a
    /// centimetre apart and metres apart in height, whose steep gradient would throw the cubic
    /// of every long edge at that vertex off.
    std::vector<float> relief;
    /// Per triangle, bit e set when edge e (opposite v[e]) is a hard breakline.
    std::vector<std::uint8_t> hard_edges;
    unsigned iterations = 0;  ///< sweeps done
    double change = 0.0;      ///< relative change in the last iteration
};

/// Estimates the gradients of @p tin by Nielson's minimum-norm network: the gradients minimise
/// the sum over all edges of the integral of the squared second derivative of the cubic
/// Hermite curve the edge gets from its end heights and the gradients' components along it
/// (G. M. Nielson, "A method for interpolating scattered data based upon a minimum norm
/// network", Math. Comp. 40, 1983; the estimate of Renka's TOMS 624 and of scipy's
/// CloughTocher2DInterpolator). Vertices on hard breaklines get one gradient per side: each
/// side's network holds that side's edges and the breakline edges. A linear surface gives the
/// exact gradient. The sparse 2 x 2-block system is solved by block Gauss-Seidel sweeps in
/// parallel (deterministic: the result never depends on the thread count), started from a
/// weighted least-squares plane of each sector's edges. Vertices of no triangle get no sector.
/// @throws Cancelled
[[nodiscard]] TinGradients estimate_gradients(const Tin& tin,
                                              const GradientOptions& options = {},
                                              const Progress& progress = {});

}  // namespace dtm
