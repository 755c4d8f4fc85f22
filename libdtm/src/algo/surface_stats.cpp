// SPDX-License-Identifier: MIT
// Surface measures of a TIN.
//
// For a triangle with vertices p0, p1, p2 and edge vectors u = p1 - p0, v = p2 - p0:
//   planimetric area = |u.x v.y - u.y v.x| / 2          (the z component of u x v)
//   3-D area         = |u x v| / 2
// so the 3-D area is never smaller than the planimetric one, and their ratio on a plane tilted by
// angle a is 1 / cos(a). Coordinates are taken relative to the first vertex before subtracting, so
// that the differences of large projected coordinates (about -750 000 / -1 050 000 in S-JTSK) are
// exact in double precision for survey-sized triangles. The sums are exact (a long accumulator,
// algo/detail/long_sum.hpp) and rounded once, so they depend neither on the order of the
// triangles nor on how they are split over the ranks of a distributed run.
#include "dtm/algo/surface_stats.hpp"

#include <cmath>
#include <vector>

#include "algo/detail/area_terms.hpp"
#include "algo/detail/long_sum.hpp"

namespace dtm {
namespace {

using detail::AreaTerms;
using detail::LongSum;

}  // namespace

SurfaceStats surface_stats(const Tin& tin) {
    SurfaceStats stats;
    stats.vertex_count = tin.vertices.size();
    stats.triangle_count = tin.triangles.size();
    stats.constraint_count = tin.constraints.size();
    if (tin.triangles.empty()) {
        return stats;
    }

    const Point3 origin = tin.vertices[tin.triangles.front().v[0]];
    std::vector<bool> used(tin.vertices.size(), false);
    LongSum planimetric;
    LongSum surface;
    for (const Triangle& t : tin.triangles) {
        const AreaTerms terms = detail::area_terms(origin, tin.vertices[t.v[0]],
                                                   tin.vertices[t.v[1]], tin.vertices[t.v[2]]);
        planimetric.add(terms.planimetric);
        surface.add(terms.surface);
        for (const VertexIndex v : t.v) {
            used[v] = true;
        }
    }
    stats.planimetric_area = planimetric.value();
    stats.surface_area = surface.value();

    bool first = true;
    for (std::size_t i = 0; i < tin.vertices.size(); ++i) {
        if (!used[i]) {
            continue;
        }
        const Point3& p = tin.vertices[i];
        stats.extent.add(p);
        stats.z_min = first ? p.z : std::min(stats.z_min, p.z);
        stats.z_max = first ? p.z : std::max(stats.z_max, p.z);
        first = false;
    }
    return stats;
}

InputAccounting account_inputs(const TriangulateResult& result, std::size_t survey_point_count) {
    const Tin& tin = result.tin;
    std::vector<bool> in_triangle(tin.vertices.size(), false);
    for (const Triangle& t : tin.triangles) {
        for (const VertexIndex v : t.v) {
            in_triangle[v] = true;
        }
    }
    std::vector<bool> merged(result.input_to_vertex.size(), false);
    for (const DuplicateMerge& m : result.merges) {
        if (m.merged_input < merged.size()) {
            merged[m.merged_input] = true;
        }
    }
    InputAccounting accounting;
    for (std::size_t i = 0; i < result.input_to_vertex.size(); ++i) {
        PointFate& fate =
            i < survey_point_count ? accounting.survey_points : accounting.line_vertices;
        ++fate.total;
        const VertexIndex v = result.input_to_vertex[i];
        if (merged[i]) {
            ++fate.merged;
        } else if (v != no_vertex && v < in_triangle.size() && in_triangle[v]) {
            ++fate.used;
        } else {
            ++fate.removed;
        }
    }
    return accounting;
}

}  // namespace dtm
