// SPDX-License-Identifier: MIT
// Content sniffing in the reader table: unknown extensions go to the reader their content
// suggests, content that contradicts the extension (or is no format dtm reads) is an InputError
// naming what it appears to be, and the real HP-GL plots and point text variants still go to
// their readers.
#include "dtm/io/sniff.hpp"

#include <gtest/gtest.h>

#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/io/reader.hpp"
#include "support/test_support.hpp"

namespace {

namespace io = dtm::io;
namespace test = dtm::test;
using Kind = io::ContentGuess::Kind;

std::string_view reader_of(std::string_view name, std::string_view bytes) {
    const std::filesystem::path path(name);
    std::string ext = path.extension().string();
    if (!ext.empty()) ext.erase(0, 1);
    return io::find_reader(io::FileHead{path, ext, bytes}).name;
}

std::string error_of(std::string_view name, std::string_view bytes) {
    try {
        (void)reader_of(name, bytes);
    } catch (const dtm::InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(Sniff, UnknownExtensionsGoToTheReaderOfTheirContent) {
    EXPECT_EQ(reader_of("survey.cin", "1 100.0 200.0 10.5\n2 110.0 200.0 11.0\n"), "csv");
    EXPECT_EQ(reader_of("survey.dat", "id;y;x;z\n1;745000.1;1045000.2;300.5\n"), "csv");
    EXPECT_EQ(reader_of("noext", "x,y,z\n1,2,3\n4,5,6\n"), "csv");
    EXPECT_EQ(reader_of("cloud.bin", "LASF\1\0"), "las");
    EXPECT_EQ(reader_of("tin.mesh", "ply\nformat ascii 1.0\n"), "ply");
    EXPECT_EQ(reader_of("plan.000", "IN;SP1;PU0,0;PD100,100;"), "hpgl");
    EXPECT_EQ(reader_of("surface.land", "<?xml version=\"1.0\"?>\n<LandXML version=\"1.2\">"),
              "landxml");
    EXPECT_EQ(reader_of("drawing.cad", "  0\nSECTION\n  2\nENTITIES\n"), "dxf");
    EXPECT_EQ(reader_of("dem.grd", "ncols 4\nnrows 3\nxllcorner 0\n"), "ascii-grid");
}

TEST(Sniff, LookalikesAreInputErrorsNamingWhatTheyAppearToBe) {
    const std::string compass =
        "Z\t-129.30\t107.53\t-54.29\t20.23\t-20.48\t13.36\nSSECRET CAVE\n"
        "NSECRET\tD 7 10 1981\tCSECRET CAVE\n"
        "M\t0.00\t0.00\t0.00\tSA1\tP\t0.00\t0.00\t0.00\t0.00\tI\t0.00\n"
        "D\t-6.20\t-4.42\t-0.60\tSA2\tP\t0.00\t0.00\t0.00\t0.00\tI\t7.6\n";
    EXPECT_NE(error_of("cave.plt", compass).find("Compass cave survey"), std::string::npos);
    EXPECT_NE(error_of("cave.plt", compass).find("cave.plt"), std::string::npos);
    EXPECT_NE(error_of("points.csv", std::string("PK\3\4\x14\0", 6)).find("ZIP archive"),
              std::string::npos);
    EXPECT_NE(error_of("points.dat", "%PDF-1.7\n%\xE2\xE3").find("PDF document"),
              std::string::npos);
    EXPECT_NE(error_of("points.txt", std::string("\x1f\x8b\x08\0", 4)).find("gzip"),
              std::string::npos);
    EXPECT_NE(error_of("points.csv", "LASF\1\4").find("LAS point cloud"), std::string::npos);
    EXPECT_NE(error_of("blob.xyz", std::string("\x01\x02\0\x7f\x10\x11", 6)).find("binary data"),
              std::string::npos);
    EXPECT_NE(error_of("blob.bin", std::string("\x01\x02\0\x7f\x10\x11", 6)).find("binary data"),
              std::string::npos);
    EXPECT_NE(error_of("other.xml", "<?xml version=\"1.0\"?><svg/>").find("root element <svg>"),
              std::string::npos);
    EXPECT_NE(error_of("notes.foo", "just some words\nand more\n").find("content dtm recognises"),
              std::string::npos);
}

TEST(Sniff, ExtensionsStillDecideWhereContentAgrees) {
    EXPECT_EQ(reader_of("a.plt", "\x1b%-12345X@PJL ENTER LANGUAGE=HPGL2\nIN;"), "hpgl");
    EXPECT_EQ(reader_of("a.plt", std::string("\x1b"
                                             "E\0\0IN;",
                                             7)),
              "hpgl");  // binary PCL
    EXPECT_EQ(reader_of("a.csv", "x,y,z\n1,2,3\n"), "csv");
    EXPECT_EQ(reader_of("a.gpkg", "SQLite format 3"), "ogr");
    EXPECT_EQ(reader_of("a.tif", std::string("II*\0", 4)), "raster");
    EXPECT_EQ(reader_of("a.shp", std::string("\0\0\x27\x0a", 4)), "ogr");
    EXPECT_EQ(io::guess_content("").kind, Kind::unknown);
}

TEST(Sniff, AFileWithAnUnknownExtensionLoadsAsText) {
    const test::ScratchDir dir;
    test::write_file(dir / "survey.cin",
                     "1 100.0 200.0 10.5\n2 110.0 200.0 11.0\n"
                     "3 100.0 210.0 12.5\n");
    io::LoadOptions options;
    options.files.push_back({dir / "survey.cin", io::InputRole::points});
    EXPECT_EQ(io::load_inputs(options).terrain.points.size(), 3U);
}

TEST(Sniff, RealPlotsAndTextVariantsKeepTheirReaders) {
    if (!test::shared_data_available("hpgl-hp2xx")) GTEST_SKIP();
    std::size_t files = 0;
    for (const char* folder : {"hpgl-hp2xx", "hpgl-autocad-hpgl2", "hpgl-instrument-plots",
                               "points-pdal-text-variants"}) {
        for (const auto& entry :
             std::filesystem::directory_iterator(test::shared_data_path(folder))) {
            const auto name = entry.path().filename().string();
            if (name == "SOURCE.txt" || name == "readme" || !entry.is_regular_file()) continue;
            const std::string_view expected =
                std::string_view(folder).starts_with("hpgl") ? "hpgl" : "csv";
            try {
                const std::string_view got = io::find_reader(entry.path()).name;
                if (got != "csv-wkt") {
                    EXPECT_EQ(got, expected) << entry.path();
                }
            } catch (const dtm::InputError& e) {
                ADD_FAILURE() << e.what();
            }
            ++files;
        }
    }
    EXPECT_GT(files, 20U);
}

}  // namespace
