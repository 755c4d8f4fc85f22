// SPDX-License-Identifier: MIT
/// @file
/// @brief The three surfaces of a TIN (linear, Clough-Tocher cubic, natural neighbour) behind
/// one per-triangle evaluator, for rasterisation, contouring and point sampling.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "dtm/algo/clough_tocher.hpp"
#include "dtm/algo/gradients.hpp"
#include "dtm/algo/natural_neighbour.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// How the surface between the TIN's vertices is interpolated.
enum class Interpolation : std::uint8_t {
    linear,   ///< the plane of each triangle (C0)
    cubic,    ///< Clough-Tocher C1 cubic, creased along hard breaklines (clough_tocher.hpp)
    natural,  ///< Sibson's natural neighbours (natural_neighbour.hpp)
};

/// "linear", "cubic", "natural".
[[nodiscard]] std::string_view interpolation_name(Interpolation method);
/// The method named @p name (as interpolation_name spells it), or nothing.
[[nodiscard]] std::optional<Interpolation> parse_interpolation(std::string_view name);

/// What a method needs besides the TIN: the sector gradients (cubic) or the barrier edges
/// (natural). Indexed by triangle, so it serves any vertex renumbering of the same TIN.
class TinInterpolant {
public:
    TinInterpolant() = default;  ///< linear

    /// Prepares @p method for @p tin (for cubic: estimate_gradients with @p gradients).
    /// @throws Cancelled
    [[nodiscard]] static TinInterpolant prepare(const Tin& tin,
                                                Interpolation method,
                                                const GradientOptions& gradients = {},
                                                const Progress& progress = {});

    [[nodiscard]] Interpolation method() const { return method_; }
    [[nodiscard]] const TinGradients& gradients() const { return gradients_; }
    [[nodiscard]] const std::vector<std::uint8_t>& barriers() const { return barriers_; }
    /// The TIN the interpolant's triangles refer to, given the one it was prepared for: @p tin
    /// itself, or for the cubic, where @p tin has cocircular vertices, a copy of @p tin with
    /// data-dependent diagonals in the ties (choose_cocircular_diagonals: the same vertices and
    /// constraints, still Delaunay). Surfaces, contours and samples of the cubic use this TIN.
    [[nodiscard]] const Tin& surface(const Tin& tin) const { return surface_ ? *surface_ : tin; }

private:
    Interpolation method_ = Interpolation::linear;
    std::shared_ptr<const Tin> surface_;  ///< null: the TIN as given
    TinGradients gradients_;
    std::vector<std::uint8_t> barriers_;
};

/// Evaluates a prepared interpolant on interpolant.surface(@p tin), @p tin being the TIN it was
/// prepared for or a copy with renumbered vertices: triangle indices given to value() and
/// values() are those of that surface TIN (tin() returns it). Keeps scratch space: use one per
/// thread.
class TinEvaluator {
public:
    TinEvaluator(const Tin& tin, const TinInterpolant& interpolant);
    TinEvaluator(const Tin& tin, TinInterpolant&& interpolant) = delete;  // it keeps a reference

    /// The height at (x, y), a point in triangle @p t or on its border. On a vertex it is the
    /// vertex height exactly, for every method.
    [[nodiscard]] double value(TriangleIndex t, double x, double y);

    /// Heights at several points of triangle @p t (one patch set-up for all of them).
    void values(TriangleIndex t, std::span<const Point2> points, std::span<double> out);

    /// The height at (x, y) anywhere: the triangle is found by a walk from @p hint (updated to
    /// the triangle found). NaN when (x, y) is outside every triangle.
    [[nodiscard]] double value_at(double x, double y, TriangleIndex& hint);

    [[nodiscard]] const Tin& tin() const { return tin_; }
    [[nodiscard]] Interpolation method() const { return interpolant_.method(); }

private:
    const Tin& tin_;
    const TinInterpolant& interpolant_;
    NaturalNeighbourSurface natural_;
    NaturalNeighbourSurface::Workspace workspace_;
};

/// The triangle of @p tin containing (x, y) (inside or on its border), or no_triangle: a
/// visibility walk from @p hint decided by orient2d, and a scan of every triangle when the walk
/// leaves the TIN (a point beyond a concave border or in a hole).
[[nodiscard]] TriangleIndex locate_triangle(const Tin& tin,
                                            double x,
                                            double y,
                                            TriangleIndex hint = 0);

}  // namespace dtm
