// SPDX-License-Identifier: MIT
// Golden digests of the sample TINs: each sample is triangulated with 1, 4 and 64 tiles, its
// PLY bytes (the lossless TIN: every coordinate, triangle, constrained edge and the CRS) are
// hashed, and the digest must be the same for every tile count and equal to the one committed in
// tests/golden/expected/sample_tins.txt. A change of the triangulation that changes any byte of
// a sample TIN fails here; when the change is intended, DTM_UPDATE_GOLDEN=1 rewrites the file.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "dtm/algo/triangulate.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/products/surface.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;

namespace {

fs::path samples() { return fs::path(DTM_SOURCE_DIR) / "samples"; }
fs::path expected_file() {
    return fs::path(DTM_SOURCE_DIR) / "tests/golden/expected/sample_tins.txt";
}

/// The inputs of the README's runs of each sample.
std::map<std::string, dtm::io::LoadOptions> sample_inputs() {
    using dtm::io::InputRole;
    std::map<std::string, dtm::io::LoadOptions> all;
    const fs::path s = samples() / "sjtsk";
    dtm::io::LoadOptions csv;
    csv.files = {{s / "points.csv", InputRole::points},
                 {s / "breaklines.shp", InputRole::breaklines},
                 {s / "boundary.shp", InputRole::boundary},
                 {s / "building.shp", InputRole::holes}};
    csv.crs.default_crs = "EPSG:5514";
    csv.read.skip_bad_lines = true;
    all["sjtsk_csv"] = csv;
    dtm::io::LoadOptions hpgl;
    hpgl.files = {{s / "plan_500.hpgl", InputRole::points}};
    hpgl.crs.default_crs = "EPSG:5514";
    hpgl.read.hpgl.scale = 500;
    hpgl.read.hpgl.origin_e = -750310;
    hpgl.read.hpgl.origin_n = -1050210;
    hpgl.read.hpgl.pens = {{1, dtm::io::PenRole::points},
                           {2, dtm::io::PenRole::breakline},
                           {3, dtm::io::PenRole::boundary},
                           {4, dtm::io::PenRole::hole}};
    all["sjtsk_hpgl"] = hpgl;
    dtm::io::LoadOptions quick;
    quick.files = {{samples() / "quick" / "points.xyz", InputRole::points},
                   {samples() / "quick" / "breaklines.csv", InputRole::breaklines}};
    all["quick"] = quick;
    return all;
}

/// FNV-1a, 64 bits, of a file's bytes, as 16 hex digits.
std::string digest(const fs::path& file) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : dtm::test::read_file(file)) {
        h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

std::map<std::string, std::string> read_expected() {
    std::map<std::string, std::string> expected;
    std::istringstream lines(dtm::test::read_file(expected_file()));
    std::string name, value;
    while (lines >> name >> value) expected[name] = value;
    return expected;
}

bool update_goldens() {
    return std::getenv("DTM_UPDATE_GOLDEN") != nullptr ||
           std::getenv("DTM_UPDATE_GOLDENS") != nullptr;
}

TEST(SampleTins, DigestsAreTheSameForEveryTileCountAndMatchTheCommittedOnes) {
    const dtm::test::ScratchDir dir;
    const std::map<std::string, std::string> expected = read_expected();
    std::map<std::string, std::string> found;
    for (const auto& [name, options] : sample_inputs()) {
        for (const std::size_t tiles : {1, 4, 64}) {
            dtm::io::LoadedInputs loaded = dtm::io::load_inputs(options);
            dtm::TriangulateOptions triangulation;
            triangulation.tiles = tiles;
            const dtm::products::Surface surface = dtm::products::surface(loaded, triangulation);
            const fs::path ply = dir / (name + "-" + std::to_string(tiles) + ".ply");
            dtm::io::write_tin_ply(surface.result.tin, ply,
                                   {.crs_wkt = loaded.crs_wkt, .ascii = false});
            const std::string d = digest(ply);
            if (tiles == 1) {
                found[name] = d;
            } else {
                EXPECT_EQ(d, found[name]) << name << " with " << tiles << " tiles";
            }
        }
        if (!update_goldens()) {
            const auto it = expected.find(name);
            ASSERT_NE(it, expected.end()) << name << " has no digest in " << expected_file();
            EXPECT_EQ(found[name], it->second)
                << name
                << ": the TIN changed (DTM_UPDATE_GOLDEN=1 rewrites the digests if intended)";
        }
    }
    if (update_goldens()) {
        std::string text;
        for (const auto& [name, d] : found) text += name + " " + d + "\n";
        dtm::test::write_file(expected_file(), text);
    }
}

}  // namespace
