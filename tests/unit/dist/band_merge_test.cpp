// SPDX-License-Identifier: MIT
// R-S1/R-S2: the top merge of the kernel run on a band of triangles (the seeds of both halves,
// their ghosts, A's spare slots and one ring) writes exactly the slots the serial kernel
// writes; starting from the seeds alone, the guard widens the band and still gives the same
// triangles.
#include "dist/band_merge.hpp"

#include <gtest/gtest.h>

#include "algo/detail/delaunay_dc.hpp"
#include "support/dist_cases.hpp"

namespace dtm::dist {
namespace {

using detail::BigArray;
using detail::KernelPoint;

struct Halves {
    BigArray<KernelPoint> pts;
    detail::GhostMesh mesh;
    detail::KernelSubtree left;
    detail::KernelSubtree right;
    std::size_t mid = 0;
};

/// The two halves of the root built by the kernel's own steps, not yet merged.
Halves build_halves(const std::vector<Point>& points) {
    Halves h;
    const std::size_t n = points.size();
    h.pts = BigArray<KernelPoint>(n);
    for (std::size_t i = 0; i < n; ++i) {
        h.pts[i] = {{points[i].x, points[i].y}, static_cast<std::uint32_t>(i)};
    }
    detail::order_kernel_subtree(h.pts, 0, n, 0);
    h.mesh.tris.assign(2 * n, Triangle{});
    h.mid = n / 2;
    h.left = detail::build_kernel_subtree(h.pts, h.mesh, 0, h.mid, 1, 0);
    h.right = detail::build_kernel_subtree(h.pts, h.mesh, h.mid, n, 1, 0);
    return h;
}

LocalMesh to_local(const detail::GhostMesh& mesh, const BigArray<KernelPoint>& pts) {
    LocalMesh local;
    local.tris = mesh.tris;
    for (std::size_t i = 0; i < pts.size(); ++i) local.own_points.push_back({pts[i].x, pts[i].y});
    return local;
}

GlobalHull global(detail::GhostHull<detail::HalfEdge> h) { return {h.last_out, h.first_in}; }

void add_slot(const LocalMesh& local, std::uint64_t slot, BandMesh& band) {
    const GlobalTriangle t = local.at(slot);
    band.add(slot, t);
    for (const std::uint64_t v : t.v) {
        if (v != global_ghost) band.add_point(v, local.point(v));
    }
}

struct BandRun {
    std::vector<GlobalTriangle> tris;
    int attempts = 0;
    std::size_t band_size = 0;
};

/// Seeds (+ rings), the merge on the band, widened by the slot it lacked until it succeeds.
BandRun merge_by_band(const Halves& h, int rings) {
    const std::size_t n = h.pts.size();
    LocalMesh local = to_local(h.mesh, h.pts);
    // The x cut at the root: the smallest point of B in (x, y) order.
    double cut = h.pts[h.mid].x;
    for (std::size_t i = h.mid; i < n; ++i) cut = std::min(cut, h.pts[i].x);
    BandMesh band;
    for (std::uint64_t s : band_seeds(local, 0, 2 * h.mid, 0, cut, true)) add_slot(local, s, band);
    for (std::uint64_t s : band_seeds(local, 2 * h.mid, 2 * n, 0, cut, false))
        add_slot(local, s, band);
    for (std::uint64_t s : h.left.spare) add_slot(local, s, band);
    for (int r = 0; r < rings; ++r) {
        for (std::uint64_t s : band_ring(band)) add_slot(local, s, band);
    }
    BandRun run;
    for (;;) {
        ++run.attempts;
        try {
            const BandMergeOutcome out =
                merge_on_band(band, global(h.left.hull), global(h.right.hull),
                              {h.left.spare[0], h.left.spare[1]}, 0);
            for (const auto& [slot, t] : out.changed) local.set(slot, t);
            break;
        } catch (const BandTooNarrow& e) {
            add_slot(local, e.slot, band);
        }
    }
    run.band_size = band.triangles().size();
    for (std::uint64_t s = 0; s < local.tris.size(); ++s) run.tris.push_back(local.at(s));
    return run;
}

TEST(BandMerge, OneRingHoldsEverythingTheSerialMergeTouches) {
    for (const auto& c : test::dist_cases(20000)) {
        if (c.points.size() < 4) continue;
        const Halves h = build_halves(c.points);
        const BandRun run = merge_by_band(h, 1);
        EXPECT_EQ(run.attempts, 1) << c.name;
        EXPECT_EQ(run.tris, test::serial_kernel(c.points).tris) << c.name;
        if (c.points.size() >= 10000 && c.name != "collinear") {
            // A band, not the mesh (mostly collinear points make thin triangles with huge
            // circles: nearly all of them reach the cut, as they should).
            EXPECT_LT(run.band_size, c.points.size() / 5) << c.name;
        }
    }
}

TEST(BandMerge, TheGuardWidensATooNarrowBandAndChangesNothing) {
    int widened = 0;
    for (const auto& c : test::dist_cases(5000)) {
        if (c.points.size() < 4) continue;
        const Halves h = build_halves(c.points);
        const BandRun run = merge_by_band(h, 0);
        widened += run.attempts > 1 ? 1 : 0;
        EXPECT_EQ(run.tris, test::serial_kernel(c.points).tris) << c.name;
    }
    EXPECT_GT(widened, 0);
}

TEST(BandMerge, SeedsIncludeEveryCircumdiskThatReachesTheCut) {
    // A triangle whose circle just touches the cut line from the left is a seed; one far from
    // it is not; a flat one always is.
    EXPECT_TRUE(circumdisk_reaches({-1, 0}, {1, 0}, {0, 1}, 0, 1.0, true));
    EXPECT_FALSE(circumdisk_reaches({-1, 0}, {1, 0}, {0, 1}, 0, 1.1, true));
    EXPECT_TRUE(circumdisk_reaches({-1, 0}, {1, 0}, {0, 1}, 0, -1.0, false));
    EXPECT_FALSE(circumdisk_reaches({-1, 0}, {1, 0}, {0, 1}, 0, -1.1, false));
    EXPECT_TRUE(circumdisk_reaches({0, 0}, {1, 0}, {2, 1e-30}, 1, 1e9, true));
    EXPECT_TRUE(circumdisk_reaches({-750000, -1050000}, {-749999, -1050000}, {-749999.5, -1049999},
                                   1, -1049999.375, true));
}

}  // namespace
}  // namespace dtm::dist
