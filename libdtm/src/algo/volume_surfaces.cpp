// SPDX-License-Identifier: MIT
// Clipping a TIN to a polygon and spanning a stockpile's base.
//
// Clipping: the polygon (with holes) is triangulated by the constrained Delaunay triangulator
// (its rings as boundary and hole constraints, heights 0); the overlay of the TIN with that flat
// triangulation has exactly the TIN's surface over the polygon, and its pieces, fanned into one
// TIN (difference_surface) with the TIN's heights, are the clipped surface. Every decision is the
// overlay's exact one; the only new coordinates are edge crossings.
// Spanning: the outer rings of the pile's border (counter-clockwise, border_rings) become the
// boundary constraints of a triangulation of their own vertices, which keep the pile's heights.
#include "dtm/algo/volume_surfaces.hpp"

#include "dtm/algo/difference_surface.hpp"
#include "dtm/algo/overlay.hpp"
#include "dtm/algo/tin_topology.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"

namespace dtm {

Tin clip_tin(const Tin& tin, const TerrainInput& area, const Progress& progress) {
    if (area.boundaries.empty()) {
        throw InputError("clip: the area has no closed outer ring");
    }
    TerrainInput flat;
    for (const std::vector<Polyline>* rings : {&area.boundaries, &area.holes}) {
        for (const Polyline& ring : *rings) {
            Polyline p = ring;
            for (Point3& q : p.points) {
                q.z = 0.0;
                flat.points.push_back(q);
            }
            (rings == &area.boundaries ? flat.boundaries : flat.holes).push_back(std::move(p));
        }
    }
    const Tin mask = triangulate(flat, {}, progress.sub(0.0, 0.2)).tin;
    const TinOverlay overlay(tin, mask);
    DifferenceSurface clipped = difference_surface(overlay, progress.sub(0.2, 1.0));
    for (std::size_t i = 0; i < clipped.tin.vertices.size(); ++i) {
        clipped.tin.vertices[i].z = clipped.top_z[i];
    }
    return std::move(clipped.tin);
}

Tin spanned_base(const Tin& pile, const Progress& progress) {
    TerrainInput input;
    for (const std::vector<VertexIndex>& ring : border_rings(pile)) {
        Polyline p;
        for (const VertexIndex v : ring) {
            p.points.push_back(pile.vertices[v]);
        }
        p.points.push_back(p.points.front());
        if (ring_area(p.points) <= 0.0) {
            continue;  // a hole of the pile
        }
        input.points.insert(input.points.end(), p.points.begin(), p.points.end() - 1);
        input.boundaries.push_back(std::move(p));
    }
    if (input.boundaries.empty()) {
        throw InputError("stockpile: the pile surface has no triangle, so no foot to span");
    }
    return triangulate(input, {}, progress).tin;
}

}  // namespace dtm
