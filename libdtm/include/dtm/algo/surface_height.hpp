// SPDX-License-Identifier: MIT
/// @file
/// @brief The height of a surface at a place: one interface for every way of interpolating a TIN
/// (linear on the triangles here; smoother interpolants can implement the same interface).
#pragma once

#include <memory>
#include <span>
#include <vector>

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

}  // namespace dtm
