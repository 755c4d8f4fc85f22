// SPDX-License-Identifier: MIT
// R-B2: breaklines inserted into the distributed mesh give the serial insertion's slots and
// constraint bits exactly, on 1 to 64 in-process ranks: lines along seams, crossing every
// rank, longer than a rank's region, crossing each other (split first, as the serial path
// does), on uniform points, a cocircular grid, clusters and S-JTSK magnitudes; random delays
// before every send change nothing.
#include "dist/constraints.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "dtm/dist/in_process.hpp"
#include "support/dist_lines.hpp"

namespace dtm::dist {
namespace {

using test::LineCase;

struct Result : test::ConstrainedMesh {
    std::uint64_t components = 0;
};

Result distributed(const LineCase& c, int ranks, unsigned jitter = 0) {
    std::vector<DistributedMesh> meshes(static_cast<std::size_t>(ranks));
    std::vector<ConstraintStats> stats(static_cast<std::size_t>(ranks));
    run_in_process(
        ranks,
        [&](Comm& comm) {
            const Share share = partition_points(
                comm, test::initial_share(c.points, comm.rank(), ranks, true), {}, {});
            DistributedMesh& m = meshes[static_cast<std::size_t>(comm.rank())];
            m = triangulate_share(comm, share, KernelOptions{}, {});
            stats[static_cast<std::size_t>(comm.rank())] =
                insert_constraints(comm, m, c.segments, {});
        },
        InProcessOptions{jitter, 5});
    Result r;
    for (const DistributedMesh& m : meshes) {
        const auto tris = m.mesh.global_triangles();
        r.tris.insert(r.tris.end(), tris.begin(), tris.end());
        r.bits.insert(r.bits.end(), m.mesh.bits.begin(), m.mesh.bits.end());
    }
    r.components = stats.front().components;
    return r;
}

std::size_t constrained_edges(const test::ConstrainedMesh& r) {
    std::size_t n = 0;
    for (const auto& b : r.bits) n += (b[0] != 0) + (b[1] != 0) + (b[2] != 0);
    return n;
}

TEST(DistributedConstraints, EqualTheSerialInsertionSlotForSlot) {
    for (const auto& c : test::dist_cases(5000)) {
        if (c.points.size() < 1000 || c.name == "collinear") continue;
        const LineCase lines = test::with_lines(c);
        ASSERT_GT(lines.segments.size(), 100U) << c.name;
        const test::ConstrainedMesh expected = test::serial_constrained(lines);
        ASSERT_GT(constrained_edges(expected), lines.segments.size()) << c.name;
        for (int ranks : {1, 2, 3, 4, 7, 16, 64}) {
            const Result got = distributed(lines, ranks);
            const std::string what = c.name + " on " + std::to_string(ranks) + " ranks";
            ASSERT_EQ(got.tris.size(), expected.tris.size()) << what;
            EXPECT_TRUE(got.tris == expected.tris) << what;
            EXPECT_TRUE(got.bits == expected.bits) << what;
            EXPECT_GT(got.components, 1U) << what;
        }
    }
}

TEST(DistributedConstraints, RandomDelaysChangeNoSlot) {
    const LineCase lines = test::with_lines(test::dist_cases(3000).front());
    const test::ConstrainedMesh expected = test::serial_constrained(lines);
    for (int ranks : {3, 16}) {
        const Result got = distributed(lines, ranks, 300);
        EXPECT_TRUE(got.tris == expected.tris && got.bits == expected.bits) << ranks;
    }
}

TEST(DistributedConstraints, CrossingSegmentsAreRefusedOnEveryRank) {
    LineCase c{"cross", {{0, 0, 0}, {10, 0, 1}, {10, 10, 2}, {0, 10, 3}, {3, 4, 4}, {6, 5, 5}}, {}};
    c.segments = {{0, 2, detail::constraint_breakline}, {1, 3, detail::constraint_breakline}};
    for (int ranks : {1, 2}) {
        std::vector<std::string> errors(static_cast<std::size_t>(ranks));
        run_in_process(ranks, [&](Comm& comm) {
            const Share share = partition_points(
                comm, test::initial_share(c.points, comm.rank(), ranks, false), {}, {});
            DistributedMesh m = triangulate_share(comm, share, KernelOptions{}, {});
            try {
                insert_constraints(comm, m, c.segments, {});
            } catch (const Error& e) {
                errors[static_cast<std::size_t>(comm.rank())] = e.what();
            }
        });
        for (const std::string& e : errors) EXPECT_NE(e.find("cross"), std::string::npos) << e;
    }
}

}  // namespace
}  // namespace dtm::dist
