// SPDX-License-Identifier: MIT
// R-S3: the Delaunay kernel over 1 to 64 in-process ranks gives the serial kernel's triangle
// slots and vertex order exactly, on uniform points, a grid cut through rows and columns,
// clusters, S-JTSK magnitudes, collinear runs and tiny sets, from contiguous and strided
// initial spreads; bands that start too narrow are widened without changing a slot; random
// delays before every send change nothing.
#include "dist/kernel.hpp"

#include <gtest/gtest.h>

#include "algo/detail/delaunay_dc.hpp"
#include "dtm/dist/in_process.hpp"
#include "support/dist_cases.hpp"

namespace dtm::dist {
namespace {

using Serial = test::SerialKernel;

struct Distributed {
    Serial gathered;
    std::uint32_t widenings = 0;
    std::uint64_t band_triangles = 0;
};

Distributed run(const std::vector<Point>& points,
                int ranks,
                bool strided,
                unsigned rings,
                unsigned jitter = 0) {
    std::vector<DistributedMesh> meshes(static_cast<std::size_t>(ranks));
    run_in_process(
        ranks,
        [&](Comm& comm) {
            const Share share = partition_points(
                comm, test::initial_share(points, comm.rank(), ranks, strided), {}, {});
            meshes[static_cast<std::size_t>(comm.rank())] =
                triangulate_share(comm, share, KernelOptions{rings}, {});
        },
        InProcessOptions{jitter, 9});
    Distributed d;
    for (const DistributedMesh& m : meshes) {
        if (!m.mesh.tris.empty()) {
            EXPECT_EQ(m.mesh.first_slot, d.gathered.tris.size());
        }
        const auto tris = m.mesh.global_triangles();
        d.gathered.tris.insert(d.gathered.tris.end(), tris.begin(), tris.end());
        d.gathered.ids.insert(d.gathered.ids.end(), m.input_ids.begin(), m.input_ids.end());
        d.widenings = std::max(d.widenings, m.stats.widenings);
        d.band_triangles += m.stats.band_triangles;
    }
    return d;
}

TEST(DistributedKernel, EqualsTheSerialKernelSlotForSlot) {
    for (const auto& c : test::dist_cases(6000)) {
        const Serial serial = test::serial_kernel(c.points);
        for (int ranks : {1, 2, 3, 4, 7, 16, 64}) {
            for (bool strided : {false, true}) {
                const Distributed d = run(c.points, ranks, strided, 1);
                const std::string what = c.name + " on " + std::to_string(ranks) + " ranks";
                ASSERT_EQ(d.gathered.tris.size(), serial.tris.size()) << what;
                EXPECT_TRUE(d.gathered.tris == serial.tris) << what;
                EXPECT_EQ(d.gathered.ids, serial.ids) << what;
                if (c.name == "uniform") {
                    EXPECT_EQ(d.widenings, 0U) << what;
                }
            }
        }
    }
}

TEST(DistributedKernel, BandsWithoutRingsAreWidenedToTheSameSlots) {
    std::uint32_t widened = 0;
    for (const auto& c : test::dist_cases(4000)) {
        const Serial serial = test::serial_kernel(c.points);
        for (int ranks : {2, 7}) {
            const Distributed d = run(c.points, ranks, false, 0);
            EXPECT_TRUE(d.gathered.tris == serial.tris) << c.name << " on " << ranks;
            widened += d.widenings;
        }
    }
    EXPECT_GT(widened, 0U);
}

TEST(DistributedKernel, RandomDelaysChangeNoSlot) {
    const auto c = test::dist_cases(5000).front();
    const Serial serial = test::serial_kernel(c.points);
    for (int ranks : {3, 16}) {
        EXPECT_TRUE(run(c.points, ranks, true, 1, 300).gathered.tris == serial.tris);
    }
}

TEST(DistributedKernel, BandsAreSmallAgainstTheMesh) {
    const auto c = test::dist_cases(40000).front();  // uniform
    const Distributed d = run(c.points, 4, false, 1);
    EXPECT_LT(d.band_triangles, c.points.size() / 4);
}

}  // namespace
}  // namespace dtm::dist
