// SPDX-License-Identifier: MIT
/// @file
/// @brief Point sets for the methods lab and tests: the lab's distributions (uniform, gauss,
/// cluster, arc) and the degenerate families (grid, circle, collinear, duplicates).
///
/// Every set is a function of (distribution, n, seed, options) only, bit for bit on every
/// platform: the generators use their own random numbers (splitmix64, Box-Muller), never the
/// implementation-defined std:: distributions. z is a smooth terrain function of x, y.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "dtm/core/point.hpp"

namespace dtm::methods {

enum class Distribution {
    uniform,     ///< uniform in the square
    gauss,       ///< normal around the centre (sigma = size / 6), clipped to the square
    cluster,     ///< a few dense normal clusters (sigma = size / 50) over a sparse background
    arc,         ///< a thin annulus sector: nearly cocircular, very non-uniform (hard for grids)
    grid,        ///< regular square lattice: every unit square cocircular
    circle,      ///< integer points exactly on one circle (all n points cocircular)
    collinear,   ///< many points on a few lines (collinear runs), exact coordinates
    duplicates,  ///< uniform points of which about a third repeat an earlier xy exactly
};

struct PointSetOptions {
    double x0 = 0.0;  ///< lower-left corner of the square (S-JTSK: -750000, -1050000)
    double y0 = 0.0;
    double size = 1000.0;  ///< side of the square
    /// Round x and y to multiples of this (0: no rounding); 0.001 gives survey millimetres.
    /// Not applied to circle, whose exactness it would destroy.
    double quantum = 0.0;
};

/// @p n points of @p distribution, deterministic in @p seed. circle gives exactly n points on
/// one circle (centred in the square) as long as n <= max_circle_points(); more throws
/// std::invalid_argument.
[[nodiscard]] std::vector<Point3> generate_points(Distribution distribution,
                                                  std::size_t n,
                                                  std::uint64_t seed,
                                                  const PointSetOptions& options = {});

/// The most points circle can give (integer points on one circle of radius below 2^31).
[[nodiscard]] std::size_t max_circle_points();

[[nodiscard]] std::string_view distribution_name(Distribution distribution);
[[nodiscard]] std::optional<Distribution> parse_distribution(std::string_view name);
/// Every distribution, in declaration order.
[[nodiscard]] std::span<const Distribution> all_distributions();
/// The four of the lab (`dtm methods compare --dist`): uniform, gauss, cluster, arc.
[[nodiscard]] std::span<const Distribution> lab_distributions();

}  // namespace dtm::methods
