// SPDX-License-Identifier: MIT
// io::identify_crs on ESRI .prj texts written here from ESRI's definitions (ArcGIS's names, D_
// datums, no AUTHORITY or ESRI's own), and on the real S-JTSK .prj files of ../shared/data.
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "dtm/io/formats/crs.hpp"
#include "support/test_support.hpp"

namespace {

/// ESRI's Krovak East-North (wkid 102067 / 5514) with the given name, unit and authority.
std::string krovak(const std::string& name,
                   const std::string& unit = "UNIT[\"Meter\",1.0]",
                   const std::string& tail = "") {
    return "PROJCS[\"" + name +
           "\",GEOGCS[\"GCS_S_JTSK\",DATUM[\"D_S_JTSK\",SPHEROID[\"Bessel_1841\",6377397.155,"
           "299.1528128]],PRIMEM[\"Greenwich\",0.0],UNIT[\"Degree\",0.0174532925199433]],"
           "PROJECTION[\"Krovak\"],PARAMETER[\"False_Easting\",0.0],PARAMETER[\"False_Northing\","
           "0.0],PARAMETER[\"Pseudo_Standard_Parallel_1\",78.5],PARAMETER[\"Scale_Factor\",0.9999],"
           "PARAMETER[\"Azimuth\",30.28813975277778],PARAMETER[\"Longitude_Of_Center\","
           "24.83333333333333],PARAMETER[\"Latitude_Of_Center\",49.5],PARAMETER[\"X_Scale\",-1.0],"
           "PARAMETER[\"Y_Scale\",1.0],PARAMETER[\"XY_Plane_Rotation\",90.0]," +
           unit + tail + "]";
}

std::string number(double v) {
    std::ostringstream out;
    out.precision(17);
    out << v;
    return out.str();
}

/// An ESRI transverse Mercator on @p gcs.
std::string esri_tm(const std::string& name,
                    const std::string& gcs,
                    double false_easting,
                    double false_northing,
                    double central_meridian,
                    double scale,
                    double latitude_of_origin = 0.0) {
    return "PROJCS[\"" + name + "\"," + gcs +
           ",PROJECTION[\"Transverse_Mercator\"],PARAMETER[\"False_Easting\"," +
           number(false_easting) + "],PARAMETER[\"False_Northing\"," + number(false_northing) +
           "],PARAMETER[\"Central_Meridian\"," + number(central_meridian) +
           "],PARAMETER[\"Scale_Factor\"," + number(scale) + "],PARAMETER[\"Latitude_Of_Origin\"," +
           number(latitude_of_origin) + "],UNIT[\"Meter\",1.0]]";
}

const std::string gcs_wgs84 =
    "GEOGCS[\"GCS_WGS_1984\",DATUM[\"D_WGS_1984\",SPHEROID[\"WGS_1984\",6378137.0,"
    "298.257223563]],PRIMEM[\"Greenwich\",0.0],UNIT[\"Degree\",0.0174532925199433]]";
const std::string gcs_etrs89 =
    "GEOGCS[\"GCS_ETRS_1989\",DATUM[\"D_ETRS_1989\",SPHEROID[\"GRS_1980\",6378137.0,"
    "298.257222101]],PRIMEM[\"Greenwich\",0.0],UNIT[\"Degree\",0.0174532925199433]]";

std::string code_of(const std::string& wkt) {
    OGRSpatialReference srs;
    srs.SetFromUserInput(wkt.c_str());
    const char* name = srs.GetAuthorityName(nullptr);
    const char* code = srs.GetAuthorityCode(nullptr);
    return name != nullptr && code != nullptr ? std::string(name) + ":" + code : "";
}

void expect_identified(const std::string& prj, const std::string& epsg) {
    const dtm::io::CrsIdentity id = dtm::io::identify_crs(prj);
    EXPECT_EQ(code_of(id.wkt), epsg) << prj;
    EXPECT_TRUE(id.note.starts_with(epsg + " identified from ESRI WKT")) << id.note;
    EXPECT_NE(id.note.find("confidence"), std::string::npos) << id.note;
    EXPECT_EQ(dtm::io::crs_label(id.wkt), epsg);
}

TEST(IdentifyCrs, SjtskKrovakEastNorthUnderEsriNamesIsEpsg5514) {
    expect_identified(krovak("S_JTSK_Krovak_East_North"), "EPSG:5514");
    expect_identified(krovak("S-JTSK_Krovak_East_North"), "EPSG:5514");
    expect_identified(
        krovak("S-JTSK_Krovak_East_North", "UNIT[\"Meter\",1.0]", ",AUTHORITY[\"ESRI\",102067]"),
        "EPSG:5514");
    const dtm::io::CrsIdentity id = dtm::io::identify_crs(krovak("S_JTSK_Krovak_East_North"));
    EXPECT_NE(id.note.find("\"S_JTSK_Krovak_East_North\""), std::string::npos) << id.note;
}

TEST(IdentifyCrs, OtherCommonEsriNamesGetTheirEpsgCodes) {
    expect_identified(esri_tm("ETRS_1989_UTM_Zone_33N", gcs_etrs89, 500000, 0, 15, 0.9996),
                      "EPSG:25833");
    expect_identified(esri_tm("WGS_1984_UTM_Zone_34N", gcs_wgs84, 500000, 0, 21, 0.9996),
                      "EPSG:32634");
    // EPSG renamed the datum of CS92 (ETRF2000-PL): found by its parameters.
    expect_identified(esri_tm("ETRS_1989_Poland_CS92", gcs_etrs89, 500000, -5300000, 19, 0.9993),
                      "EPSG:2180");
    expect_identified(
        esri_tm("British_National_Grid",
                "GEOGCS[\"GCS_OSGB_1936\",DATUM[\"D_OSGB_1936\",SPHEROID[\"Airy_1830\","
                "6377563.396,299.3249646]],PRIMEM[\"Greenwich\",0.0],UNIT[\"Degree\","
                "0.0174532925199433]]",
                400000, -100000, -2, 0.9996012717, 49),
        "EPSG:27700");
    expect_identified(gcs_wgs84, "EPSG:4326");
    expect_identified(
        "PROJCS[\"WGS_1984_Web_Mercator_Auxiliary_Sphere\"," + gcs_wgs84 +
            ",PROJECTION[\"Mercator_Auxiliary_Sphere\"],PARAMETER[\"False_Easting\",0.0],"
            "PARAMETER[\"False_Northing\",0.0],PARAMETER[\"Central_Meridian\",0.0],"
            "PARAMETER[\"Standard_Parallel_1\",0.0],PARAMETER[\"Auxiliary_Sphere_Type\",0.0],"
            "UNIT[\"Meter\",1.0]]",
        "EPSG:3857");
}

TEST(IdentifyCrs, UncertainMatchesKeepTheOriginal) {
    // A local grid and Krovak in US feet: no EPSG entry is the same CRS.
    for (const std::string& prj :
         {esri_tm("My_Local_Grid", gcs_wgs84, 12345, 0, 14.321, 1.0),
          krovak("S-JTSK_Krovak_East_North", "UNIT[\"Foot_US\",0.3048006096012192]")}) {
        const dtm::io::CrsIdentity id = dtm::io::identify_crs(prj);
        EXPECT_EQ(code_of(id.wkt), "") << prj;
        EXPECT_NE(id.note.find("kept as it is: no certain EPSG match"), std::string::npos)
            << id.note;
        OGRSpatialReference kept, original;
        kept.SetFromUserInput(id.wkt.c_str());
        original.SetFromUserInput(prj.c_str());
        EXPECT_TRUE(kept.IsSame(&original)) << id.wkt;
    }
}

TEST(IdentifyCrs, AnEpsgCodeInTheDefinitionIsKeptWithoutANote) {
    const dtm::io::CrsIdentity id = dtm::io::identify_crs(dtm::io::crs_to_wkt("EPSG:5514"));
    EXPECT_EQ(code_of(id.wkt), "EPSG:5514");
    EXPECT_EQ(id.note, "");
}

TEST(IdentifyCrs, RealSjtskPrjFilesOfSharedData) {
    const char* folder = "points-cz-sjtsk-jvf-dtm/derived";
    if (!dtm::test::shared_data_available(folder)) GTEST_SKIP() << "no ../shared/data/" << folder;
    int seen = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(dtm::test::shared_data_path(folder))) {
        if (entry.path().extension() != ".prj") continue;
        expect_identified(dtm::test::read_file(entry.path()), "EPSG:5514");
        ++seen;
    }
    EXPECT_GT(seen, 0);
}

}  // namespace
