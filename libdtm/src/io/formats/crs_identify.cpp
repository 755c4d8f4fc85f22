// SPDX-License-Identifier: MIT
// Identification of CRSs that come without an EPSG code, above all ESRI .prj files (ArcGIS writes
// PROJCS["S-JTSK_Krovak_East_North", ... DATUM["D_S_JTSK" ...] with no AUTHORITY, or with
// AUTHORITY["ESRI",102067]). GDAL/PROJ's FindMatches (proj_identify) scores every database entry
// against the definition: 100 % equivalent with the same name, 90 % equivalent with an alias or
// another name, 70 % equivalent ignoring the datum name, below that different. The rule:
//   1. an EPSG code in the definition is kept;
//   2. else the best EPSG match is taken when it is unique and scores >= 90 %;
//   3. else the EPSG match whose PROJ string equals the definition's (same projection, ellipsoid,
//      parameters and units; only names differ, a null shift to WGS 84 ignored), when exactly
//      one does;
//   4. else the definition is kept as it is (outputs carry it unchanged), and the note says so.
#include <ogr_spatialref.h>

#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"

namespace dtm::io {
namespace {

struct Match {
    std::string code;
    int confidence = 0;
    OGRSpatialReference srs;
};

std::string proj_string(const OGRSpatialReference& srs) {
    char* text = nullptr;
    std::string out;
    if (srs.exportToProj4(&text) == OGRERR_NONE && text != nullptr) out = text;
    CPLFree(text);
    // EPSG's ETRS89 realisations export a null shift to WGS 84; the ESRI texts have none.
    for (const char* null_shift : {" +towgs84=0,0,0,0,0,0,0", " +towgs84=0,0,0"}) {
        const std::size_t at = out.find(null_shift);
        if (at != std::string::npos) out.erase(at, std::string(null_shift).size());
    }
    return out;
}

/// The EPSG entries FindMatches proposes for @p srs, best first.
std::vector<Match> epsg_matches(const OGRSpatialReference& srs) {
    int count = 0;
    int* confidence = nullptr;
    OGRSpatialReferenceH* found = srs.FindMatches(nullptr, &count, &confidence);
    std::vector<Match> out;
    for (int i = 0; i < count; ++i) {
        const OGRSpatialReference* m = OGRSpatialReference::FromHandle(found[i]);
        const char* name = m->GetAuthorityName(nullptr);
        const char* code = m->GetAuthorityCode(nullptr);
        if (name == nullptr || code == nullptr || std::string(name) != "EPSG") continue;
        out.push_back({std::string("EPSG:") + code, confidence[i], *m});
    }
    OSRFreeSRSArray(found);
    CPLFree(confidence);
    return out;
}

/// The definition without a non-EPSG authority (ESRI:102067 matches only itself otherwise).
OGRSpatialReference without_authority(const OGRSpatialReference& srs) {
    char* text = nullptr;
    const char* const options[] = {"FORMAT=WKT1_ESRI", nullptr};
    OGRSpatialReference bare;
    bare.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (srs.exportToWkt(&text, options) != OGRERR_NONE || text == nullptr ||
        bare.SetFromUserInput(text) != OGRERR_NONE) {
        bare = srs;
    }
    CPLFree(text);
    return bare;
}

std::string describe(const std::string& definition, const OGRSpatialReference& srs) {
    const bool esri = definition.find("DATUM[\"D_") != std::string::npos ||
                      definition.find("AUTHORITY[\"ESRI\"") != std::string::npos;
    const char* name = srs.GetName();
    return std::string(esri ? "ESRI WKT" : "WKT") + " \"" + (name != nullptr ? name : "") + "\"";
}

}  // namespace

CrsIdentity identify_crs(const std::string& definition) {
    if (definition.empty()) return {};
    OGRSpatialReference srs;
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (srs.SetFromUserInput(definition.c_str()) != OGRERR_NONE) {
        throw InputError("expected a coordinate reference system GDAL/PROJ knows, found '" +
                         definition.substr(0, 80) + "'");
    }
    const char* authority = srs.GetAuthorityName(nullptr);
    if (authority != nullptr && std::string(authority) == "EPSG") return {srs_to_wkt(srs), {}};
    const std::string what = describe(definition, srs);
    const OGRSpatialReference bare = authority != nullptr ? without_authority(srs) : srs;
    const std::vector<Match> matches = epsg_matches(bare);
    const Match* chosen = nullptr;
    std::string how;
    if (!matches.empty() && matches[0].confidence >= crs_match_confidence &&
        (matches.size() == 1 || matches[1].confidence < matches[0].confidence)) {
        chosen = &matches[0];
        how = "GDAL match confidence " + std::to_string(chosen->confidence) + " %";
    } else {
        const std::string own = proj_string(bare);
        for (const Match& m : matches) {
            if (own.empty() || proj_string(m.srs) != own) continue;
            if (chosen != nullptr) {
                chosen = nullptr;  // two EPSG entries with these parameters: not certain
                break;
            }
            chosen = &m;
        }
        if (chosen != nullptr) {
            how = "GDAL match confidence " + std::to_string(chosen->confidence) +
                  " %, the same projection parameters";
        }
    }
    if (chosen == nullptr) {
        std::string best = matches.empty() ? std::string("no EPSG candidate")
                                           : "best " + matches[0].code + " at " +
                                                 std::to_string(matches[0].confidence) + " %";
        return {srs_to_wkt(srs), what + " kept as it is: no certain EPSG match (" + best + ")"};
    }
    OGRSpatialReference epsg = chosen->srs;
    epsg.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    return {srs_to_wkt(epsg), chosen->code + " identified from " + what + " (" + how + ")"};
}

}  // namespace dtm::io
