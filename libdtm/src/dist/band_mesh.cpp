// SPDX-License-Identifier: MIT
//
// The band's seed test (band_mesh.hpp): the circumcircle from the classic closed form, relative
// to the first corner, compared with the cut with a margin of 1e-6 of the radius plus 1e-9 of
// the coordinates' size. Nearly flat triangles (huge or undefined circles) are always seeds.
#include "dist/band_mesh.hpp"

#include <cmath>

namespace dtm::dist {

bool circumdisk_reaches(XY a, XY b, XY c, int axis, double cut, bool left) noexcept {
    const double bx = b.x - a.x;
    const double by = b.y - a.y;
    const double cx = c.x - a.x;
    const double cy = c.y - a.y;
    const double d = 2.0 * (bx * cy - by * cx);
    const double b2 = bx * bx + by * by;
    const double c2 = cx * cx + cy * cy;
    if (!(std::abs(d) > 1e-12 * (b2 + c2))) return true;
    const double ux = (cy * b2 - by * c2) / d;
    const double uy = (bx * c2 - cx * b2) / d;
    const double r = std::sqrt(ux * ux + uy * uy);
    const double centre = axis == 0 ? a.x + ux : a.y + uy;
    const double margin = 1e-6 * r + 1e-9 * (std::abs(centre) + std::abs(cut) + 1.0);
    if (!std::isfinite(centre) || !std::isfinite(r)) return true;
    return left ? centre + r + margin >= cut : centre - r - margin <= cut;
}

std::vector<std::uint64_t> band_seeds(const LocalMesh& mesh,
                                      std::uint64_t first,
                                      std::uint64_t last,
                                      int axis,
                                      double cut,
                                      bool left) {
    std::vector<std::uint64_t> seeds;
    const std::uint64_t lo = std::max(first, mesh.first_slot);
    const std::uint64_t hi = std::min<std::uint64_t>(last, mesh.first_slot + mesh.tris.size());
    for (std::uint64_t s = lo; s < hi; ++s) {
        const GlobalTriangle t = mesh.at(s);
        if (t.unused()) continue;
        if (t.is_ghost() || circumdisk_reaches(mesh.point(t.v[0]), mesh.point(t.v[1]),
                                               mesh.point(t.v[2]), axis, cut, left)) {
            seeds.push_back(s);
        }
    }
    return seeds;
}

}  // namespace dtm::dist
