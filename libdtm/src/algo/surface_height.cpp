// SPDX-License-Identifier: MIT
// Linear heights on a TIN: the triangles near the point come from the bucket grid
// (detail/triangle_grid); the first one (in triangle order) whose closed interior holds the point
// by three exact orient2d tests gives the height (detail::height_at: vertex, edge or plane).
#include "dtm/algo/surface_height.hpp"

#include "algo/detail/triangle_grid.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {

struct LinearSurface::Impl {
    detail::TriangleGrid grid;
};

LinearSurface::LinearSurface(const Tin& tin) : impl_(std::make_unique<Impl>()) {
    impl_->grid = detail::TriangleGrid(tin, 0.5);
}

LinearSurface::~LinearSurface() = default;

bool LinearSurface::height(double x, double y, double& z) const {
    Box2 box;
    box.add(x, y);
    bool found = false;
    TriangleIndex best = no_triangle;
    std::array<int, 3> best_signs{};
    impl_->grid.for_each_candidate(box, [&](TriangleIndex t) {
        if (found && t > best) {
            return;
        }
        const Box2& b = impl_->grid.box(t);
        if (x < b.xmin || x > b.xmax || y < b.ymin || y > b.ymax) {
            return;
        }
        const detail::PackedTriangle& p = impl_->grid.triangle(t);
        std::array<int, 3> s{};
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t k1 = (k + 1) % 3;
            s[k] = geom::orient2d(p.x[k], p.y[k], p.x[k1], p.y[k1], x, y);
            if (s[k] < 0) {
                return;
            }
        }
        found = true;
        best = t;
        best_signs = s;
    });
    if (found) {
        z = detail::height_at(impl_->grid.triangle(best), best_signs, x, y);
    }
    return found;
}

}  // namespace dtm
