// SPDX-License-Identifier: MIT
// One evaluator for the three TIN surfaces, and point location by a visibility walk.
//
// The walk (Devillers, Pion and Teillaud, "Walking in a triangulation", IJFCS 13(2), 2002):
// from the current triangle, step across an edge that has the point strictly on its outer side
// (orient2d < 0), trying the edges from a rotating start so that the walk cannot cycle; stop in
// the triangle that has the point on no outer side.
#include "dtm/algo/interpolation.hpp"

#include <cmath>
#include <limits>

#include "dtm/algo/cocircular_diagonals.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {

std::string_view interpolation_name(Interpolation method) {
    switch (method) {
        case Interpolation::cubic:
            return "cubic";
        case Interpolation::natural:
            return "natural";
        case Interpolation::linear:
            break;
    }
    return "linear";
}

std::optional<Interpolation> parse_interpolation(std::string_view name) {
    for (const Interpolation m :
         {Interpolation::linear, Interpolation::cubic, Interpolation::natural}) {
        if (name == interpolation_name(m)) {
            return m;
        }
    }
    return std::nullopt;
}

TinInterpolant TinInterpolant::prepare(const Tin& tin,
                                       Interpolation method,
                                       const GradientOptions& gradients,
                                       const Progress& progress) {
    TinInterpolant out;
    out.method_ = method;
    if (method == Interpolation::cubic) {
        // Lattice data: the diagonals of cocircular ties by the heights (the surface TIN).
        if (has_improvable_cocircular_edge(tin)) {
            auto copy = std::make_shared<Tin>(tin);
            choose_cocircular_diagonals(*copy);
            out.surface_ = std::move(copy);
        }
        out.gradients_ = estimate_gradients(out.surface(tin), gradients, progress);
    } else if (method == Interpolation::natural) {
        out.barriers_ = natural_neighbour_barriers(tin);
    }
    progress.report(1.0, "interpolation");
    return out;
}

TinEvaluator::TinEvaluator(const Tin& tin, const TinInterpolant& interpolant)
    : tin_(interpolant.surface(tin)),
      interpolant_(interpolant),
      natural_(tin_, interpolant.barriers()) {}

double TinEvaluator::value(TriangleIndex t, double x, double y) {
    const Triangle& tri = tin_.triangles[t];
    const Point3& a = tin_.vertices[tri.v[0]];
    const Point3& b = tin_.vertices[tri.v[1]];
    const Point3& c = tin_.vertices[tri.v[2]];
    for (const Point3* p : {&a, &b, &c}) {
        if (p->x == x && p->y == y) {
            return p->z;
        }
    }
    switch (interpolant_.method()) {
        case Interpolation::cubic:
            return CubicSurface(tin_, interpolant_.gradients()).patch(t).value(x, y);
        case Interpolation::natural:
            return natural_.value(t, x, y, workspace_);
        case Interpolation::linear:
            break;
    }
    const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    const double det = bx * cy - cx * by;
    const double px = x - a.x, py = y - a.y;
    const double l1 = (cy * px - cx * py) / det, l2 = (bx * py - by * px) / det;
    return a.z + l1 * (b.z - a.z) + l2 * (c.z - a.z);
}

void TinEvaluator::values(TriangleIndex t, std::span<const Point2> points, std::span<double> out) {
    if (interpolant_.method() != Interpolation::cubic) {
        for (std::size_t k = 0; k < points.size(); ++k) {
            out[k] = value(t, points[k].x, points[k].y);
        }
        return;
    }
    const Triangle& tri = tin_.triangles[t];
    const CloughTocherPatch patch = CubicSurface(tin_, interpolant_.gradients()).patch(t);
    for (std::size_t k = 0; k < points.size(); ++k) {
        const Point2& p = points[k];
        out[k] = patch.value(p.x, p.y);
        for (const VertexIndex v : tri.v) {
            if (tin_.vertices[v].x == p.x && tin_.vertices[v].y == p.y) {
                out[k] = tin_.vertices[v].z;
            }
        }
    }
}

double TinEvaluator::value_at(double x, double y, TriangleIndex& hint) {
    const TriangleIndex t = locate_triangle(tin_, x, y, hint);
    if (t == no_triangle) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    hint = t;
    return value(t, x, y);
}

TriangleIndex locate_triangle(const Tin& tin, double x, double y, TriangleIndex hint) {
    if (tin.triangles.empty()) {
        return no_triangle;
    }
    const Point2 p{x, y};
    TriangleIndex t = hint < tin.triangles.size() ? hint : 0;
    const std::size_t limit = 4 * tin.triangles.size() + 16;
    std::size_t rotate = 0;
    for (std::size_t step = 0; step < limit; ++step) {
        const Triangle& tri = tin.triangles[t];
        bool moved = false;
        for (std::size_t k = 0; k < 3 && !moved; ++k) {
            const std::size_t e = (k + rotate) % 3;
            const Point3& a = tin.vertices[tri.v[(e + 1) % 3]];
            const Point3& b = tin.vertices[tri.v[(e + 2) % 3]];
            if (geom::orient2d(a, b, p) < 0) {
                if (tri.n[e] == no_triangle) {
                    step = limit;  // left the TIN: fall back to the scan
                    break;
                }
                t = tri.n[e];
                moved = true;
            }
        }
        if (!moved && step < limit) {
            return t;
        }
        ++rotate;
    }
    for (TriangleIndex u = 0; u < tin.triangles.size(); ++u) {
        const Triangle& tri = tin.triangles[u];
        bool inside = true;
        for (std::size_t e = 0; e < 3 && inside; ++e) {
            inside = geom::orient2d(tin.vertices[tri.v[(e + 1) % 3]],
                                    tin.vertices[tri.v[(e + 2) % 3]], p) >= 0;
        }
        if (inside) {
            return u;
        }
    }
    return no_triangle;
}

}  // namespace dtm
