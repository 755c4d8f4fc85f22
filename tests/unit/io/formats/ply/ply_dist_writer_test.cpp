// SPDX-License-Identifier: MIT
// R-P1 for survey points: the distributed run (exact duplicates merged across ranks, the tree
// over ranks, the kernel over ranks) writes one PLY that is byte for byte the PLY of the serial
// triangulate() + write_tin_ply(), for 1 to 64 in-process ranks; a failed write leaves no file.
#include "io/formats/ply/ply_dist_writer.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "dtm/algo/triangulate.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/io/formats/ply.hpp"
#include "support/dist_cases.hpp"
#include "support/test_support.hpp"

namespace dtm::io {
namespace {

std::string file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The distributed pipeline for points: merge, partition, kernel, write.
void distributed_ply(const TerrainInput& input,
                     int ranks,
                     const std::filesystem::path& out,
                     const TinWriteOptions& options) {
    const auto all = test::combined_input(input);
    dist::run_in_process(ranks, [&](dist::Comm& comm) {
        const auto r = static_cast<std::size_t>(comm.rank());
        const auto p = static_cast<std::size_t>(ranks);
        const std::span<const dist::InputPoint> mine(all.data() + r * all.size() / p,
                                                     (r + 1) * all.size() / p - r * all.size() / p);
        const dist::MergedShare merged =
            dist::merge_exact_duplicates(comm, mine, DuplicateRule::mean);
        std::vector<dist::Point> points;
        for (const dist::Vertex& v : merged.vertices) points.push_back({v.p.x, v.p.y, v.id});
        const dist::Share share = dist::partition_points(comm, std::move(points), {}, {});
        const dist::DistributedMesh kernel = dist::triangulate_share(comm, share, {}, {});
        write_distributed_ply(comm, merged, kernel, out, options);
    });
}

TEST(DistributedPly, EqualsTheSerialFileByteForByte) {
    const test::ScratchDir dir;
    TinWriteOptions options;
    options.crs_wkt = "PROJCRS[\"S-JTSK / Krovak East North\",\n  ID[\"EPSG\",5514]]";
    std::vector<TerrainInput> inputs;
    for (const auto& c : test::dist_cases(5000)) {
        if (c.points.size() < 3 || c.name == "collinear") continue;
        TerrainInput input;
        for (const auto& p : c.points) input.points.push_back({p.x, p.y, p.x * 0.01 + p.y * 0.02});
        inputs.push_back(std::move(input));
    }
    inputs.push_back(test::duplicate_rich_input(3000, 3));  // duplicates, 0.0 and -0.0
    inputs.back().soft_breaklines.clear();
    for (std::size_t k = 0; k < inputs.size(); ++k) {
        TriangulateOptions topts;
        topts.duplicates = DuplicateRule::mean;
        const TriangulateResult serial = triangulate(inputs[k], topts);
        const auto serial_path = dir.path() / ("serial" + std::to_string(k) + ".ply");
        write_tin_ply(serial.tin, serial_path, options);
        const std::string want = file_bytes(serial_path);
        for (int ranks : {1, 2, 3, 4, 7, 16, 64}) {
            const auto path =
                dir.path() / ("dist" + std::to_string(k) + "_" + std::to_string(ranks) + ".ply");
            distributed_ply(inputs[k], ranks, path, options);
            EXPECT_TRUE(file_bytes(path) == want) << "input " << k << " on " << ranks << " ranks";
        }
    }
    // Nothing but the outputs is left behind (no temporaries).
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        EXPECT_EQ(entry.path().extension(), ".ply") << entry.path();
    }
}

TEST(DistributedPly, AnUnwritableFolderFailsOnEveryRankAndLeavesNothing) {
    TerrainInput input;
    // The cases live as long as the loop (a range over a temporary's member would not).
    const auto cases = test::dist_cases(500);
    for (const auto& p : cases.front().points) input.points.push_back({p.x, p.y, 1.0});
    const test::ScratchDir dir;
    EXPECT_THROW(distributed_ply(input, 3, dir.path() / "missing" / "tin.ply", {}), Error);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace dtm::io
