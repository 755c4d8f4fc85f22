// SPDX-License-Identifier: MIT
// `dtm info` on a shapefile whose .prj is ESRI WKT (issue 17.6): the CRS is identified as its EPSG
// code and the report says so; a .prj no EPSG entry matches is kept, and the report says that.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

const char* const krovak_prj =
    "PROJCS[\"S_JTSK_Krovak_East_North\",GEOGCS[\"GCS_S_JTSK\",DATUM[\"D_S_JTSK\",SPHEROID["
    "\"Bessel_1841\",6377397.155,299.1528128]],PRIMEM[\"Greenwich\",0.0],UNIT[\"Degree\","
    "0.0174532925199433]],PROJECTION[\"Krovak\"],PARAMETER[\"False_Easting\",0.0],PARAMETER["
    "\"False_Northing\",0.0],PARAMETER[\"Pseudo_Standard_Parallel_1\",78.5],PARAMETER["
    "\"Scale_Factor\",0.9999],PARAMETER[\"Azimuth\",30.28813975277778],PARAMETER["
    "\"Longitude_Of_Center\",24.83333333333333],PARAMETER[\"Latitude_Of_Center\",49.5],"
    "PARAMETER[\"X_Scale\",-1.0],PARAMETER[\"Y_Scale\",1.0],PARAMETER[\"XY_Plane_Rotation\",90.0],"
    "UNIT[\"Meter\",1.0]]";

/// The sample's boundary shapefile with @p prj as its .prj, in @p dir.
fs::path shapefile_with_prj(const dtm::test::ScratchDir& dir, const std::string& prj) {
    const fs::path sample = fs::path(DTM_TEST_DATA_DIR) / ".." / ".." / "samples" / "sjtsk";
    for (const char* ext : {".shp", ".shx", ".dbf"}) {
        fs::copy_file(sample / ("boundary" + std::string(ext)), dir / ("b" + std::string(ext)));
    }
    dtm::test::write_file(dir / "b.prj", prj);
    return dir / "b.shp";
}

TEST(InfoCrs, EsriKrovakPrjIsReportedAsEpsg5514AndHow) {
    const dtm::test::ScratchDir dir;
    const fs::path shp = shapefile_with_prj(dir, krovak_prj);
    const dtm::test::RunResult r = dtm::test::run_dtm({"info", shp.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("crs                EPSG:5514"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("EPSG:5514 identified from ESRI WKT \"S_JTSK_Krovak_East_North\""),
              std::string::npos)
        << r.out;
    const dtm::test::RunResult j = dtm::test::run_dtm({"info", shp.string(), "--json"});
    EXPECT_NE(j.out.find("\"crs_note\""), std::string::npos) << j.out;
}

TEST(InfoCrs, AnUnmatchedPrjIsKeptAndSaidSo) {
    std::string feet = krovak_prj;
    feet.replace(feet.find("UNIT[\"Meter\",1.0]"), std::string("UNIT[\"Meter\",1.0]").size(),
                 "UNIT[\"Foot_US\",0.3048006096012192]");
    const dtm::test::ScratchDir dir;
    const dtm::test::RunResult r =
        dtm::test::run_dtm({"info", shapefile_with_prj(dir, feet).string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("kept as it is: no certain EPSG match"), std::string::npos) << r.out;
}

}  // namespace
