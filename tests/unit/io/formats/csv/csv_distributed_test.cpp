// SPDX-License-Identifier: MIT
// R-D2: survey points of a text file read by byte ranges on 1 to 16 in-process ranks are
// read_csv's points in read_csv's order, whatever the cut; the first bad line is reported on
// every rank with read_csv's own message, wherever it falls.
#include "io/formats/csv/csv_distributed.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <fstream>
#include <mutex>

#include "dtm/dist/in_process.hpp"
#include "dtm/io/formats/csv.hpp"
#include "support/test_support.hpp"

namespace dtm::io {
namespace {

std::filesystem::path write_points(const test::ScratchDir& dir,
                                   const std::string& name,
                                   std::size_t n,
                                   std::size_t bad_line) {
    const auto path = dir / name;
    std::ofstream out(path);
    out << "# survey, S-JTSK\nid,x,y,z\n";
    for (std::size_t i = 0; i < n; ++i) {
        if (i % 97 == 5) out << "# a comment line\n\n";
        out << "P" << i << "," << -750000.0 - 0.125 * static_cast<double>(i % 1000) << ","
            << -1050000.0 - 0.375 * static_cast<double>(i / 1000) << ","
            << 250.0 + 0.001 * static_cast<double>(i) << "\n";
        if (i + 1 == bad_line) out << "P-bad,-750000.5,not-a-number,251\n";
    }
    return path;
}

std::vector<Point3> read_distributed(const std::filesystem::path& path, int ranks) {
    std::vector<std::vector<Point3>> parts(static_cast<std::size_t>(ranks));
    const InputFile file{path, InputRole::points};
    dist::run_in_process(ranks, [&](dist::Comm& comm) {
        const DistributedPoints d = read_text_points_distributed(comm, file, {});
        auto& mine = parts[static_cast<std::size_t>(comm.rank())];
        for (const auto& p : d.points) mine.push_back(p.p);
    });
    std::vector<Point3> all;
    for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
    return all;
}

bool same(const std::vector<Point3>& a, const std::vector<Point3>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::bit_cast<std::uint64_t>(a[i].x) != std::bit_cast<std::uint64_t>(b[i].x) ||
            std::bit_cast<std::uint64_t>(a[i].y) != std::bit_cast<std::uint64_t>(b[i].y) ||
            std::bit_cast<std::uint64_t>(a[i].z) != std::bit_cast<std::uint64_t>(b[i].z)) {
            return false;
        }
    }
    return true;
}

TEST(DistributedText, ByteRangesGiveTheSerialPointsInOrder) {
    const test::ScratchDir dir;
    const auto path = write_points(dir, "points.csv", 5000, 0);
    const ReadResult serial = read_csv({path, InputRole::points}, {});
    ASSERT_EQ(serial.terrain.points.size(), 5000U);
    // Ranges parsed in blocks of whole lines: one block, blocks of a few lines, of one line.
    for (const std::size_t block : {std::size_t{32} << 20, std::size_t{1000}, std::size_t{7}}) {
        distributed_block_bytes = block;
        for (int ranks : {1, 2, 3, 4, 7, 16}) {
            EXPECT_TRUE(same(read_distributed(path, ranks), serial.terrain.points))
                << ranks << " ranks, blocks of " << block;
        }
    }
    distributed_block_bytes = std::size_t{32} << 20;
    // More ranks than lines: most ranges are empty.
    const auto tiny = write_points(dir, "tiny.csv", 3, 0);
    EXPECT_TRUE(
        same(read_distributed(tiny, 16), read_csv({tiny, InputRole::points}, {}).terrain.points));
}

TEST(DistributedText, TheFirstBadLineIsReportedOnEveryRankAsTheSerialReaderDoes) {
    const test::ScratchDir dir;
    for (std::size_t bad : {1, 2500, 4999}) {
        const auto path = write_points(dir, "bad" + std::to_string(bad) + ".csv", 5000, bad);
        std::string serial_message;
        try {
            (void)read_csv({path, InputRole::points}, {});
        } catch (const InputError& e) {
            serial_message = e.what();
        }
        ASSERT_FALSE(serial_message.empty());
        for (int ranks : {2, 4, 7}) {
            distributed_block_bytes = ranks == 4 ? 500 : std::size_t{32} << 20;
            std::mutex mutex;
            std::vector<std::string> messages;
            dist::run_in_process(ranks, [&](dist::Comm& comm) {
                try {
                    (void)read_text_points_distributed(comm, {path, InputRole::points}, {});
                } catch (const InputError& e) {
                    const std::lock_guard lock(mutex);
                    messages.emplace_back(e.what());
                }
            });
            ASSERT_EQ(messages.size(), static_cast<std::size_t>(ranks)) << "every rank fails";
            for (const auto& m : messages) EXPECT_EQ(m, serial_message) << ranks << " ranks";
        }
    }
    distributed_block_bytes = std::size_t{32} << 20;
}

}  // namespace
}  // namespace dtm::io
