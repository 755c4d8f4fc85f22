// SPDX-License-Identifier: MIT
// Heights on a TIN through the one point location of the analyses, SurfaceSampler (exact walk;
// linear: on an edge or a vertex the height does not depend on the triangle reached), and the
// smooth surfaces of algo/interpolation evaluated in the triangle found.
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

bool LinearSurface::height(double x, double y, double& z) const {
    SurfaceSampler::Cursor cursor;
    const double h = impl_->sampler.height(Point2{x, y}, cursor);
    if (std::isnan(h)) return false;
    z = h;
    return true;
}

struct InterpolatedSurface::Impl {
    Impl(const Tin& t, const TinInterpolant& i)
        : tin(i.surface(t)), interpolant(i), sampler(i.surface(t)) {}
    const Tin& tin;
    const TinInterpolant& interpolant;
    SurfaceSampler sampler;
};

InterpolatedSurface::InterpolatedSurface(const Tin& tin, const TinInterpolant& interpolant)
    : impl_(std::make_unique<Impl>(tin, interpolant)) {}

InterpolatedSurface::~InterpolatedSurface() = default;

bool InterpolatedSurface::height(double x, double y, double& z) const {
    SurfaceSampler::Cursor cursor;
    const TinLocation where = impl_->sampler.locate(Point2{x, y}, cursor);
    if (where.kind == TinLocation::Kind::outside) return false;
    if (where.kind == TinLocation::Kind::vertex) {
        z = impl_->tin.vertex(origin(impl_->tin, where.edge)).z;
        return true;
    }
    TinEvaluator evaluator(impl_->tin, impl_->interpolant);  // its scratch space: one per call
    z = evaluator.value(where.edge.triangle, x, y);
    return true;
}

}  // namespace dtm
