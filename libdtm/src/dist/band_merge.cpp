// SPDX-License-Identifier: MIT
//
// A merge on a band (band_merge.hpp). The merge runs on a copy so that a BandTooNarrow leaves
// the band as it was for the retry; the changed slots are found by comparing with it.
#include "dist/band_merge.hpp"

#include <algorithm>

namespace dtm::dist {

BandMergeOutcome merge_on_band(const BandMesh& band,
                               GlobalHull left,
                               GlobalHull right,
                               std::array<std::uint64_t, 2> spare,
                               int frame) {
    BandMesh work = band;
    const std::uint64_t on_hull = detail::ghost_merge(work, left, right, spare);
    BandMergeOutcome out;
    out.hull = detail::hull_handles(work, on_hull, frame);
    for (const auto& [slot, t] : work.triangles()) {
        if (!(band.triangles().at(slot) == t)) out.changed.emplace_back(slot, t);
    }
    std::sort(out.changed.begin(), out.changed.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    return out;
}

std::vector<std::uint64_t> band_ring(const BandMesh& band) {
    std::vector<std::uint64_t> ring;
    for (const auto& [slot, t] : band.triangles()) {
        for (const std::uint64_t h : t.n) {
            if (h != global_ghost && !band.has(h >> 2)) ring.push_back(h >> 2);
        }
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    return ring;
}

}  // namespace dtm::dist
