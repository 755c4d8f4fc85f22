// SPDX-License-Identifier: MIT
// A "nan" or "inf" coordinate (std::from_chars reads both) is an input error in the readers that
// parse numbers themselves, not a point that poisons the TIN.
#include <gtest/gtest.h>

#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/dxf.hpp"
#include "dtm/io/formats/jvf.hpp"
#include "dtm/io/formats/landxml.hpp"
#include "support/test_support.hpp"

namespace {

namespace io = dtm::io;
namespace test = dtm::test;

std::string error_of(io::ReadFn read, const std::filesystem::path& path) {
    try {
        (void)read({path, io::InputRole::points}, {}, {});
    } catch (const dtm::InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(NonFinite, CoordinatesAreInputErrors) {
    const test::ScratchDir dir;
    test::write_file(dir / "s.xml",
                     "<LandXML><Surfaces><Surface name=\"s\"><Definition surfType=\"TIN\"><Pnts>"
                     "<P id=\"1\">0 0 1</P><P id=\"2\">0 nan 1</P><P id=\"3\">1 1 1</P></Pnts>"
                     "<Faces><F>1 2 3</F></Faces></Definition></Surface></Surfaces></LandXML>");
    EXPECT_NE(error_of(&io::read_landxml, dir / "s.xml").find("finite number, found 'nan'"),
              std::string::npos);
    test::write_file(dir / "j.xml",
                     "<JVFDTM xmlns:gml=\"http://www.opengis.net/gml/3.2\"><Data><PodrobnyBodZPS>"
                     "<ZaznamObjektu><Point srsDimension=\"3\"><pos>-1 inf 3</pos></Point>"
                     "</ZaznamObjektu></PodrobnyBodZPS></Data></JVFDTM>");
    EXPECT_NE(error_of(&io::read_jvf, dir / "j.xml").find("finite coordinate, found 'inf'"),
              std::string::npos);
    test::write_file(dir / "f.dxf",
                     "0\nSECTION\n2\nENTITIES\n0\n3DFACE\n10\n0\n20\nnan\n30\n1\n0\nENDSEC\n");
    EXPECT_NE(error_of(&io::read_dxf, dir / "f.dxf").find("finite number for group code 20"),
              std::string::npos);
}

}  // namespace
