// SPDX-License-Identifier: MIT
// dtm with LAS and sniffed inputs: `--classes` and `--thin` reach the LAS reader and `dtm info`
// accounts for every record; `dtm tin` triangulates a LAS; LAZ, a Compass plot and a ZIP are input
// errors (exit 2) naming what the file is; a `.dat` point list is read as text.
#include <gtest/gtest.h>

#include <string>

#include "support/las_fixture.hpp"
#include "support/test_support.hpp"

namespace {

using dtm::test::run_dtm;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

dtm::test::LasSpec ground_and_water() {
    dtm::test::LasSpec spec;
    spec.minor = 4;
    spec.format = 6;
    spec.epsg = 32633;
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 10; ++j) {
            spec.records.push_back({i * 100, j * 100, 1000 + i * 10 + j, j < 5 ? 2U : 9U, false});
            spec.records.push_back({i * 100 + 30, j * 100 + 30, 5000, 5U, false});  // vegetation
        }
    }
    return spec;
}

TEST(CliInputs, InfoAccountsForEveryLasRecord) {
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "cloud.las", dtm::test::las_bytes(ground_and_water()));
    const auto r = run_dtm(
        {"info", (dir / "cloud.las").string(), "--classes", "2,9", "--thin", "2", "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "\"format\": \"LAS 1.4 point format 6\"")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"crs\": \"EPSG:32633\"")) << r.out;
    EXPECT_TRUE(contains(r.out, "\"points\": 25,")) << r.out;
    EXPECT_TRUE(contains(r.out,
                         "\"point_records\": {\"read\": 200, \"withheld\": 0, "
                         "\"filtered_by_class\": 100, \"thinned\": 75, \"kept\": 25}"))
        << r.out;
    const auto table = run_dtm({"info", (dir / "cloud.las").string(), "--classes", "2"});
    ASSERT_EQ(table.exit_code, 0) << table.err;
    EXPECT_TRUE(contains(table.out,
                         "point records      200 read, 0 withheld, 150 filtered by "
                         "class, 0 thinned, 50 kept"))
        << table.out;
    const auto bad = run_dtm({"info", (dir / "cloud.las").string(), "--classes", "2,300"});
    EXPECT_EQ(bad.exit_code, 2) << bad.err;
}

TEST(CliInputs, TinOfALasGroundClass) {
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "cloud.las", dtm::test::las_bytes(ground_and_water()));
    const auto r = run_dtm({"tin", (dir / "cloud.las").string(), "--classes", "2", "-o",
                            (dir / "tin.ply").string(), "--stats"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "\"vertices\": 50")) << r.out;
}

TEST(CliInputs, LookalikesAreInputErrorsNamingWhatTheyAre) {
    const dtm::test::ScratchDir dir;
    auto laz = ground_and_water();
    laz.compressed = true;
    dtm::test::write_file(dir / "cloud.las", dtm::test::las_bytes(laz));
    dtm::test::write_file(dir / "cave.plt",
                          "Z\t-129.30\t107.53\t-54.29\t20.23\t-20.48\t13.36\n"
                          "SSECRET CAVE\n"
                          "NSECRET\tD 7 10 1981\tCSECRET CAVE\n"
                          "M\t0.00\t0.00\t0.00\tSA1\tP\t0.00\t0.00\t0.00\t0.00\tI\t0.00\n"
                          "D\t-6.20\t-4.42\t-0.60\tSA2\tP\t0.00\t0.00\t0.00\t0.00\tI\t7.6\n");
    dtm::test::write_file(dir / "points.csv", std::string("PK\x03\x04\x14\0\0\0", 8));
    struct Case {
        const char* file;
        const char* says;
    };
    for (const Case c : {Case{"cloud.las", "LAZ"}, Case{"cave.plt", "Compass cave survey"},
                         Case{"points.csv", "ZIP archive"}}) {
        const auto r = run_dtm({"info", (dir / c.file).string()});
        EXPECT_EQ(r.exit_code, 2) << c.file << ": " << r.out << r.err;
        EXPECT_TRUE(contains(r.err, c.file)) << r.err;
        EXPECT_TRUE(contains(r.err, c.says)) << r.err;
    }
}

TEST(CliInputs, ADatPointListIsReadAsText) {
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "survey.dat",
                          "1 100.0 200.0 10.5\n2 110.0 200.0 11.0\n"
                          "3 100.0 210.0 12.5\n4 110.0 210.0 10.0\n");
    const auto r = run_dtm({"info", (dir / "survey.dat").string(), "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "\"points\": 4,")) << r.out;
}

}  // namespace
