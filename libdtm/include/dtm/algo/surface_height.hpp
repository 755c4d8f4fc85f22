// SPDX-License-Identifier: MIT
/// @file
/// @brief The height of a surface at a place: one interface for every way of interpolating a TIN
/// (linear on the triangles, or the cubic and natural-neighbour surfaces of algo/interpolation).
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "dtm/algo/interpolation.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// Height of a surface at (x, y); thread-safe const calls.
class SurfaceHeight {
public:
    virtual ~SurfaceHeight() = default;
    /// Sets @p z and returns true where the surface exists; false outside it (and in holes).
    [[nodiscard]] virtual bool height(double x, double y, double& z) const = 0;
};

/// Linear interpolation on the TIN's triangles, by SurfaceSampler (exact point location; a point
/// on an edge or a vertex gets the same height whichever triangle holds it). The TIN needs its
/// neighbour links.
class LinearSurface final : public SurfaceHeight {
public:
    /// @p tin must outlive the object.
    explicit LinearSurface(const Tin& tin);
    LinearSurface(const LinearSurface&) = delete;
    LinearSurface& operator=(const LinearSurface&) = delete;
    ~LinearSurface() override;
    [[nodiscard]] bool height(double x, double y, double& z) const override;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// A prepared TinInterpolant (cubic or natural neighbour) behind the same interface: the
/// triangle from SurfaceSampler's exact location, the height from a TinEvaluator (on a vertex:
/// its z). The TIN needs its neighbour links.
class InterpolatedSurface final : public SurfaceHeight {
public:
    /// @p tin and @p interpolant (prepared for @p tin) must outlive the object.
    InterpolatedSurface(const Tin& tin, const TinInterpolant& interpolant);
    InterpolatedSurface(const InterpolatedSurface&) = delete;
    InterpolatedSurface& operator=(const InterpolatedSurface&) = delete;
    ~InterpolatedSurface() override;
    [[nodiscard]] bool height(double x, double y, double& z) const override;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace dtm
