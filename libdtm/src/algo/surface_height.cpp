// SPDX-License-Identifier: MIT
// Linear heights on a TIN through the one point location of the analyses, SurfaceSampler (exact
// walk; on an edge or a vertex the height does not depend on the triangle reached).
#include "dtm/algo/surface_height.hpp"

#include <cmath>

#include "dtm/algo/surface_sampler.hpp"

namespace dtm {

struct LinearSurface::Impl {
    explicit Impl(const Tin& tin) : sampler(tin) {}
    SurfaceSampler sampler;
};

LinearSurface::LinearSurface(const Tin& tin) : impl_(std::make_unique<Impl>(tin)) {}

LinearSurface::~LinearSurface() = default;

bool LinearSurface::height(double x, double y, double& z) const
{
    SurfaceSampler::Cursor cursor;
    const double h = impl_->sampler.height(Point2{x, y}, cursor);
    if (std::isnan(h)) return false;
    z = h;
    return true;
}

}  // namespace dtm
