// SPDX-License-Identifier: MIT
// LAS reader: every version 1.2-1.4 and point format 0-10 with scale and offset, legacy and 1.4
// counts, the CRS from the WKT VLR, the WKT EVLR and the GeoTIFF keys, withheld records, the
// class filter and thinning with every record accounted for, LAZ refused with the reason, errors
// naming the file and byte; and an independent struct reader (tests/support/las_oracle.py) giving
// the same points.
#include "dtm/io/formats/las.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/inputs.hpp"
#include "support/las_fixture.hpp"
#include "support/test_support.hpp"

namespace {

namespace io = dtm::io;
namespace test = dtm::test;
using test::LasRecord;
using test::LasSpec;

std::vector<LasRecord> three_records() {
    return {{100, 200, 3000, 2, false}, {-150, 250, 3100, 9, false}, {120, -230, 2900, 1, false}};
}

io::ReadResult read(const std::filesystem::path& path, const io::ReadOptions& options = {}) {
    return io::read_las({path, io::InputRole::points}, options);
}

std::string error_of(const std::filesystem::path& path, const io::ReadOptions& options = {}) {
    try {
        (void)read(path, options);
    } catch (const dtm::InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(Las, EveryVersionAndPointFormatGivesScaledAndOffsetPoints) {
    const test::ScratchDir dir;
    for (unsigned minor = 2; minor <= 4; ++minor) {
        for (unsigned format = 0; format <= (minor == 4 ? 10U : 5U); ++format) {
            LasSpec spec;
            spec.minor = minor;
            spec.format = format;
            spec.extra_bytes = format % 3;  // records longer than the standard fields
            spec.offset[0] = -750000.0;
            spec.offset[1] = -1050000.0;
            spec.offset[2] = 200.0;
            spec.legacy_count = format % 2 == 0;  // 1.4: the 64-bit count alone is enough
            spec.records = three_records();
            const auto path =
                dir / ("v" + std::to_string(minor) + "f" + std::to_string(format) + ".las");
            test::write_file(path, test::las_bytes(spec));
            EXPECT_EQ(io::find_reader(path).name, "las");
            const io::ReadResult r = read(path);
            const std::string name = path.filename().string();
            ASSERT_EQ(r.terrain.points.size(), 3U) << name;
            EXPECT_EQ(r.terrain.points[1].x, -150 * 0.01 + -750000.0) << name;
            EXPECT_EQ(r.terrain.points[1].y, 250 * 0.01 + -1050000.0) << name;
            EXPECT_EQ(r.terrain.points[1].z, 3100 * 0.001 + 200.0) << name;
            EXPECT_EQ(r.summary.format,
                      "LAS 1." + std::to_string(minor) + " point format " + std::to_string(format));
            ASSERT_TRUE(r.summary.cloud.has_value());
            EXPECT_EQ(r.summary.cloud->records, 3U);
            EXPECT_TRUE(r.crs_wkt.empty());
        }
    }
}

TEST(Las, CrsComesFromTheWktRecordTheWktEvlrOrTheGeoTiffKeys) {
    const test::ScratchDir dir;
    LasSpec spec;
    spec.records = three_records();
    spec.wkt = io::crs_to_wkt("EPSG:5514");
    test::write_file(dir / "wkt.las", test::las_bytes(spec));
    EXPECT_EQ(io::crs_label(read(dir / "wkt.las").crs_wkt), "EPSG:5514");

    spec.minor = 4;
    spec.format = 6;
    spec.wkt_as_evlr = true;
    test::write_file(dir / "evlr.las", test::las_bytes(spec));
    EXPECT_EQ(io::crs_label(read(dir / "evlr.las").crs_wkt), "EPSG:5514");

    LasSpec keys;
    keys.records = three_records();
    keys.epsg = 32633;
    test::write_file(dir / "keys.las", test::las_bytes(keys));
    EXPECT_EQ(io::crs_label(read(dir / "keys.las").crs_wkt), "EPSG:32633");

    keys.epsg = 32767;  // user-defined: no EPSG code, said so
    test::write_file(dir / "user.las", test::las_bytes(keys));
    const io::ReadResult user = read(dir / "user.las");
    EXPECT_TRUE(user.crs_wkt.empty());
    ASSERT_EQ(user.summary.warnings.size(), 1U);
    EXPECT_NE(user.summary.warnings[0].find("user-defined"), std::string::npos);
}

TEST(Las, ClassFilterWithheldAndThinningAccountForEveryRecord) {
    const test::ScratchDir dir;
    for (const unsigned format : {1U, 7U}) {
        LasSpec spec;
        spec.minor = 4;
        spec.format = format;
        spec.scale[0] = spec.scale[1] = spec.scale[2] = 0.01;
        // Cells of 1 m: (0,0) holds three ground points, the lowest (z 4) second; (1,0) one
        // water point; (0,0) also a withheld point and a class-1 point lower than all.
        spec.records = {{10, 10, 500, 2, false}, {50, 60, 400, 2, false}, {150, 20, 100, 9, false},
                        {90, 90, 450, 2, false}, {20, 20, 100, 2, true},  {30, 30, 50, 1, false},
                        {60, 10, 400, 2, false}};
        const auto path = dir / ("c" + std::to_string(format) + ".las");
        test::write_file(path, test::las_bytes(spec));

        const io::ReadResult all = read(path);
        EXPECT_EQ(all.terrain.points.size(), 6U);
        EXPECT_EQ(all.summary.cloud->withheld, 1U);

        io::ReadOptions options;
        options.classes = {2, 9};
        const io::ReadResult filtered = read(path, options);
        EXPECT_EQ(filtered.terrain.points.size(), 5U);
        EXPECT_EQ(filtered.summary.cloud->class_filtered, 1U);
        EXPECT_EQ(filtered.summary.cloud->thinned, 0U);

        options.thin = 1.0;
        const io::ReadResult thin = read(path, options);
        const io::PointCloudCounts& c = *thin.summary.cloud;
        ASSERT_EQ(thin.terrain.points.size(), 2U);
        EXPECT_EQ(c.records, 7U);
        EXPECT_EQ(c.withheld, 1U);
        EXPECT_EQ(c.class_filtered, 1U);
        EXPECT_EQ(c.thinned, 3U);
        EXPECT_EQ(c.records,
                  c.withheld + c.class_filtered + c.thinned + thin.terrain.points.size());
        // Cell (0,0) keeps its lowest point, the first of the two at z 4, in its first place.
        EXPECT_EQ(thin.terrain.points[0].x, 50 * 0.01);
        EXPECT_EQ(thin.terrain.points[0].y, 60 * 0.01);
        EXPECT_EQ(thin.terrain.points[0].z, 400 * 0.01);
        EXPECT_EQ(thin.terrain.points[1].x, 150 * 0.01);
    }
}

TEST(Las, BadOptionsAreOptionErrors) {
    const test::ScratchDir dir;
    LasSpec spec;
    spec.records = three_records();
    test::write_file(dir / "a.las", test::las_bytes(spec));
    io::ReadOptions options;
    options.thin = -1;
    EXPECT_THROW((void)read(dir / "a.las", options), dtm::OptionError);
    options.thin = 0;
    options.classes = {256};
    EXPECT_THROW((void)read(dir / "a.las", options), dtm::OptionError);
}

TEST(Las, LazIsRefusedWithTheReasonAndHowToDecompress) {
    const test::ScratchDir dir;
    LasSpec spec;
    spec.records = three_records();
    spec.compressed = true;
    test::write_file(dir / "packed.las", test::las_bytes(spec));
    for (const char* name : {"packed.las"}) {
        const std::string what = error_of(dir / name);
        EXPECT_NE(what.find("packed.las"), std::string::npos) << what;
        EXPECT_NE(what.find("LAZ"), std::string::npos) << what;
        EXPECT_NE(what.find("Debian"), std::string::npos) << what;
        EXPECT_NE(what.find("laszip -i"), std::string::npos) << what;
        EXPECT_NE(what.find("pdal translate"), std::string::npos) << what;
    }
    spec.compressed = false;
    test::write_file(dir / "named.laz", test::las_bytes(spec));
    EXPECT_EQ(io::find_reader(dir / "named.laz").name, "las");
    EXPECT_NE(error_of(dir / "named.laz").find("LAZ"), std::string::npos);
}

TEST(Las, ErrorsNameTheFileAndTheByteOffset) {
    const test::ScratchDir dir;
    LasSpec spec;
    spec.records = three_records();
    const std::string good = test::las_bytes(spec);
    test::write_file(dir / "cut.las", good.substr(0, good.size() - 5));
    std::string what = error_of(dir / "cut.las");
    EXPECT_NE(what.find("cut.las"), std::string::npos) << what;
    EXPECT_NE(what.find("LAS byte 227"), std::string::npos) << what;
    EXPECT_NE(what.find("truncated"), std::string::npos) << what;

    test::write_file(dir / "short.las", good.substr(0, 100));
    what = error_of(dir / "short.las");
    EXPECT_NE(what.find("end of the file"), std::string::npos) << what;

    std::string bad = good;
    bad[105] = 10;  // record length below format 0's 20 bytes
    test::write_file(dir / "length.las", bad);
    EXPECT_NE(error_of(dir / "length.las").find("LAS byte 105"), std::string::npos);

    bad = good;
    bad[25] = 7;
    test::write_file(dir / "version.las", bad);
    EXPECT_NE(error_of(dir / "version.las").find("version 1.0 to 1.4, found 1.7"),
              std::string::npos);

    bad = good;
    bad[104] = 11;
    test::write_file(dir / "format.las", bad);
    EXPECT_NE(error_of(dir / "format.las").find("LAS byte 104"), std::string::npos);

    test::write_file(dir / "text.las", "x y z\n1 2 3\n");
    EXPECT_NE(error_of(dir / "text.las").find("LASF"), std::string::npos);
}

TEST(Las, AnIndependentStructReaderGivesTheSamePoints) {
    const test::ScratchDir dir;
    LasSpec spec;
    spec.minor = 3;
    spec.format = 3;
    spec.extra_bytes = 4;
    spec.scale[0] = spec.scale[1] = 0.001;
    spec.offset[0] = -520000.0;
    spec.offset[1] = -1164000.0;
    for (int i = 0; i < 200; ++i) {
        spec.records.push_back({i * 7919 % 100003 - 50000, i * 104729 % 100019 - 50000,
                                (i * 31) % 5000, static_cast<unsigned>(i % 5), i % 17 == 0});
    }
    const auto path = dir / "oracle.las";
    test::write_file(path, test::las_bytes(spec));
    const auto oracle =
        std::filesystem::path(DTM_TEST_DATA_DIR) / ".." / "support" / "las_oracle.py";
    const std::string command =
        "/usr/bin/python3 '" + oracle.string() + "' '" + path.string() + "'";
    std::string out;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[4096];
        std::size_t n = 0;
        while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
        ASSERT_EQ(::pclose(pipe), 0) << out;
    }
    std::istringstream lines(out);
    std::string version;
    unsigned format = 0;
    std::size_t count = 0;
    lines >> version >> format >> count;
    EXPECT_EQ(version, "1.3");
    EXPECT_EQ(format, 3U);
    ASSERT_EQ(count, 200U);
    io::ReadOptions options;
    options.classes = {0, 2, 4};
    const io::ReadResult r = read(path, options);
    std::size_t kept = 0;
    std::size_t withheld = 0;
    std::size_t filtered = 0;
    for (std::size_t i = 0; i < count; ++i) {
        std::string x, y, z;
        unsigned cls = 0;
        int held = 0;
        lines >> x >> y >> z >> cls >> held;
        if (held != 0) {
            ++withheld;
        } else if (cls % 2 != 0) {
            ++filtered;
        } else {
            ASSERT_LT(kept, r.terrain.points.size());
            EXPECT_EQ(r.terrain.points[kept].x, std::stod(x)) << i;
            EXPECT_EQ(r.terrain.points[kept].y, std::stod(y)) << i;
            EXPECT_EQ(r.terrain.points[kept].z, std::stod(z)) << i;
            ++kept;
        }
    }
    EXPECT_EQ(r.terrain.points.size(), kept);
    EXPECT_EQ(r.summary.cloud->withheld, withheld);
    EXPECT_EQ(r.summary.cloud->class_filtered, filtered);
}

TEST(Las, LoadInputsKeepsTheCountsAndTheCrs) {
    const test::ScratchDir dir;
    LasSpec spec;
    spec.records = three_records();
    spec.epsg = 5514;
    test::write_file(dir / "a.las", test::las_bytes(spec));
    io::LoadOptions options;
    options.files.push_back({dir / "a.las", io::InputRole::points});
    options.read.classes = {2};
    const io::LoadedInputs loaded = io::load_inputs(options);
    ASSERT_EQ(loaded.summaries.size(), 1U);
    EXPECT_EQ(loaded.summaries[0].points, 1U);
    EXPECT_EQ(loaded.summaries[0].crs, "EPSG:5514");
    EXPECT_EQ(loaded.summaries[0].cloud->class_filtered, 2U);
    EXPECT_THROW((void)io::read_las({dir / "a.las", io::InputRole::breaklines}, {}),
                 dtm::InputError);
}

}  // namespace
